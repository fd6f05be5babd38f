#!/usr/bin/env bash
# census_cli_test.sh IDVIEW LAVAPIPE_ICD - `idview --census` as a user runs it on a CAD file:
# one JSON line per part and a summary whose counts follow from those lines, the CSV holding
# the same rows, the exterior as glTF and as STEP loading back with the seen parts and
# solids, and every refusal in one line.
source "$(dirname "$0")/cli_lib.sh"

motor=/usr/share/opencascade/data/occ/Motor-c.brep
run=(--census 42x128 --validation --model "$motor")

# expect_refusal NAME CODE MESSAGE ARGS...: exit CODE and exactly one line holding MESSAGE
# (a usage error, exit 2, adds the pointer to --help).
expect_refusal() {
    local name=$1 code=$2 message=$3 out rc
    shift 3
    out=$("$idview" "$@" 2>&1)
    rc=$?
    if [[ $rc -eq $code && $(grep -vc '^see idview --help$' <<<"$out") -eq 1 &&
        $out == *"$message"* ]]; then
        echo "ok   $name"
    else
        fail "$name: exit $rc (expected $code), output:"; echo "$out" | head -5
    fi
}

expect_refusal bad-spec 2 "--census expects VIEWSxSIZE (e.g. 162x1024), not '162'" --census 162
expect_refusal small-size 2 "--census size" --census 12x8
expect_refusal csv-alone 2 "--census-csv and --census-export need --census VIEWSxSIZE" \
    --census-csv "$work/c.csv"
expect_refusal export-kind 2 "--census-export writes .glb, .step or .stp, not '$work/x.obj'" \
    --census 4x32 --census-export "$work/x.obj"
expect_refusal mesh-to-step 1 "a STEP export needs a CAD model (STEP, IGES or BREP)" \
    --census 4x32 --scene tiles --census-export "$work/x.step"
# A section that keeps nothing: nothing seen, nothing written.
expect_refusal empty-glb 1 "nothing to write: the census saw no part" "${run[@]}" \
    --section x,-1e6 --census-export "$work/empty.glb"
expect_refusal empty-step 1 "nothing to write: no solid was seen" "${run[@]}" \
    --section x,-1e6 --census-export "$work/empty.step"
[[ ! -e $work/empty.glb && ! -e $work/empty.step ]] && echo "ok   empty-writes-nothing" ||
    fail "empty-writes-nothing: a file was left"

"$idview" "${run[@]}" --census-csv "$work/c.csv" --census-export "$work/seen.glb" \
    >"$work/c.jsonl" 2>"$work/c.err" || fail "census: exit $?: $(cat "$work/c.err")"
"$idview" "${run[@]}" --census-export "$work/seen.step" >/dev/null 2>&1 ||
    fail "census-step: exit $?"
parts=$("$idview" --stats --model "$motor" | jq .parts)
summary=$(tail -n 1 "$work/c.jsonl")
lines=$(head -n -1 "$work/c.jsonl")
# The part lines: one per part in order, each with every field.
[[ $(jq -s 'map(.part) == [range(0; length)]' <<<"$lines") == true &&
    $(grep -c . <<<"$lines") -eq $parts ]] && echo "ok   a-line-per-part" ||
    fail "a-line-per-part: $(grep -c . <<<"$lines") lines for $parts parts"
[[ $(jq -s 'all(has("part","object","name","path","pixels","views","largest_share"))' \
    <<<"$lines") == true ]] && echo "ok   part-fields" || fail "part-fields: $(head -1 <<<"$lines")"
# The summary's counts, counted again from the lines (no part is hidden or empty here).
never=$(jq -s 'map(select(.pixels == 0)) | length' <<<"$lines")
solids_seen=$(jq -s 'map(select(.pixels > 0) | .object) | unique | length' <<<"$lines")
[[ $(jq .parts_never_seen <<<"$summary") -eq $never && $never -gt 0 &&
    $(jq .parts_seen <<<"$summary") -eq $((parts - never)) &&
    $(jq .objects_seen <<<"$summary") -eq $solids_seen ]] && echo "ok   summary-counts" ||
    fail "summary-counts: $summary (never seen by the lines: $never, solids: $solids_seen)"
# Views never exceed 42, a seen part was seen in some, shares lie in 0..1.
[[ $(jq -s 'all(.views <= 42 and ((.pixels > 0) == (.views > 0)) and .largest_share >= 0 and
    .largest_share <= 1)' <<<"$lines") == true ]] && echo "ok   part-values" ||
    fail "part-values"
# The CSV: a header and the same rows.
from_json=$(jq -r '[.part, .object, .pixels, .views] | @csv' <<<"$lines")
from_csv=$(tail -n +2 "$work/c.csv" | awk -F, '{print $1 "," $2 "," $(NF-2) "," $(NF-1)}')
[[ $(head -1 "$work/c.csv") == "part,object,name,path,pixels,views,largest_share" &&
    $from_json == "$from_csv" ]] && echo "ok   csv-rows" || fail "csv-rows differ from the lines"
# The exterior: glTF of the seen parts (faces), STEP of the seen solids with their names.
glb_parts=$("$idview" --stats --model "$work/seen.glb" --parts primitives | jq .parts)
[[ $glb_parts -eq $((parts - never)) ]] && echo "ok   glb-reloads" ||
    fail "glb-reloads: $glb_parts parts, expected $((parts - never))"
step_objects=$("$idview" --tree --model "$work/seen.step" | jq '[.. | objects | select(has("object"))] | length')
[[ $step_objects -eq $solids_seen ]] && echo "ok   step-reloads" ||
    fail "step-reloads: $step_objects objects, expected $solids_seen"
[[ $failures -eq 0 ]] && echo "all census command-line checks passed"
exit $((failures > 0))
