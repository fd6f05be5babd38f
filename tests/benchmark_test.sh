#!/usr/bin/env bash
# benchmark_test.sh IDVIEW LAVAPIPE_ICD - the benchmark smoke test: at a tiny size every
# renderer x mode and the no-id floor in every mode run, with validation on, and the JSON
# and CSV carry every field. Timings are printed, never asserted.
set -uo pipefail
idview=$1
icd=$2
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

common=(--benchmark --validation --size 64x48 --frames 3 --copies 2 --scene procedural:preset=small)
"$idview" "${common[@]}" --benchmark-out "$work/b.json" >"$work/table.txt" 2>"$work/progress.txt" ||
    fail "benchmark exit $?: $(tail -3 "$work/progress.txt")"
cat "$work/table.txt"

renderers=$("$idview" --list-renderers | awk '/^renderers:/{r=1;next} /^per-draw modes:/{r=0} r{print $1}')
modes=$("$idview" --list-renderers | awk '/^per-draw modes:/{m=1;next} /^reference/{m=0} m{print $1}')
floor=$("$idview" --list-renderers | awk '/^reference/{f=1;next} f{print $1}')
[[ -n $floor ]] || fail "no reference floor in --list-renderers"
[[ $(wc -w <<<"$renderers") -ge 2 && $(wc -w <<<"$modes") -ge 1 ]] || fail "renderer list: $renderers / $modes"
# Every renderer and the floor, in every mode, as --list-renderers names them.
rows=$((($(wc -w <<<"$renderers") + 1) * $(wc -w <<<"$modes")))
[[ $(grep -c '"renderer":' "$work/b.json") -eq $rows ]] ||
    fail "expected $rows rows in the JSON, got $(grep -c '"renderer":' "$work/b.json")"
for r in $floor $renderers; do
    for m in $modes; do
        row=$(grep "\"renderer\":\"$r\",\"mode\":\"$m\"" "$work/b.json")
        [[ -n $row ]] || { fail "no row for $r + $m"; continue; }
        for key in gpu_ms_median gpu_ms_p90 cpu_ms_median draws triangles id_bytes ratio_to_no_id; do
            [[ $row =~ \"$key\":[0-9] ]] || fail "$r + $m lacks $key: $row"
        done
        for key in id_image_hash color_image_hash; do
            [[ $row =~ \"$key\":\"[0-9a-f]{16}\" ]] || fail "$r + $m lacks $key: $row"
        done
        # Timings are positive and the ratio is 1 for the floor itself.
        [[ $row =~ \"gpu_ms_median\":0\.0000, ]] && fail "$r + $m has no GPU time"
        [[ $r == "$floor" && ! $row =~ \"ratio_to_no_id\":1\.000 ]] && fail "floor ratio: $row"
        [[ $r == "$floor" && ! $row =~ \"draws\":136, ]] && fail "floor draws (2 x 68 objects): $row"
    done
done
for key in '"device":{"name":"llvmpipe' '"driver":"' '"api":"1\.' '"size":"64x48"' '"msaa":4' \
    '"scene":"procedural:preset=small"' '"copies":2' '"search_batch":16' '"frames":3' \
    '"visible":1.000' '"part_weight":0.500' '"colorize_draws":false' '"ignore_materials":false'; do
    grep -qE "$key" "$work/b.json" || fail "JSON lacks $key"
done
# Every technique drew the same parts: one ID image over all part-ID rows (the floor writes
# none, so its image is the cleared one).
ids=$(grep -v "\"renderer\":\"$floor\"" "$work/b.json" | grep -o '"id_image_hash":"[0-9a-f]*"' | sort -u)
[[ $(wc -l <<<"$ids") -eq 1 ]] || fail "part-ID rows drew different ID images: $ids"
floorIds=$(grep "\"renderer\":\"$floor\"" "$work/b.json" | grep -o '"id_image_hash":"[0-9a-f]*"' | sort -u)
[[ $floorIds != "$ids" ]] || fail "the floor wrote part IDs"
grep -q "benchmark: \[$rows/$rows\]" "$work/progress.txt" || fail "progress lines on stderr"

# CSV: a header and one row per renderer x mode, the floor first.
set -- $renderers
two="$1,$2"
"$idview" "${common[@]}" --renderer "$two" --mode push --benchmark-out "$work/b.csv" \
    >/dev/null 2>&1 || fail "csv run"
[[ $(head -1 "$work/b.csv") == renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,ratio_to_no_id,id_image_hash,color_image_hash ]] ||
    fail "csv header: $(head -1 "$work/b.csv")"
[[ $(wc -l <"$work/b.csv") -eq 4 ]] || fail "csv rows ($floor, $two in push): $(cat "$work/b.csv")"

# The benchmark draws with the shading flags given: --colorize-draws changes every colour
# image (one colour per draw call) and no ID image.
"$idview" "${common[@]}" --renderer "$two" --mode push --colorize-draws \
    --benchmark-out "$work/c.csv" >/dev/null 2>&1 || fail "colorize run"
"$idview" "${common[@]}" --renderer "$two" --mode push --colorize-draws \
    --benchmark-out "$work/c.json" >/dev/null 2>&1 || fail "colorize json run"
grep -q '"colorize_draws":true' "$work/c.json" || fail "JSON lacks colorize_draws true"
for r in $floor $1 $2; do
    plain=$(grep "^$r,push," "$work/b.csv" | cut -d, -f10,11)
    colored=$(grep "^$r,push," "$work/c.csv" | cut -d, -f10,11)
    [[ -n $plain && ${plain%,*} == "${colored%,*}" ]] || fail "$r: --colorize-draws changed the IDs ($plain / $colored)"
    [[ ${plain#*,} != "${colored#*,}" ]] || fail "$r: --colorize-draws did not change the colours"
done
out=$("$idview" --benchmark --renderer "$1",nope 2>&1)
[[ $? -eq 2 && $out == *"--renderer: unknown name 'nope'"* ]] || fail "bad renderer list: $out"
"$idview" --headless --renderer all >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "--renderer all without --benchmark must be a usage error"

echo "benchmark_test: $failures failed"
exit $((failures > 0))
