#!/usr/bin/env bash
# viewer_rest_test.sh IDVIEW LAVAPIPE_ICD - the viewer at rest, counted through its event
# lines under Xvfb on lavapipe with validation (issue 34, item 1): resting the cursor over a
# part for four seconds runs no scene pass while the hovered part's blink is composed again
# and again, over the hovered part's tiles alone and with the panel kept as drawn, and those
# pictures are the ones a frame that draws everything shows; vsync off draws a scene pass
# every frame; a drag that turns the camera draws scene passes; the explode slider changes
# the picture and the viewer rests again after it. On Motor-c.brep with a B-rep edge hovered
# the same holds (the edge is drawn again over the tiles, the panel kept); the hover ends when
# the pointer leaves or the window loses focus. Without Xvfb it fails (viewer_lib.sh).
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
# The rest records' fields, from the records on stdin: scene passes, compositions, those over
# the hovered part's tiles, frames keeping the panel.
rest_field() { jq -r "select(.event == \"rest\") | .$1"; }
scenes() { rest_field scene_passes; }
comps() { rest_field compositions; }
tiles() { rest_field hover_tiles; }
kept() { rest_field panel_kept; }

hovered=$(event_lines "$out" '.event == "hovered" and .part != null' | head -1)
off=$(event_lines "$out" '.event == "title" and (.text | contains(" - vsync off"))' | head -1)
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
# Every step of the blink: the hovered part's tiles, the panel kept; but for the first one on
# a machine slow enough that the hover's last whole composition has not finished by then
# (its tiles are read back once it has) or the panel still took in the hovered part's name.
steps=$((last - first))
tiled=$(($(echo "$resting" | tiles | tail -1) - $(echo "$resting" | tiles | head -1)))
panels=$(($(echo "$resting" | kept | tail -1) - $(echo "$resting" | kept | head -1)))
[[ $steps -ge 3 && $tiled -ge $((steps - 1)) && $panels -ge $((steps - 1)) ]] &&
    echo "ok   $steps steps of the blink: $tiled over the hovered part's tiles, $panels keeping the panel" ||
    fail "of $steps steps of the blink $tiled were over the tiles and $panels kept the panel"

# vsync off: a scene pass every frame (the script's 10 frames at least), continuous title.
said "$out" title '.text | contains(" - vsync off, continuous - ")' &&
    echo "ok   vsync off says continuous" || fail "vsync off: no 'continuous' title"
on=$(event_lines "$out" '.event == "title" and (.text | contains(" - vsync on, draws on change"))' |
    awk -v from="$off" '$1 > from {print; exit}')
after=$(sed -n "${on:-1},\$p" "$out" | scenes | head -1)
[[ -n $after && $after -ge $((s + 10)) ]] &&
    echo "ok   continuous drawing: scene passes $s -> $after" ||
    fail "vsync off drew scene passes $s -> '$after' (10 frames at least)"
# A drag turns the camera: more scene passes by the last rest.
end=$(scenes <"$out" | tail -1)
[[ -n $end && $end -gt $after ]] && echo "ok   a drag draws scene passes: $after -> $end" ||
    fail "a drag drew no scene pass ($after -> '$end')"
events "$out" rest | wc -l | xargs echo "     rest records:"

# Pictures: each step of the blink (held by the script) drawn anew from the scene pass on
# (`redraw` and the screenshot at the same time, so in the same frame), and composed over
# the hovered part's tiles with the panel kept, after the other step was drawn. A rest after
# each screenshot puts a rest line after it however slow the frames are (commands 0.1 s
# apart leave no time to sleep on a slow machine). blink_pictures NAME X Y [FLAGS...]: the
# cursor at X,Y; FLAGS go to the session.
blink_pictures() {
    local name=$1 x=$2 y=$3
    shift 3
    t=0.5
    {
        at frames 3
        at move "$x" "$y"
        at frames 5
        at blink strong
        at frames 3
        echo "$t redraw"
        at screenshot "$work/$name-strong-drawn.png"
        at rest 0.3
        at frames 3
        at blink weak
        at frames 3
        at screenshot "$work/$name-weak-kept.png"
        at rest 0.3
        echo "$t redraw"
        at screenshot "$work/$name-weak-drawn.png"
        at rest 0.3
        at frames 3
        at blink strong
        at frames 3
        at screenshot "$work/$name-strong-kept.png"
        at rest 0.3
        at quit
    } >"$work/$name.txt"
    session "$name" "$@"
    # Screenshots come from the same encoder, so equal files are equal pictures.
    same() { cmp -s "$work/$name-$1.png" "$work/$name-$2.png"; }
    local pictures
    pictures=$(events "$work/$name.out" screenshot | wc -l)
    # The frames keeping the panel by each screenshot (the first rest record after it).
    kept_at() {
        local at
        at=$(event_lines "$work/$name.out" ".event == \"screenshot\" and (.path | endswith(\"$name-$1.png\"))")
        sed -n "${at:-\$},\$p" "$work/$name.out" | kept | head -1
    }
    if [[ $pictures -ne 4 ]]; then
        fail "$name: $pictures screenshots of 4"
    elif same strong-drawn weak-drawn; then
        fail "$name: the two steps of the blink show the same picture"
    elif same strong-drawn strong-kept && same weak-drawn weak-kept; then
        echo "ok   $name: both steps of the blink composed over its tiles with the panel kept equal them drawn anew"
    else
        fail "$name: a step of the blink composed at rest differs from the same step drawn anew"
    fi
    [[ $(kept_at weak-kept) -gt $(kept_at strong-drawn) && $(kept_at strong-kept) -gt $(kept_at weak-drawn) ]] &&
        echo "ok   $name: the frames of those steps kept the panel" ||
        fail "$name: no frame kept the panel: $(kept_at strong-drawn) $(kept_at weak-kept) $(kept_at weak-drawn) $(kept_at strong-kept)"
    grep -q 'validation' "$work/$name.err" && fail "validation: $(grep -m3 validation "$work/$name.err")"
}
blink_pictures blink 480 230
# On a B-rep the pointer also hovers an edge, drawn over the scene apart from the panel
# (ImGui's foreground list): a step of the blink draws it again over the part's tiles alone.
motor=/usr/share/opencascade/data/occ/Motor-c.brep
blink_pictures edge 480 230 --model "$motor"
said "$work/edge.out" edge_hovered '.edge != null' &&
    echo "ok   edge: $(events "$work/edge.out" edge_hovered 'select(.edge != null) | .edge' | head -1)" ||
    fail "edge: no B-rep edge hovered at 480,230 on $motor"

# The hover ends when the pointer leaves the window and when the window loses the keyboard:
# nothing blinks then (the compositions stop), and moving over the part hovers it again.
t=0.5
{
    at frames 3
    at move 480 230
    at frames 5
    at leave
    at rest 3
    at move 480 230
    at frames 5
    at unfocus
    at rest 3
    at quit
} >"$work/leave.txt"
session leave
out=$work/leave.out
# After each "hovered: none", three seconds of rest: a blink would compose six frames or more
# in them however slow the machine (a step every third of a second, each woken by the clock);
# without it only the frames that follow an event (three, pacer.h) and the hover's own.
n=0
while read -r at; do
    n=$((n + 1))
    # The records from there to the next hover of a part.
    next=$(event_lines "$out" '.event == "hovered" and .part != null' |
        awk -v from="$at" '$1 > from {print; exit}')
    c=$(sed -n "$at,${next:-\$}p" "$out" | comps)
    first=$(echo "$c" | head -1)
    last=$(echo "$c" | tail -1)
    [[ -n $first && $((last - first)) -le 4 ]] &&
        echo "ok   hover $n ended: compositions $first to $last while the pointer is away" ||
        fail "hover $n ended but the compositions went on: '$first' to '$last'"
done < <(event_lines "$out" '.event == "hovered" and .part == null')
began=$(events "$out" hovered 'select(.part != null)' | wc -l)
[[ $n -eq 2 && $began -eq 2 ]] || fail "leave, then unfocus: $n hovers ended of 2, $began began"

# The explode slider, as a script's `explode` sets it: the picture changes, and afterwards
# the viewer rests again, frames composed with no scene pass while nothing moves.
t=0.5
{
    at frames 3
    at rest 0.5
    at screenshot "$work/at-rest.png"
    at explode 0.8
    at frames 3
    at rest 0.5
    at screenshot "$work/exploded.png"
    at frames 3
    at rest 0.5
    at quit
} >"$work/explode.txt"
session explode
out=$work/explode.out
said=$(event_lines "$out" '.event == "explode" and .at == 0.8' | head -1)
# The rest lines after the slider moved: the first after its scene pass, then the last.
moved=$(sed -n "${said:-1},\$p" "$out" | scenes | head -1)
ended=$(sed -n "${said:-1},\$p" "$out" | scenes | tail -1)
before=$(sed -n "1,${said:-1}p" "$out" | scenes | tail -1)
if [[ -z $said ]]; then
    fail "no 'explode: 0.8' line"
elif cmp -s "$work/at-rest.png" "$work/exploded.png"; then
    fail "exploding did not change the picture"
elif [[ -n $moved && -n $before && $moved -gt $before && $ended -eq $moved ]]; then
    echo "ok   explode 0.8 changed the picture ($before -> $moved scene passes), then rested at $ended"
else
    fail "scene passes around the explode: before '$before', after '$moved', at the end '$ended'"
fi
grep -q 'validation' "$work/explode.err" && fail "validation: $(grep -m3 validation "$work/explode.err")"
[[ $failures -eq 0 ]] || exit 1
