#!/usr/bin/env bash
# census-gpu-runs.sh IDVIEW OUT MODELS - the visibility census runs docs/census.md cites, each
# into OUT/NAME.json (the census's benchmark line, or with answers-* its summary line) and
# OUT/NAME.err, and a line per run in OUT/runs.txt (name, seconds, command). IDVIEW is the
# program or the bundle's `run` (shared/gpu/README.md); MODELS holds Motor-c.brep and the
# KiCad board's video.step (a model that is not there is said, and its runs left out).
#   scale-VxS     the default model, V views of SxS, timed (3 runs, the first warms up)
#   tech-NAME     162x1024 with each configuration
#   empty         162x1024 of a scene of a few quads: the cost of a view that draws nothing
#   answers-NAME  the census's answer (its summary line) for the model
# Then: scripts/census_table.py --write docs/census.md OUT's folder name.
set -uo pipefail
if [[ $# -ne 3 ]]; then
    sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit 2
fi
idview=$1 out=$2 models=$3
mkdir -p "$out"
failed=0

# run NAME FLAGS...: the census benchmark line of the last line of stdout into NAME.json.
run() {
    local name=$1 start=$SECONDS
    shift
    if "$idview" "$@" >"$out/$name.out" 2>"$out/$name.err"; then
        tail -n 1 "$out/$name.out" >"$out/$name.json"
    else
        echo "census-gpu-runs: $name failed: $(tail -n 1 "$out/$name.err")" >&2
        failed=1
    fi
    rm -f "$out/$name.out"
    echo "$name $((SECONDS - start)) idview $*" >>"$out/runs.txt"
}

for views in 42 162 642; do
    for size in 512 1024 2048; do
        run "scale-${views}x$size" --census "${views}x$size" --benchmark --copies 1
    done
done
for config in per-draw:push vertex-fs:mdi-baseinstance mesh-fs:mdi-baseinstance \
    visbuffer:mdi-baseinstance visbuffer-compute:mdi-baseinstance no-id:mdi-baseinstance; do
    run "tech-${config%%:*}" --census 162x1024 --benchmark --copies 1 --renderer "${config%%:*}" \
        --mode "${config##*:}"
done
run empty --census 162x1024 --benchmark --scene tiles
run answers-default --census 162x1024 --copies 1
for model in Motor-c.brep video.step; do
    if [[ -f $models/$model ]]; then
        run "answers-${model%%.*}" --census 162x1024 --model "$models/$model"
        run "time-${model%%.*}" --census 162x1024 --benchmark --copies 1 --model "$models/$model"
    else
        echo "census-gpu-runs: $models/$model is not there; its runs are left out" >&2
    fi
done
exit $failed
