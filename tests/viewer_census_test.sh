#!/usr/bin/env bash
# viewer_census_test.sh IDVIEW LAVAPIPE_ICD - the Visibility section's census in the viewer
# under Xvfb on lavapipe with validation (docs/viewer.md): a census of the small procedural
# scene (an assembly with parts inside) finds as many never-seen parts as `idview --census`
# with the same views and size; hiding, isolating and selecting them each act on that many
# parts, and Ctrl+Z brings the hidden ones back; its tint by visibility changes the picture
# and, off, leaves it as before; Esc cancels a census half-way; `census here`
# lists the same parts as headless --visible-parts of the same view. Small sizes keep it to a
# few seconds of lavapipe. viewer_lib.sh: the environment, $work, fail, at and session.
source "$(dirname "$0")/viewer_lib.sh"
spec=12x128

# What the headless census counts, and the parts headless frames in the whole window.
headless=$("$idview" --scene procedural:preset=small --census $spec 2>/dev/null | tail -1)
never=$(echo "$headless" | jq -r '.parts_never_seen')
parts=$(echo "$headless" | jq -r '.parts')
[[ $never -gt 0 && $never -lt $parts ]] ||
    fail "headless --census $spec: expected some parts never seen, got '$never' of '$parts'"
visible=$("$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
    --visible-parts 2>/dev/null | jq -r '.parts[]' | sort -n)

# The census, tinted by visibility and back (the panel hidden and the blink held, so equal
# pictures are equal files); then its never-seen parts hidden (undone), isolated (undone)
# and selected.
t=0.5
{
    at key F9
    at blink strong
    at frames 2
    at screenshot "$work/plain.png"
    at census $spec
    at census-done
    at frames 2
    at screenshot "$work/done.png"
    at census tint on
    at frames 2
    at screenshot "$work/tinted.png"
    at census tint off
    at frames 2
    at screenshot "$work/untinted.png"
    at census hide
    at frames 2
    at key ctrl+Z
    at frames 2
    at census isolate
    at frames 2
    at undo
    at census select
    at frames 2
    at quit
} >"$work/run.txt"
session run --no-saved-settings
done_line=$(events "$work/run.out" census 'select(.state == "done")')
seen_never=$(echo "$done_line" | jq -r '.never_seen')
[[ $seen_never == "$never" ]] && echo "ok   never seen: $seen_never of $parts, as headless" ||
    fail "viewer census never_seen '$seen_never', headless '$never' ($done_line)"
tinted=$(events "$work/run.out" tint .parts | paste -sd' ' -)
[[ $tinted == "$(echo "$done_line" | jq -r '.seen + .never_seen') 0" ]] &&
    echo "ok   tint by visibility: $tinted parts tinted" || fail "tint events: parts '$tinted'"
same() { cmp -s "$work/$1.png" "$work/$2.png"; }
if [[ $(events "$work/run.out" screenshot | wc -l) -ne 4 ]]; then
    fail "tint: $(events "$work/run.out" screenshot | wc -l) screenshots of 4"
elif ! same plain done || same plain tinted || ! same plain untinted; then
    fail "tint: expected the picture changed by the tint alone (plain, done, untinted equal)"
else
    echo "ok   tint by visibility changes the picture, and off it is as before"
fi
hidden=$(events "$work/run.out" hidden .parts | paste -sd' ' -)
expected="$never 0 $((parts - never)) 0"
[[ $hidden == "$expected" ]] && echo "ok   hide, undo, isolate, undo: hidden $hidden" ||
    fail "hidden counts '$hidden', expected '$expected'"
selected=$(events "$work/run.out" selected .parts | tail -1)
[[ $selected == "$never" ]] && echo "ok   select never seen: $selected parts" ||
    fail "select never seen: $selected parts selected, expected $never"

# A long census cancelled by Esc after two frames; then, the panel hidden and the scene
# fitted in the whole window as headless frames it, the parts visible from here.
t=0.5
{
    at census 2000x64
    at frames 2
    at key ESC
    at census-done
    at key F9
    at fit
    at frames 3
    at census here
    at census-done
    at quit
} >"$work/here.txt"
session here --no-saved-settings
cancelled=$(events "$work/here.out" census 'select(.state == "cancelled")')
drawn=$(echo "$cancelled" | jq -r '.views_drawn // 0')
[[ $drawn -gt 0 && $drawn -lt 2000 ]] && echo "ok   Esc cancelled the census at view $drawn of 2000" ||
    fail "Esc: expected a census cancelled half-way, got '$cancelled'"
said "$work/here.out" census '.state == "done"' && fail "a cancelled census finished anyway"
here=$(events "$work/here.out" census_here '.parts[]' | sort -n)
[[ -n $here && $here == "$visible" ]] &&
    echo "ok   visible from here: $(echo "$here" | wc -l) parts, as headless --visible-parts" ||
    fail "census here: $(echo "$here" | wc -l) parts, headless $(echo "$visible" | wc -l)"
pixels=$(events "$work/here.out" census_here '.pixels | . == (sort | reverse)')
[[ $pixels == true ]] && echo "ok   visible from here: largest first" ||
    fail "census here: pixels not largest first"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer census test passed"
