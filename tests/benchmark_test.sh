#!/usr/bin/env bash
# benchmark_test.sh IDVIEW LAVAPIPE_ICD - the benchmark smoke test: at a tiny size every
# renderer x mode x culling mode and the floors (no-id, and no-id-mesh for the mesh
# techniques) in every mode and culling mode run, with validation on, and the JSON and CSV
# carry every field. Timings are printed, never asserted.
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
[[ $(grep -c '"renderer":' "$work/b.json") -eq $rows ]] ||
    fail "expected $rows rows in the JSON, got $(grep -c '"renderer":' "$work/b.json")"
isFloor() { [[ " $floors " == *" $1 "* ]]; }
for r in $floors $renderers; do
    for m in $modes; do for c in $cullings; do
        row=$(grep "\"renderer\":\"$r\",\"mode\":\"$m\",\"culling\":\"$c\"" "$work/b.json")
        [[ -n $row ]] || { fail "no row for $r + $m, culling $c"; continue; }
        for key in gpu_ms_median gpu_ms_p90 cpu_ms_median cpu_record_ms_median cull_ms_median \
            pyramid_ms_median draws \
            draws_drawn triangles triangles_drawn meshlets_drawn id_bytes geometry_bytes \
            added_vertices added_vertex_bytes meshlets ratio_to_floor reused_frames; do
            [[ $row =~ \"$key\":[0-9] ]] || fail "$r + $m + $c lacks $key: $row"
        done
        # Recording is a part of recording and submitting.
        rec=$(sed -E 's/.*"cpu_record_ms_median":([0-9.]+).*/\1/' <<<"$row")
        all=$(sed -E 's/.*"cpu_ms_median":([0-9.]+).*/\1/' <<<"$row")
        awk -v a="$rec" -v b="$all" 'BEGIN { exit !(a > 0 && a <= b) }' ||
            fail "$r + $m + $c: recording took $rec ms of $all ms"
        [[ $row =~ \"culling_applied\":\"[a-zA-Z] ]] || fail "$r + $m + $c lacks culling_applied: $row"
        # The view stands still: from the warm-up on, what was culled in two phases (the
        # GPU-built lists, push mode's meshlets against the pyramid) is drawn again every
        # timed frame; nothing else reuses lists.
        reuses=0
        [[ $c == occlusion && ($row =~ \"culling_applied\":\"GPU-built ||
            $row =~ \"culling_applied\":\"[^\"]*depth\ pyramid) ]] && reuses=3
        [[ $row =~ \"reused_frames\":([0-9]+) ]] || fail "reused_frames: $row"
        [[ ${BASH_REMATCH[1]} -eq $reuses ]] || fail "$r + $m + $c reused ${BASH_REMATCH[1]} frames, not $reuses"
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
ids=$(grep '"renderer":' "$work/b.json" | grep -vE "$floorRows" | grep -o '"id_image_hash":"[0-9a-f]*"' | sort -u)
[[ $(wc -l <<<"$ids") -eq 1 ]] || fail "part-ID rows drew different ID images: $ids"
floorIds=$(grep -E "$floorRows" "$work/b.json" | grep -o '"id_image_hash":"[0-9a-f]*"' | sort -u)
[[ -n $floorIds && $floorIds != *"$ids"* ]] || fail "a floor wrote part IDs: $floorIds"
grep -q "benchmark: \[$rows/$rows\]" "$work/progress.txt" || fail "progress lines on stderr"

# CSV: a header and one row per renderer x mode, the floor first (two vertex-pipeline
# renderers: only the no-id floor; one culling mode).
set -- $renderers
two="$1,$2"
common+=(--culling occlusion)
"$idview" "${common[@]}" --renderer "$two" --mode push --benchmark-out "$work/b.csv" \
    >/dev/null 2>&1 || fail "csv run"
[[ $(head -1 "$work/b.csv") == renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,geometry_bytes,added_vertices,meshlets,floor,ratio_to_floor,id_image_hash,color_image_hash,culling,draws_drawn,meshlets_drawn,triangles_drawn,cull_ms_median,pyramid_ms_median ]] ||
    fail "csv header: $(head -1 "$work/b.csv")"
[[ $(wc -l <"$work/b.csv") -eq 4 ]] || fail "csv rows (no-id, $two in push): $(cat "$work/b.csv")"

# The benchmark draws with the shading flags given: --colorize-draws changes every colour
# image (one colour per draw call) and no ID image.
"$idview" "${common[@]}" --renderer "$two" --mode push --colorize-draws \
    --benchmark-out "$work/c.csv" >/dev/null 2>&1 || fail "colorize run"
"$idview" "${common[@]}" --renderer "$two" --mode push --colorize-draws \
    --benchmark-out "$work/c.json" >/dev/null 2>&1 || fail "colorize json run"
grep -q '"colorize_draws":true' "$work/c.json" || fail "JSON lacks colorize_draws true"
for r in $(head -2 "$work/b.csv" | tail -1 | cut -d, -f1) $1 $2; do
    plain=$(grep "^$r,push," "$work/b.csv" | cut -d, -f14,15)
    colored=$(grep "^$r,push," "$work/c.csv" | cut -d, -f14,15)
    [[ -n $plain && ${plain%,*} == "${colored%,*}" ]] || fail "$r: --colorize-draws changed the IDs ($plain / $colored)"
    [[ ${plain#*,} != "${colored#*,}" ]] || fail "$r: --colorize-draws did not change the colours"
done
# A camera path: every timed frame's GPU time in path order, and the path in the settings.
"$idview" "${common[@]}" --renderer "$1" --mode mdi-baseinstance --camera-path dolly \
    --benchmark-out "$work/p.json" >/dev/null 2>&1 || fail "camera path run"
grep -q '"camera_path":"dolly"' "$work/p.json" || fail "JSON lacks camera_path dolly"
[[ $(grep -c '"gpu_ms_frames":\[[0-9.]*,[0-9.]*,[0-9.]*\]' "$work/p.json") -eq 2 ]] ||
    fail "rows lack 3 frame times: $(grep -o '"gpu_ms_frames":[^]]*' "$work/p.json")"
out=$("$idview" --benchmark --renderer "$1",nope 2>&1)
[[ $? -eq 2 && $out == *"--renderer: unknown name 'nope'"* ]] || fail "bad renderer list: $out"
"$idview" --headless --renderer all >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "--renderer all without --benchmark must be a usage error"

echo "benchmark_test: $failures failed"
exit $((failures > 0))
