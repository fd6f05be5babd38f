#!/usr/bin/env bash
# viewer_census_export_test.sh IDVIEW LAVAPIPE_ICD - the Visibility section's Export seen...
# (issue 49) in the window under Xvfb on lavapipe with validation: after a census of the small
# procedural scene, `census export X.glb` writes the seen parts (the file loads back with as
# many parts as the census saw), a second export says it replaced the file, and a STEP export
# of that mesh scene is refused in words, leaving no file; after a census of occt-misc's
# Motor-c.brep with one solid hidden, `census export X.step` writes the solids with a seen
# face (the file's tree holds as many objects as headless --census counts seen). viewer_lib.sh: the environment.
source "$(dirname "$0")/viewer_lib.sh"
motor=/usr/share/opencascade/data/occ/Motor-c.brep
[[ -r $motor ]] || { echo "FAIL needs $motor from Debian's occt-misc: apt-get install occt-misc"; exit 1; }
spec=12x128

# The procedural scene: a .glb twice (the second replaces the first), a .step refused.
t=0.5
{
    at census $spec
    at census-done
    at census export "$work/seen.glb"
    at census-done
    at census export "$work/seen.step"
    at census-done
    at census export "$work/seen.glb"
    at census-done
    at quit
} >"$work/mesh.txt"
session mesh --no-saved-settings
seen=$(events "$work/mesh.out" census 'select(.state == "done") | .seen')
exports=$(events "$work/mesh.out" census_export)
[[ $(wc -l <<<"$exports") -eq 3 ]] || fail "expected 3 census_export records, got: $exports"
first=$(sed -n 1p <<<"$exports")
[[ $(jq .parts <<<"$first") == "$seen" && $(jq .replaced <<<"$first") == false ]] &&
    echo "ok   export glb: $seen parts, as the census saw" || fail "export glb: $first (seen $seen)"
reloaded=$("$idview" --stats --model "$work/seen.glb" --parts primitives 2>/dev/null | jq .parts)
[[ -n $seen && $reloaded == "$seen" ]] && echo "ok   the .glb loads back with $reloaded parts" ||
    fail "the .glb loads back with '$reloaded' parts, the census saw '$seen'"
refused=$(sed -n 2p <<<"$exports" | jq -r '.error // empty')
[[ $refused == *"a STEP export needs a CAD model"* && ! -e $work/seen.step &&
    ! -e $work/seen.step.part ]] && echo "ok   STEP of a mesh refused: $refused" ||
    fail "STEP of a mesh: expected a refusal and no file, got '$refused'"
[[ $(sed -n 3p <<<"$exports" | jq '.replaced and .parts == '"${seen:-0}") == true ]] &&
    echo "ok   a second export says it replaced the file" ||
    fail "second export: $(sed -n 3p <<<"$exports")"

# Motor-c.brep, its "solid 4" (parts 59 to 64) hidden so that one solid goes unseen: the
# solids with a seen face to .step, against headless --census's count with the same hidden.
solids_seen=$("$idview" --model "$motor" --census $spec --hide 59,60,61,62,63,64 2>/dev/null |
    tail -1 | jq .objects_seen)
t=0.5
{
    at object solid 4
    at hide
    at census $spec
    at census-done
    at census export "$work/motor.step"
    at census-done
    at quit
} >"$work/motor.txt"
xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --validation --size 720x450 --no-saved-settings \
    --model "$motor" --script "$work/motor.txt" --print-events >"$work/motor.out" 2>"$work/motor.err" ||
    { fail "motor session: exit code $?"; head -c 2000 "$work/motor.err"; }
step=$(events "$work/motor.out" census_export)
[[ $(jq .objects <<<"$step") == "$solids_seen" ]] &&
    echo "ok   export step: $solids_seen solids, as headless --census saw" ||
    fail "export step: $step, headless solids seen '$solids_seen'"
objects=$("$idview" --tree --model "$work/motor.step" 2>/dev/null |
    jq '[.. | objects | select(has("object"))] | length')
[[ -n $solids_seen && $objects == "$solids_seen" ]] &&
    echo "ok   the .step loads back with $objects solids" ||
    fail "the .step loads back with '$objects' solids, expected '$solids_seen'"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer census export test passed"
