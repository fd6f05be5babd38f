#!/usr/bin/env bash
# gpu-runs.sh [OPTIONS] IDVIEW OUT - makes the run folder that docs/benchmarks.md's tables
# need: every `idview --headless --benchmark` run the page cites, with exactly the flags it
# cites, each into OUT/NAME.json (its table on stdout in NAME.txt, its progress in NAME.log),
# and a line per run in OUT/runs.txt (name, seconds, command; runs-partN.txt with --part, so
# that the parts' files unpack side by side into one folder). IDVIEW is the program or the
# bundle's `run` (shared/gpu/README.md); Motor-c.brep is read from --models.
#
#   --part N        only the runs of part N (1 to 5; default: all), each part one command
#                   of the device, under 9 minutes (the estimates below)
#   --only A,B      only the runs named
#   --models DIR    where Motor-c.brep is (default: IDVIEW's folder/models)
#   --commit HASH   the build's commit, written into the runs file (bench_tables.py cites it)
#   --pack FILE     after each run, pack OUT into FILE (.tgz), so a command stopped by its
#                   time limit still returns every run it finished
#   --extra 'ARGS'  flags added to every command after its own (later flags win), e.g.
#                   '--size 64x48 --frames 1 --visible 0 --copies 1' for a dry run of the
#                   command lines on lavapipe
#   --list          print the commands and do nothing
# A run whose NAME.json is in OUT already is skipped, so a part can be taken up again; a run
# that fails is said, the others go on, and the script exits 1 at the end.
#
# On the device (one command a part; 30 minutes of device time a session, 10 per command):
#   mkdir -p /tmp/g && tar -xzf .gpu.tgz -C /tmp/g && scripts/gpu-runs.sh --part 1 \
#     --commit HASH --pack $OUT/part1.tgz /tmp/g/.gpu/run /tmp/runs
# then unpack the parts into docs/benchmarks/h100-DATE/ and print the page's tables from it:
#   scripts/bench_tables.py --write --from h100-DATE
# The estimates: each row's warm-up and timed frames at its median GPU (or CPU) time and its
# switch, as the JSON of the runs before recorded them for the same or the nearest
# configuration, plus 5 s a process (8 s at 16 copies) for the device, the scene and its
# levels: part 1 about 5.5 minutes, part 2 about 5, part 3 about 2, part 4 about 4.5 (17 in
# all; 21 at 10 s a process); part 5 took 3.4 minutes on the H200 (runs-part5.txt of
# docs/benchmarks/h200-2026-11-29-raster). Parts 1 and 2 are the tables culling and levels of
# detail change, part 1 first.
set -euo pipefail

part=all only="" models="" commit="" pack="" extra="" list=0 failed=0
while [[ $# -gt 2 || ${1:-} == --list ]]; do
    case $1 in
    --part) part=$2; shift 2 ;;
    --only) only=,$2,; shift 2 ;;
    --models) models=$2; shift 2 ;;
    --commit) commit=$2; shift 2 ;;
    --pack) pack=$2; shift 2 ;;
    --extra) extra=$2; shift 2 ;;
    --list) list=1; shift ;;
    *) echo "gpu-runs: unknown option '$1'" >&2; exit 2 ;;
    esac
done
if [[ $# -ne 2 ]]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit 2
fi
idview=$1 out=$2
log=$out/runs.txt
[[ $part == all ]] || log=$out/runs-part$part.txt
models=${models:-$(dirname "$idview")/models}
# The parts hidden or isolated by the hiding runs: every third unique part ID below 3,000.
thirds=$(seq -s, 0 3 2997)
if [[ $list -eq 0 ]]; then
    mkdir -p "$out"
    [[ -z $commit ]] || echo "commit: $commit" >>"$log"
fi

# run PART NAME FLAGS...: one benchmark run. bench_tables.py reads the runs from --list.
run() {
    local p=$1 name=$2
    shift 2
    [[ $part == all || $part == "$p" ]] || return 0
    [[ -z $only || $only == *",$name,"* ]] || return 0
    local line="idview --headless --benchmark $*"
    line=${line//$thirds/\$thirds} # the page writes the thousand IDs so
    if [[ $list -eq 1 ]]; then echo "part $p $name: $line"; return 0; fi
    if [[ -f $out/$name.json ]]; then
        echo "gpu-runs: $name.json is there, skipped" >&2
        return 0
    fi
    echo "gpu-runs: part $p $name: $line" >&2
    local start=$SECONDS status=0
    # shellcheck disable=SC2086 # --extra is words on purpose
    "$idview" --headless --benchmark "$@" $extra --benchmark-out "$out/$name.json" \
        >"$out/$name.txt" 2>"$out/$name.log" || status=$?
    if [[ $status -ne 0 ]]; then
        echo "gpu-runs: $name failed (exit $status): $(tail -1 "$out/$name.log")" >&2
        echo "$name: failed (exit $status) after $((SECONDS - start)) s: $line" >>"$log"
        rm -f "$out/$name.json"
        failed=$((failed + 1))
    else
        echo "$name: $((SECONDS - start)) s: $line" >>"$log"
    fi
    [[ -z $pack ]] || tar -czf "$pack" -C "$out" .
}

# Part 1 (about 5.5 min): still views, the tables culling and levels of detail change.
for msaa in 1 4; do
    # Every technique and mode, culling off and occlusion (45 s at 1x, 66 s at 4x).
    run 1 techniques-${msaa}x --msaa $msaa --frames 60 --culling off,occlusion
done
for msaa in 1 4; do
    # Levels of detail at the benchmark view (8 s, 14 s).
    run 1 view-${msaa}x --msaa $msaa --frames 60 --renderer vertex-fs,tri-fs,per-draw,mesh-fs \
        --mode mdi-baseinstance --culling off,occlusion --lod-error 0,1
done
for msaa in 1 4; do
    # 16 copies: culling, CPU recording, levels of detail and model size (35 s, 55 s).
    run 1 copies16-${msaa}x --msaa $msaa --copies 16 --frames 30 --mode mdi-baseinstance \
        --culling off,occlusion --lod-error 0,1
done
# Turning around the model (35 s).
run 1 orbit-1x --msaa 1 --frames 120 --camera-path orbit --mode mdi-baseinstance \
    --culling off,occlusion --lod-error 0,1
for msaa in 1 4; do
    # One CAD part filling the view, an object per solid (5 s, 10 s).
    run 1 motor-all-${msaa}x --msaa $msaa --model "$models/Motor-c.brep" --copies 1 --frames 60 \
        --mode push,mdi-baseinstance --culling off,occlusion
done

# Part 2 (about 5 min): the dolly path (71 s, 150 s), and the frame's fixed cost on each
# clear path with the targets' configurations (12 runs, about 2 s each).
for msaa in 1 4; do
    run 2 dolly-${msaa}x --msaa $msaa --frames 120 --camera-path dolly \
        --mode mdi-baseinstance,push --lod-error 0,1
done
for msaa in 1 4; do
    for clear in pass compute auto; do
        run 2 view-$msaa-$clear --msaa $msaa --frames 60 --renderer vertex-fs \
            --mode mdi-baseinstance --culling off,occlusion --lod-error 0,1 --clear $clear
        run 2 motor-$msaa-$clear --msaa $msaa --model "$models/Motor-c.brep" --copies 1 \
            --frames 60 --renderer vertex-fs --mode mdi-baseinstance --culling off,occlusion \
            --lod-error 0,1 --clear $clear
    done
done

# Part 3 (about 2 min): the model size and per-draw tables, last measured on older builds
# (the pass clear path, before culling).
for copies in 1 4; do
    for msaa in 1 4; do
        # Model size at 1 and 4 copies (37 s in all).
        run 3 copies$copies-${msaa}x --msaa $msaa --copies $copies --frames 30 \
            --mode mdi-baseinstance --culling off,occlusion --lod-error 0,1
    done
done
for copies in 1 2 4 8; do
    # per-draw's CPU with push constants against tri-fs in mdi-baseinstance (57 s in all).
    run 3 copies$copies --msaa 4 --copies $copies --frames 100 --renderer per-draw,tri-fs \
        --mode push,mdi-baseinstance --culling off
done
# Part 5 (about 3.4 min on the H200): the visibility buffer and its compute rasterizer against
# vertex-fs, mesh-fs and the floors, each row in the same run: the benchmark view, 16 copies,
# the dolly path and Motor-c, culling off and occlusion, levels of detail off and at 1 px;
# then the compute rasterizer with every meshlet it can draw (--raster-all), and with fewer
# and more of them than its default of 32 (--raster-pixels).
vis=(--renderer vertex-fs,mesh-fs,visbuffer,visbuffer-compute --mode mdi-baseinstance
    --culling off,occlusion --lod-error 0,1)
for msaa in 1 4; do
    run 5 "vis-view-$msaa" --msaa "$msaa" --frames 60 "${vis[@]}"
    run 5 "vis-copies16-$msaa" --msaa "$msaa" --copies 16 --frames 30 "${vis[@]}"
    run 5 "vis-dolly-$msaa" --msaa "$msaa" --frames 120 --camera-path dolly "${vis[@]}"
    run 5 "vis-motor-$msaa" --msaa "$msaa" --model "$models/Motor-c.brep" --copies 1 \
        --frames 60 "${vis[@]}"
done
raster=(--renderer visbuffer-compute --mode mdi-baseinstance --culling off,occlusion
    --lod-error 0,1)
for msaa in 1 4; do
    run 5 "rasterall-view-$msaa" --msaa "$msaa" --frames 60 "${raster[@]}" --raster-all
    run 5 "rasterall-copies16-$msaa" --msaa "$msaa" --copies 16 --frames 30 "${raster[@]}" \
        --raster-all
    run 5 "rasterall-motor-$msaa" --msaa "$msaa" --model "$models/Motor-c.brep" --copies 1 \
        --frames 60 "${raster[@]}" --raster-all
done
for px in 8 128; do
    run 5 "rasterpx$px-view-1" --msaa 1 --frames 60 "${raster[@]}" --raster-pixels $px
    run 5 "rasterpx$px-copies16-1" --msaa 1 --copies 16 --frames 30 "${raster[@]}" \
        --raster-pixels $px
done

# Part 4 (about 4.5 min): the ID-image passes, edges and the visible part count (68 s in
# all), and hidden and isolated parts (95 s in all).
for msaa in 1 4; do
    passes=(--msaa "$msaa" --frames 200 --renderer "vertex-fs,mesh-vertex-fs"
        --mode mdi-baseinstance)
    run 4 "edges-w1-$msaa" "${passes[@]}" --culling off --edges
    run 4 "edges-w3-$msaa" "${passes[@]}" --culling off --edges --edge-width 3
    run 4 "visible-$msaa" "${passes[@]}" --culling off --visible-parts
done
for msaa in 1 4; do
    hiding=(--msaa "$msaa" --frames 100 --renderer "tri-fs,tri-gs,vertex-fs,mesh-fs,mesh-vertex-fs")
    run 4 "hide-base-$msaa" "${hiding[@]}" --mode mdi-baseinstance --culling off
    run 4 "hide-hide-$msaa" "${hiding[@]}" --mode mdi-baseinstance --culling off --hide "$thirds"
    run 4 "hide-isolate-$msaa" "${hiding[@]}" --mode mdi-baseinstance --culling off \
        --isolate "$thirds"
    gs=(--msaa "$msaa" --frames 100 --renderer tri-gs --mode mdi-baseinstance --culling off)
    run 4 "hide-gsord-base-$msaa" "${gs[@]}" --gs-ordinary
    run 4 "hide-gsord-hide-$msaa" "${gs[@]}" --gs-ordinary --hide "$thirds"
done
[[ $list -eq 1 ]] && exit 0
if [[ $failed -gt 0 ]]; then
    echo "gpu-runs: $failed run(s) failed, in $out ($(basename "$log") says which)" >&2
    exit 1
fi
echo "gpu-runs: done, in $out" >&2
