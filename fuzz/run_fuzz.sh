#!/usr/bin/env bash
# run_fuzz.sh gltf|cad [SECONDS | --runs N | --replay] - builds the loader's fuzzer with clang
# in build-fuzz/ and runs it for SECONDS (default 60) on a copy of its seed corpus, from a new
# random seed each time: what a person runs to look for new faults. --runs N instead tries
# exactly N inputs from seed 1: the same ones on every machine only where the loader does the
# same work for the same input at any speed, as the glTF loader does (CI runs it so).
# --replay runs the committed inputs alone and mutates nothing: CI's CAD run, since the CAD
# loader is not like that (Open CASCADE meshes in parallel threads, a watchdog cancels a load
# after 5 s, and a mutated face can keep the mesher busy for minutes; see
# docs/reliability.md). Exits non-zero on any crash, hang or sanitizer report. Before fuzzing,
# real files and the regressions in fuzz/regressions/ run once each through the instrumented
# loader (with --replay, the seed corpus too).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:-}
limit=(-max_total_time="${2:-60}")
[[ ${2:-} == --runs ]] && limit=(-runs="${3:?--runs needs a count}" -seed=1)
replay_only=false
[[ ${2:-} == --replay ]] && replay_only=true
build=$root/build-fuzz

case $target in
gltf)
    seeds=$root/fuzz/corpus
    replay=/usr/share/assimp/models/glTF2 # Debian's assimp-testmodels: real and malformed files
    pattern=('(' -name '*.gltf' -o -name '*.glb' ')' -size -4M)
    ;;
cad)
    seeds=$root/fuzz/corpus-cad
    replay=/usr/share/opencascade/data # occt-misc; the small files, the sanitizers are slow
    pattern=('(' -name '*.brep' -o -name '*.step' -o -name '*.iges' ')' -size -100k)
    # Open CASCADE leaks by design when a read fails (objects of a half-built model, and those
    # a converted fault leaves on the stack it jumps over; see src/scene/cad/fault_guard.h), so
    # leak detection would report every damaged input: it is off for this target only.
    export ASAN_OPTIONS=detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}
    ;;
*)
    echo "usage: fuzz/run_fuzz.sh gltf|cad [SECONDS | --runs N | --replay]" >&2
    exit 2
    ;;
esac
fuzzer=$build/fuzz/fuzz_$target

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DIDVIEW_FUZZ=ON -DIDVIEW_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target "fuzz_$target"

files=()
[[ -d $replay ]] && mapfile -t files < <(find "$replay" "${pattern[@]}" | sort)
mapfile -t -O "${#files[@]}" files < <(find "$root/fuzz/regressions" -name "$target-*" | sort)
$replay_only && mapfile -t -O "${#files[@]}" files < <(find "$seeds" -type f | sort)
echo "run_fuzz: replaying ${#files[@]} files ($replay, fuzz/regressions$($replay_only && echo ", ${seeds#"$root/"}"))"
if ((${#files[@]})); then
    "$fuzzer" -runs=1 "${files[@]}" 2>&1 | tail -n 3
fi
$replay_only && exit 0

# The fuzzer adds inputs to its corpus folder: work on a copy so the seeds stay as committed.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$seeds" "$work/corpus"
# A crashing or hanging input is kept in build-fuzz/ as crash-<hash> or timeout-<hash>; it goes
# into fuzz/regressions/ once fixed. -timeout is per input: a hang fails the run.
"$fuzzer" "${limit[@]}" -max_len=32768 -timeout=30 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/" "$work/corpus"
