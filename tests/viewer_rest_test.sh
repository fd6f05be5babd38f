#!/usr/bin/env bash
# viewer_rest_test.sh IDVIEW LAVAPIPE_ICD - the viewer at rest, counted through its event
# lines under Xvfb on lavapipe with validation (issue 34, item 1): resting the cursor over a
# part for four seconds runs no scene pass while the hovered part's blink is composed again
# and again; vsync off draws a scene pass every frame; a drag that turns the camera draws
# scene passes. Exit 77: skipped (viewer_lib.sh).
source "$(dirname "$0")/viewer_lib.sh"

cat >"$work/rest.txt" <<'SCRIPT'
0.5 frames 3
0.6 move 480 230
0.7 frames 5
# four seconds with the cursor resting over a part: nothing to do but blink
0.8 rest 4
0.9 key V
1.0 frames 10
1.1 key V
1.2 frames 3
1.25 rest 0.5
1.3 drag 480 230 520 250
1.4 frames 3
1.45 rest 0.5
1.5 quit
SCRIPT
session rest
out=$work/rest.out
# rest lines: "idview: rest: S scene passes, C compositions"
scenes() { sed -n 's/^idview: rest: \([0-9]*\) scene passes, \([0-9]*\) compositions$/\1/p'; }
comps() { sed -n 's/^idview: rest: \([0-9]*\) scene passes, \([0-9]*\) compositions$/\2/p'; }

hovered=$(grep -m1 -n '^idview: hovered: part ' "$out" | cut -d: -f1)
off=$(grep -m1 -n '^idview: title: .* - vsync off' "$out" | cut -d: -f1)
[[ -n $hovered && -n $off && $hovered -lt $off ]] || {
    fail "no part hovered before vsync went off (hovered at line '$hovered', off at '$off')"
    exit 1
}
resting=$(sed -n "$((hovered + 1)),$((off - 1))p" "$out")
s=$(echo "$resting" | scenes | sort -u)
c=$(echo "$resting" | comps)
first=$(echo "$c" | head -1)
last=$(echo "$c" | tail -1)
if [[ $(echo "$s" | wc -l) -eq 1 && -n $s && -n $first && $((last - first)) -ge 3 ]]; then
    echo "ok   resting over a part: $s scene passes throughout, compositions $first to $last"
else
    fail "resting over a part: scene passes '$(echo "$s" | tr '\n' ' ')', compositions $first to $last"
fi

# vsync off: a scene pass every frame (the script's 10 frames at least), continuous title.
grep -q '^idview: title: .* - vsync off, continuous - ' "$out" &&
    echo "ok   vsync off says continuous" || fail "vsync off: no 'continuous' title"
on=$(awk -v from="$off" 'NR > from && /^idview: title: .* - vsync on, draws on change/ {print NR; exit}' "$out")
after=$(sed -n "${on:-1},\$p" "$out" | scenes | head -1)
[[ -n $after && $after -ge $((s + 10)) ]] &&
    echo "ok   continuous drawing: scene passes $s -> $after" ||
    fail "vsync off drew scene passes $s -> '$after' (10 frames at least)"
# A drag turns the camera: more scene passes by the last rest.
end=$(scenes <"$out" | tail -1)
[[ -n $end && $end -gt $after ]] && echo "ok   a drag draws scene passes: $after -> $end" ||
    fail "a drag drew no scene pass ($after -> '$end')"
grep -c '^idview: rest: ' "$out" | xargs echo "     rest lines:"
[[ $failures -eq 0 ]] || exit 1
