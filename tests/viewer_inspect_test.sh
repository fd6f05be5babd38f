#!/usr/bin/env bash
# viewer_inspect_test.sh IDVIEW LAVAPIPE_ICD - the Inspect panel's Open CASCADE work off the UI
# thread (issue 47, item 2), in the window under Xvfb on lavapipe with validation, on
# occt-misc's Motor-c.brep. The script holds the worker (`inspect hold`) for as long as
# "computing" must last, so nothing here depends on how fast Open CASCADE is: selecting every
# solid says "inspect: computing" at once, the viewer then rests (a rest line: no frames spun
# while it waits) and still presents frames (a screenshot), and once released the answer
# lands with the values headless --properties gives. A second selection made while the first
# is held supersedes it: only the second's answer shows. Without Xvfb it fails (viewer_lib.sh).
source "$(dirname "$0")/viewer_lib.sh"
motor=/usr/share/opencascade/data/occ/Motor-c.brep
[[ -r $motor ]] || { echo "FAIL needs $motor from Debian's occt-misc: apt-get install occt-misc"; exit 1; }

# motor NAME: the viewer on Motor-c.brep, running $work/NAME.txt.
motor() {
    local name=$1
    xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --validation --size 720x450 \
        --no-saved-settings --model "$motor" --script "$work/$name.txt" --print-events \
        >"$work/$name.out" 2>"$work/$name.err"
    local rc=$?
    [[ $rc -eq 0 ]] || { fail "$name session: exit code $rc"; head -c 2000 "$work/$name.err"; }
}
# near A B: A and B agree to 1e-6 (relative), B not empty.
near() {
    awk -v a="$1" -v b="$2" \
        'BEGIN{d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(b != "" && d <= 1e-6 * (m < 1 ? 1 : m))}'
}
# json KEY: KEY's number in the JSON line on stdin.
json() { python3 -c "import json, sys; print(json.load(sys.stdin)$1)"; }

t=0.5
{
    at inspect hold
    at node select Motor-c
    at frames 3
    at rest 1
    at screenshot "$work/held.png"
    at inspect release
    at inspect ready
    at frames 2
    # A newer selection while the first is held: the first's answer never shows.
    at escape
    at inspect hold
    at node select Motor-c
    at frames 3
    at node select Motor-c/solid 2
    at frames 3
    at inspect release
    at inspect ready
    at frames 2
    at quit
} >"$work/inspect.txt"
motor inspect
out=$work/inspect.out
grep -q 'validation' "$work/inspect.err" && fail "validation: $(grep -m3 validation "$work/inspect.err")"

# The first selection: computing, a rest and a frame presented while held, then the answer.
# One word a record: its event, with the selection's count and the solids' count and volume.
events=$(jq -r 'if .event == "selected" then "selected \(.parts)"
    elif .event == "inspect_solids" then "inspect_solids \(.solids) \(.volume)"
    elif (.event | test("^(inspect_.*|rest|screenshot)$")) then .event else empty end' "$out")
first=$(sed -n '/^selected /,$p' <<<"$events" | sed '/^inspect_solids/q')
line() { grep -n "$1" <<<"$first" | head -1 | cut -d: -f1; }
computing=$(line '^inspect_computing$') rest=$(line '^rest$') shot=$(line '^screenshot$')
solids=$(line '^inspect_solids ')
[[ -n $computing && -n $rest && -n $shot && -n $solids ]] &&
    ((computing < rest && rest < solids && shot < solids)) &&
    echo "ok   held: computing, the viewer rested and drew, then the answer: $(paste -sd'|' <<<"$first" | cut -c1-300)" ||
    fail "events out of order or missing: $(paste -sd'|' <<<"$first" | cut -c1-400)"

# Its values: every solid whole, as headless --properties all sums them.
total=$("$idview" --model "$motor" --properties all 2>/dev/null | tail -1)
read -r n volume area < <(events "$out" inspect_solids '"\(.solids) \(.volume) \(.area)"' | head -1)
want_volume=$(json '["volume"]' <<<"$total") want_area=$(json '["area"]' <<<"$total")
[[ $n == 17 ]] && near "$volume" "$want_volume" && near "$area" "$want_area" &&
    echo "ok   17 solids: volume $volume area $area, as headless --properties all" ||
    fail "inspect solids '$n' volume '$volume' area '$area', headless 17 $want_volume $want_area"
read -r sx sy sz < <(events "$out" inspect_size '.size | map(tostring) | join(" ")' | head -1)
size=($(json '["bbox"]["size"]' <<<"$total" | tr -d '[],'))
near "$sx" "${size[0]}" && near "$sy" "${size[1]}" && near "$sz" "${size[2]}" &&
    echo "ok   the exact box $sx $sy $sz" || fail "inspect size '$sx $sy $sz', headless ${size[*]}"

# The second: two selections asked while held, one answer, the newer's (solid 2, object 1).
second=$(sed -n '/^selected 0$/,$p' <<<"$events")
answers=$(grep -c '^inspect_solids ' <<<"$second")
asked=$(grep -c '^inspect_computing$' <<<"$second")
one=$("$idview" --model "$motor" --properties 1 2>/dev/null | json '["volume"]')
got=$(sed -n 's/^inspect_solids 1 \(.*\)/\1/p' <<<"$second")
[[ $asked == 2 && $answers == 1 ]] && near "$got" "$one" &&
    echo "ok   the newer selection superseded the held one: its volume $got alone" ||
    fail "asked $asked, answers $answers ('$got', want solid 2's $one): $(paste -sd'|' <<<"$second" | cut -c1-400)"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer inspect test passed"
