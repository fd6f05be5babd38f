#!/usr/bin/env bash
# benchmark_test.sh IDVIEW LAVAPIPE_ICD - the benchmark smoke test: at a tiny size every
# renderer x mode x culling mode and the floors (no-id, and no-id-mesh for the mesh
# techniques) in every mode and culling mode run, with validation on, and the JSON and CSV
# carry every field; every run reports the clear path it drew with and its fixed cost (a
# frame that draws nothing). Timings are printed, never compared with a number.
set -uo pipefail
idview=$1
icd=$2
# ctest passes the ICD of build/lavapipe-25 (Mesa 25) and sets LD_LIBRARY_PATH to its lib
# folder, for the newer libdrm (tests/CMakeLists.txt).
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

common=(--benchmark --validation --size 64x48 --frames 3 --copies 2 --scene procedural:preset=small)
"$idview" "${common[@]}" --benchmark-out "$work/b.json" >"$work/table.txt" 2>"$work/progress.txt" ||
    fail "benchmark exit $?: $(tail -3 "$work/progress.txt")"
cat "$work/table.txt"

list=$("$idview" --list-renderers)
renderers=$(awk '/^renderers:/{r=1;next} /^per-draw modes:/{r=0} r{print $1}' <<<"$list")
modes=$(awk '/^per-draw modes:/{m=1;next} /^reference/{m=0} m{print $1}' <<<"$list")
floors=$(awk '/^reference/{f=1;next} /^culling modes/{f=0} f{print $1}' <<<"$list" | xargs)
cullings=$(awk '/^culling modes/{c=1;next} /^what each/{c=0} c{print $1}' <<<"$list" | xargs)
[[ $(wc -w <<<"$floors") -eq 2 ]] || fail "expected two floors in --list-renderers: $floors"
[[ $cullings == "off frustum occlusion" ]] || fail "culling modes in --list-renderers: $cullings"
[[ $(wc -w <<<"$renderers") -ge 2 && $(wc -w <<<"$modes") -ge 1 ]] || fail "renderer list: $renderers / $modes"
# Every renderer and floor, in every mode and culling mode, as --list-renderers names them.
rows=$((($(wc -w <<<"$renderers") + $(wc -w <<<"$floors")) * $(wc -w <<<"$modes") * 3))
# The results' rows, one a line (the fixed cost has a line of its own).
grep '^  {"renderer":' "$work/b.json" >"$work/rows.json"
[[ $(wc -l <"$work/rows.json") -eq $rows ]] ||
    fail "expected $rows rows in the JSON, got $(wc -l <"$work/rows.json")"
isFloor() { [[ " $floors " == *" $1 "* ]]; }
for r in $floors $renderers; do
    for m in $modes; do for c in $cullings; do
        row=$(grep "\"renderer\":\"$r\",\"mode\":\"$m\",\"culling\":\"$c\"" "$work/rows.json")
        [[ -n $row ]] || { fail "no row for $r + $m, culling $c"; continue; }
        for key in gpu_ms_median gpu_ms_p90 cpu_ms_median cpu_record_ms_median cull_ms_median \
            pyramid_ms_median draws \
            draws_drawn triangles triangles_drawn meshlets_drawn id_bytes geometry_bytes \
            added_vertices added_vertex_bytes meshlets ratio_to_floor; do
            [[ $row =~ \"$key\":[0-9] ]] || fail "$r + $m + $c lacks $key: $row"
        done
        # Recording is a part of recording and submitting.
        rec=$(sed -E 's/.*"cpu_record_ms_median":([0-9.]+).*/\1/' <<<"$row")
        all=$(sed -E 's/.*"cpu_ms_median":([0-9.]+).*/\1/' <<<"$row")
        awk -v a="$rec" -v b="$all" 'BEGIN { exit !(a > 0 && a <= b) }' ||
            fail "$r + $m + $c: recording took $rec ms of $all ms"
        [[ $row =~ \"culling_applied\":\"[a-zA-Z] ]] || fail "$r + $m + $c lacks culling_applied: $row"
        # Without culling everything is drawn; with it never more than there is.
        [[ $row =~ \"draws\":([0-9]+),\"draws_drawn\":([0-9]+)\.0, ]] || fail "draws: $row"
        if [[ $c == off ]]; then
            [[ ${BASH_REMATCH[1]} -eq ${BASH_REMATCH[2]} ]] || fail "$r + $m drew other than all without culling"
        else
            [[ ${BASH_REMATCH[2]} -le ${BASH_REMATCH[1]} ]] || fail "$r + $m + $c drew more than all"
        fi
        for key in id_image_hash color_image_hash; do
            [[ $row =~ \"$key\":\"[0-9a-f]{16}\" ]] || fail "$r + $m lacks $key: $row"
        done
        [[ $row =~ \"floor\":\"([a-z-]+)\" ]] || fail "$r + $m lacks its floor: $row"
        isFloor "${BASH_REMATCH[1]}" || fail "$r + $m is measured against a non-floor: $row"
        # Timings are positive and the ratio is 1 for a floor itself.
        [[ $row =~ \"gpu_ms_median\":0\.0000, ]] && fail "$r + $m has no GPU time"
        isFloor "$r" && [[ ! $row =~ \"floor\":\"$r\",\"ratio_to_floor\":1\.000 ]] && fail "floor ratio: $row"
        isFloor "$r" && [[ ! $row =~ \"draws\":136, ]] && fail "floor draws (2 x 68 objects): $row"
    done; done
done
for key in '"device":{"name":"llvmpipe' '"driver":"' '"api":"1\.' '"size":"64x48"' '"msaa":4' \
    '"scene":"procedural:preset=small"' '"copies":2' '"search_batch":16' '"frames":3' \
    '"visible":1.000' '"part_weight":0.500' '"colorize_draws":false' '"ignore_materials":false' \
    '"camera_path":"none"'; do
    grep -qE "$key" "$work/b.json" || fail "JSON lacks $key"
done
grep -q '"skipped":\[\]' "$work/b.json" || fail "JSON lacks an empty skipped list (lavapipe 25 runs all)"
# Every technique drew the same parts: one ID image over all part-ID rows (the floors write
# none, so their image is the cleared one).
floorRows=$(for f in $floors; do printf '"renderer":"%s",|' "$f"; done)
floorRows=${floorRows%|}
ids=$(grep -vE "$floorRows" "$work/rows.json" | grep -o '"id_image_hash":"[0-9a-f]*"' | sort -u)
[[ $(wc -l <<<"$ids") -eq 1 ]] || fail "part-ID rows drew different ID images: $ids"
floorIds=$(grep -E "$floorRows" "$work/rows.json" | grep -o '"id_image_hash":"[0-9a-f]*"' | sort -u)
[[ -n $floorIds && $floorIds != *"$ids"* ]] || fail "a floor wrote part IDs: $floorIds"

# The clear path: asked auto (the default), which timed both paths on this device (or read
# them from the file beside the pipeline cache) and drew with the faster.
[[ $(sed -n 2p "$work/b.json") =~ ^\ \"clear\":\"auto\",\"clear_path\":\"(pass|compute)\",\"clear_timing\":(.*),$ ]] ||
    fail "JSON's clear fields: $(sed -n 2p "$work/b.json")"
ran=${BASH_REMATCH[1]} timing=${BASH_REMATCH[2]}
if [[ $timing =~ ^\{\"samples\":4,\"pass_ms\":([0-9.]+),\"compute_ms\":([0-9.]+),\"remembered\":(true|false)\}$ ]]; then
    # As render::ClearTiming::faster() decides; equal after the JSON's rounding, either.
    faster=$(awk -v p="${BASH_REMATCH[1]}" -v c="${BASH_REMATCH[2]}" -v ran="$ran" 'BEGIN {
        print (!(p > 0 && c > 0) ? "none" : (c < p ? "compute" : (c > p ? "pass" : ran))) }')
    [[ $faster == "$ran" ]] || fail "auto drew with $ran, the faster was $faster: $timing"
else
    fail "auto reports no timing of the two paths at 4x MSAA: $timing"
fi
grep -qE "^clear $ran \(auto: pass [0-9.]+ ms, compute [0-9.]+ ms, (timed now|remembered)\)$" \
    "$work/table.txt" || fail "the table's header lacks the clear path: $(sed -n 2p "$work/table.txt")"
# A visibility buffer always ends its pass in compute (its shading pass writes the background).
visRows=$(for r in $(awk '/^renderers:/{r=1;next} /^per-draw modes:/{r=0} r && /visibility buffer/ {print $1}' <<<"$list"); do
    printf '"renderer":"%s",|' "$r"; done)
visRows=${visRows%|}
visCount=0
[[ -z $visRows ]] || visCount=$(grep -cE "$visRows" "$work/rows.json")
[[ -z $visRows || $(grep -E "$visRows" "$work/rows.json" | grep -c '"clear_path":"compute"') -eq $visCount ]] ||
    fail "a visibility buffer's row drew with other than compute"
[[ $(grep -vE "${visRows:-^$}" "$work/rows.json" | grep -c "\"clear_path\":\"$ran\"") -eq $((rows - visCount)) &&
    $(grep -c "^ \"fixed_cost\":.*\"clear_path\":\"$ran\"" "$work/b.json") -eq 1 ]] ||
    fail "not every row (and the fixed cost) drew with $ran"
# The fixed cost: once, the first technique in its first mode drawing nothing, culling off;
# its ID image is the one no technique wrote (the floors'), and every row's time above it is
# its median less the fixed cost's, within the JSON's rounding.
fixedRow=$(grep '^ "fixed_cost":{' "$work/b.json")
first=$(head -1 <<<"$renderers") firstMode=$(head -1 <<<"$modes")
[[ $fixedRow =~ ^\ \"fixed_cost\":\{\"visible\":0\.000,\"renderer\":\"$first\",\"mode\":\"$firstMode\",\"culling\":\"off\", ]] ||
    fail "fixed cost: not $first + $firstMode, culling off, visible 0: $fixedRow"
for key in '"draws":0,' '"draws_drawn":0\.0,' '"triangles":0,' '"triangles_drawn":0\.0,' \
    '"above_fixed_ms":0\.0000,' "${floorIds:-no floor ID image}"; do
    [[ $fixedRow =~ $key ]] || fail "fixed cost lacks $key: $fixedRow"
done
fixedMs=$(sed -E 's/.*"gpu_ms_median":([0-9.]+),.*/\1/' <<<"$fixedRow")
awk -v f="$fixedMs" 'BEGIN { exit !(f > 0) }' || fail "fixed cost has no GPU time: $fixedRow"
sed -E 's/.*"gpu_ms_median":([0-9.]+),"gpu_ms_p90":[0-9.]+,"above_fixed_ms":(-?[0-9.]+),.*/\1 \2/' \
    "$work/rows.json" | awk -v f="$fixedMs" 'NF != 2 || ($1 - f - $2)^2 > 1.5e-4^2 { bad++; print }
        END { exit bad > 0 || NR == 0 }' || fail "above_fixed_ms is not gpu_ms_median - $fixedMs"
grep -qE "^empty +$firstMode +off +[0-9.]+ +[0-9.]+ +0\.000 .* fixed cost: $first, nothing drawn$" \
    "$work/table.txt" || fail "the table lacks the fixed-cost row"

# CSV: a header, the fixed cost (visible 0) and one row per renderer x mode, the floor first
# (two vertex-pipeline renderers: only the no-id floor; one culling mode). The clear path
# forced: every row says so.
set -- $renderers
two="$1,$2"
common+=(--culling occlusion)
"$idview" "${common[@]}" --renderer "$two" --mode push --clear pass --benchmark-out "$work/b.csv" \
    --progress >/dev/null 2>"$work/csv.err" || fail "csv run"
# A line per row as it is timed is progress: into a file only with --progress (the first run
# had none), one for each of the three timed rows then.
grep -q '^benchmark: \[' "$work/progress.txt" && fail "progress lines into a file without --progress"
[[ $(grep -c '^benchmark: \[[0-9]/3\] ' "$work/csv.err") -eq 3 ]] ||
    fail "--progress: a line per row: $(grep '^benchmark: \[' "$work/csv.err")"
[[ $(head -1 "$work/b.csv") == renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,geometry_bytes,added_vertices,meshlets,floor,ratio_to_floor,id_image_hash,color_image_hash,culling,draws_drawn,meshlets_drawn,triangles_drawn,cull_ms_median,pyramid_ms_median,above_fixed_ms,clear_path,visible ]] ||
    fail "csv header: $(head -1 "$work/b.csv")"
[[ $(wc -l <"$work/b.csv") -eq 5 ]] || fail "csv rows (fixed cost, no-id, $two in push): $(cat "$work/b.csv")"
[[ $(sed -n 2p "$work/b.csv") =~ ^$1,push,([0-9.]+),[0-9.]+,[0-9.]+,0,0,.*,off,0\.0,0\.0,0\.0,.*,0\.0000,pass,0\.000$ ]] ||
    fail "csv's fixed cost: $(sed -n 2p "$work/b.csv")"
tail -n +3 "$work/b.csv" | awk -F, -v f="${BASH_REMATCH[1]:-0}" \
    '$23 != "pass" || $24 != "1.000" || ($3 - f - $22)^2 > 1.5e-4^2 { bad++; print }
    END { exit bad > 0 || NR != 3 }' || fail "csv rows: above_fixed_ms, clear_path pass, visible 1"

# The benchmark draws with the shading flags given: --colorize-draws changes every colour
# image (one colour per draw call) and no ID image.
"$idview" "${common[@]}" --renderer "$two" --mode push --colorize-draws \
    --benchmark-out "$work/c.csv" >/dev/null 2>&1 || fail "colorize run"
"$idview" "${common[@]}" --renderer "$two" --mode push --colorize-draws \
    --benchmark-out "$work/c.json" >/dev/null 2>&1 || fail "colorize json run"
grep -q '"colorize_draws":true' "$work/c.json" || fail "JSON lacks colorize_draws true"
for r in $(sed -n 3p "$work/b.csv" | cut -d, -f1) $1 $2; do
    plain=$(grep "^$r,push,.*,1\.000$" "$work/b.csv" | cut -d, -f14,15)
    colored=$(grep "^$r,push,.*,1\.000$" "$work/c.csv" | cut -d, -f14,15)
    [[ -n $plain && ${plain%,*} == "${colored%,*}" ]] || fail "$r: --colorize-draws changed the IDs ($plain / $colored)"
    [[ ${plain#*,} != "${colored#*,}" ]] || fail "$r: --colorize-draws did not change the colours"
done
# A camera path: every timed frame's GPU time in path order, and the path in the settings;
# the other clear path forced, and no timing of the two.
"$idview" "${common[@]}" --renderer "$1" --mode mdi-baseinstance --camera-path dolly \
    --clear compute --benchmark-out "$work/p.json" >"$work/p.txt" 2>&1 || fail "camera path run"
grep -q '"camera_path":"dolly"' "$work/p.json" || fail "JSON lacks camera_path dolly"
grep -q '^ "clear":"compute","clear_path":"compute","clear_timing":null,$' "$work/p.json" ||
    fail "forced compute: $(grep '"clear":' "$work/p.json")"
[[ $(grep -cE '^( "fixed_cost":|  \{"renderer":).*"clear_path":"compute"' "$work/p.json") -eq 3 ]] ||
    fail "rows (and the fixed cost) not drawn with compute"
grep -q '^clear compute (forced)$' "$work/p.txt" || fail "table header: forced compute"
# The fixed cost's frames too (it is timed like any row).
[[ $(grep -c '"gpu_ms_frames":\[[0-9.]*,[0-9.]*,[0-9.]*\]' "$work/p.json") -eq 3 ]] ||
    fail "rows lack 3 frame times: $(grep -o '"gpu_ms_frames":[^]]*' "$work/p.json")"
out=$("$idview" --benchmark --renderer "$1",nope 2>&1)
[[ $? -eq 2 && $out == *"--renderer: unknown name 'nope'"* ]] || fail "bad renderer list: $out"
"$idview" --headless --renderer all >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "--renderer all without --benchmark must be a usage error"

echo "benchmark_test: $failures failed"
exit $((failures > 0))
