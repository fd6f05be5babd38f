#!/usr/bin/env bash
# run_fuzz.sh [SECONDS] - builds the glTF loader fuzzer with clang in build-fuzz/ and runs it
# for SECONDS (default 60) on a copy of fuzz/corpus; exits non-zero on any crash or report.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=$root/build-fuzz

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DIDVIEW_FUZZ=ON -DIDVIEW_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target fuzz_gltf

# First every real and malformed file of Debian's assimp-testmodels glTF2 corpus, once each,
# through the instrumented loader: none may crash or trip a sanitizer.
corpus=/usr/share/assimp/models/glTF2
if [[ -d $corpus ]]; then
    mapfile -t files < <(find "$corpus" \( -name '*.gltf' -o -name '*.glb' \) -size -4M | sort)
    echo "run_fuzz: replaying ${#files[@]} files of $corpus"
    "$build/fuzz/fuzz_gltf" -runs=1 "${files[@]}" 2>&1 | tail -n 3
fi

# The fuzzer adds inputs to its corpus folder: work on a copy so the seeds stay as committed.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/fuzz/corpus" "$work/corpus"
# A crashing input is kept in build-fuzz/ as crash-<hash>, to be added as a regression test.
"$build/fuzz/fuzz_gltf" -max_total_time="$seconds" -max_len=16384 -timeout=20 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/" "$work/corpus"
