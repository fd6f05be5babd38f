#!/usr/bin/env bash
# viewer_builds_test.sh IDVIEW LAVAPIPE_ICD - no stalls on a pipeline switch (issue 34, item 2):
# in the window under Xvfb on lavapipe with validation, a renderer switch and the first section
# cut are built on a worker while frames go on being presented with what was drawn before;
# once built, the switch lands. The script holds the workers (`pipeline hold`) for as long as
# "being built" must last, so nothing here depends on how fast the compile is.
# Without Xvfb it fails (viewer_lib.sh).
source "$(dirname "$0")/viewer_lib.sh"

t=0.5
{
    at key F9 # the panel off: screenshots of the scene alone, comparable byte for byte
    at frames 3
    at screenshot "$work/before.png"
    at pipeline hold
    at renderer tri-fs
    at frames 5
    at screenshot "$work/held-switch.png"
    at section x,0
    at frames 5
    at screenshot "$work/held-cut.png"
    at pipeline release
    at pipeline ready
    at frames 2
    at screenshot "$work/after.png"
    at quit
} >"$work/builds.txt"
session builds --no-saved-settings
out=$work/builds.out

# The pipeline records in order, the screenshots among them: "pipeline building NAME",
# "screenshot FILE".
events=$(jq -r --arg w "$work/" 'if .event == "pipeline" then "pipeline \(.state) \(.name)"
    elif .event == "screenshot" then "screenshot \(.path | ltrimstr($w))" else empty end' "$out")
building=$(grep -n '^pipeline building tri-fs' <<<"$events" | head -1 | cut -d: -f1)
ready=$(grep -n '^pipeline ready' <<<"$events" | tail -1 | cut -d: -f1)
held=$(grep -n '^screenshot held-cut.png' <<<"$events" | cut -d: -f1)
[[ -n $building && -n $ready && -n $held ]] && ((building < held && held < ready)) &&
    echo "ok   frames presented while the builds were held: $(paste -sd'|' <<<"$events")" ||
    fail "events out of order or missing: $(paste -sd'|' <<<"$events")"
grep -q '^pipeline building .*section' <<<"$events" &&
    echo "ok   the first section cut waited for its own build" ||
    fail "no build of the section variant: $(paste -sd'|' <<<"$events")"

cmp -s "$work/before.png" "$work/held-switch.png" && cmp -s "$work/before.png" "$work/held-cut.png" &&
    echo "ok   while held, the configuration before kept drawing" ||
    fail "a held frame differs from the one before the switch"
[[ -s $work/after.png ]] && ! cmp -s "$work/before.png" "$work/after.png" &&
    echo "ok   once built, the cut shows" || fail "after the builds the image is unchanged"

# Titles name what is drawn: the technique before until the build is done, tri-fs after.
titles=$(events "$out" title .text | sed -n 's/.*idview - \([^ ]*\) + .*/\1/p' | uniq | paste -sd'|' -)
[[ $titles == "vertex-fs|tri-fs" ]] && echo "ok   the switch landed: $titles" ||
    fail "titles: '$titles', expected vertex-fs|tri-fs"
grep -q 'validation' "$work/builds.err" && fail "validation: $(grep -m3 validation "$work/builds.err")"

# Switching again while the first build is held: the newest wish wins, the other build
# finishes into the cache unawaited (and is never drawn), and nothing is left waiting.
t=0.5
{
    at pipeline hold
    at renderer tri-fs
    at frames 2
    at renderer tri-gs
    at frames 2
    at pipeline release
    at pipeline ready
    at frames 3
    at pipeline ready
    at quit
} >"$work/newest.txt"
session newest --no-saved-settings
titles=$(events "$work/newest.out" title .text | sed -n 's/.*idview - \([^ ]*\) + .*/\1/p' | uniq |
    paste -sd'|' -)
# The technique: the pipeline's name up to its first space.
ready=$(events "$work/newest.out" pipeline 'select(.state == "ready") | .name | split(" ")[0]' |
    paste -sd'|' -)
[[ $titles == "vertex-fs|tri-gs" && $ready == tri-gs ]] &&
    echo "ok   the newest wish won: $titles" ||
    fail "titles '$titles', ready '$ready', expected vertex-fs|tri-gs and tri-gs"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer builds test passed"
