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
[[ $(wc -w <<<"$renderers") -ge 6 && $(wc -w <<<"$modes") -eq 3 ]] || fail "renderer list: $renderers / $modes"
rows=$((($(wc -w <<<"$renderers") + 1) * 3)) # every renderer and the no-id floor, x 3 modes
[[ $(grep -c '"renderer":' "$work/b.json") -eq $rows ]] ||
    fail "expected $rows rows in the JSON, got $(grep -c '"renderer":' "$work/b.json")"
for r in no-id $renderers; do
    for m in $modes; do
        row=$(grep "\"renderer\":\"$r\",\"mode\":\"$m\"" "$work/b.json")
        [[ -n $row ]] || { fail "no row for $r + $m"; continue; }
        for key in gpu_ms_median gpu_ms_p90 cpu_ms_median draws triangles id_bytes ratio_to_no_id; do
            [[ $row =~ \"$key\":[0-9] ]] || fail "$r + $m lacks $key: $row"
        done
        # Timings are positive and the ratio is 1 for the floor itself.
        [[ $row =~ \"gpu_ms_median\":0\.0000, ]] && fail "$r + $m has no GPU time"
        [[ $r == no-id && ! $row =~ \"ratio_to_no_id\":1\.000 ]] && fail "no-id ratio: $row"
        [[ $r == no-id && ! $row =~ \"draws\":136, ]] && fail "no-id draws (2 x 68 objects): $row"
    done
done
for key in '"device":{"name":"llvmpipe' '"driver":"' '"api":"1\.' '"size":"64x48"' '"msaa":4' \
    '"scene":"procedural:preset=small"' '"copies":2' '"search_batch":16' '"frames":3'; do
    grep -qE "$key" "$work/b.json" || fail "JSON lacks $key"
done
grep -q "benchmark: \[$rows/$rows\]" "$work/progress.txt" || fail "progress lines on stderr"

# CSV: a header and the same 21 rows.
"$idview" "${common[@]}" --renderer tri-fs,per-draw --mode push --benchmark-out "$work/b.csv" \
    >/dev/null 2>&1 || fail "csv run"
[[ $(head -1 "$work/b.csv") == renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,ratio_to_no_id ]] ||
    fail "csv header: $(head -1 "$work/b.csv")"
[[ $(wc -l <"$work/b.csv") -eq 4 ]] || fail "csv rows (no-id, tri-fs, per-draw in push): $(cat "$work/b.csv")"
out=$("$idview" --benchmark --renderer tri-fs,nope 2>&1)
[[ $? -eq 2 && $out == *"--renderer: unknown name 'nope'"* ]] || fail "bad renderer list: $out"
"$idview" --headless --renderer all >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "--renderer all without --benchmark must be a usage error"

echo "benchmark_test: $failures failed"
exit $((failures > 0))
