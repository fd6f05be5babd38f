#!/usr/bin/env bash
# viewer_parts_test.sh IDVIEW LAVAPIPE_ICD - the viewer under Xvfb on lavapipe with validation,
# as a user selects and looks: box selections, hide, isolate and show (with every renderer's
# box), the assembly tree's checkboxes and rows, the selection levels and the double-click,
# the Inspect panel's things A and B (click, Ctrl+click, Esc) and their distance,
# loads refused past --max-triangles and cancelled, the standard views, the projection and F,
# and paths typed into the panel's open field. Each session's counts are checked against
# headless runs of the same view or --tree. Without Xvfb it fails (viewer_lib.sh). The lavapipe environment, the
# Xvfb check, $work, fail, at and session: viewer_lib.sh; each session opens on the
# viewer's defaults (--no-saved-settings).
source "$(dirname "$0")/viewer_lib.sh"
# words FILE: a line a record, its event and the fields these checks read: "selected 3" (a
# count), "selected part 5" (one part named), "hidden 0", "visible 12", "xray on", "view front",
# "projection orthographic", "fit scene"; other events by their name alone.
words() {
    jq -r '.event + " " + (if .event == "selected" and .part != null then "part \(.part)"
        elif .event | IN("selected", "hidden", "visible") then "\(.parts)"
        elif .event == "xray" then (if .on then "on" else "off" end)
        elif .event == "view" then .name
        elif .event == "projection" then (if .ortho then "orthographic" else "perspective" end)
        elif .event == "fit" then .what else "" end)' "$1"
}

# The scene to open by typing its path, as glTF.
"$idview" --scene procedural:preset=small --export "$work/small.glb" >/dev/null ||
    fail "could not export the small scene"

# The parts session: box selections (Shift, Ctrl and Alt + drag), H, Shift+H, I and the object
# list's selection by name, with edges on, checked against what headless rendering of the
# same view (720x450, no camera move) reports for the same rectangles; then a box with every
# renderer. The boxes lie right of where the panel would be; it is hidden, and F fits the
# scene in the whole window as headless frames it (a model opens fitted beside the panel).
t=0.5
parts() { # the sorted part IDs headless --select-rect finds in X0,Y0,X1,Y1, one per line
    "$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
        --select-rect "$1" "${@:2}" 2>/dev/null | sed -n 's/.*"parts":\[\([0-9,]*\)\].*/\1/p' |
        tr ',' '\n' | sed '/^$/d' | sort -n
}
big=$(parts 420,150,600,330)
cut=$(parts 420,150,500,200)
extra=$(parts 380,300,560,440)
after_remove=$(comm -23 <(echo "$big" | sort) <(echo "$cut" | sort) | sort -n)
after_add=$( (echo "$after_remove"; echo "$extra") | sed '/^$/d' | sort -nu)
count() { echo -n "$1" | grep -c .; }
hidden_ids=$(echo "$after_add" | paste -sd, -)
visible_all=$("$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
    --visible-parts 2>/dev/null | sed -n 's/^{"count":\([0-9]*\).*/\1/p')
visible_hidden=$("$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
    --visible-parts --hide "$hidden_ids" 2>/dev/null | sed -n 's/^{"count":\([0-9]*\).*/\1/p')
[[ $(count "$big") -gt 10 && $(count "$after_remove") -gt 0 && -n $visible_all &&
    $(count "$after_add") -gt $(count "$after_remove") ]] ||
    fail "headless --select-rect / --visible-parts gave nothing to compare with"
# X-ray: a pixel where, in the headless image of the same view, a part outside the big box's
# selection covers a selected part (X-ray shows the selected one there), the same in the
# 5x5 pixels around it in both images so that a sliver a bit apart changes nothing.
"$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
    --id-image "$work/plain.ids" >/dev/null 2>&1
"$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 --xray \
    --select-rect 420,150,600,330 --id-image "$work/xray.ids" >/dev/null 2>&1
read -r xray_x xray_y xray_part < <(python3 - "$work/plain.ids" "$work/xray.ids" \
    "$(echo "$big" | paste -sd, -)" <<'EOF'
import struct, sys
w, h = 720, 450
plain, xray = (struct.unpack("<%dI" % (w * h), open(f, "rb").read()) for f in sys.argv[1:3])
selected = {int(i) for i in sys.argv[3].split(",")}
for y in range(160, h - 3, 2):
    for x in range(300, w - 3, 2):
        a, b = plain[y * w + x], xray[y * w + x]
        if a in selected or b not in selected:
            continue
        if all(plain[(y + dy) * w + x + dx] == a and xray[(y + dy) * w + x + dx] == b
               for dy in range(-2, 3) for dx in range(-2, 3)):
            print(x, y, b)
            sys.exit()
EOF
)
[[ -n ${xray_part:-} ]] || fail "headless --xray showed no selected part behind another"
{
    at key F9
    at key F
    at frames 6 # the visible part count of the view F framed, however slow frames are
    at key E
    at box 420 150 600 330
    at frames 6
    at box 420 150 500 200 remove
    at frames 6
    at box 380 300 560 440 add
    at frames 6
    at key H
    at pipeline ready # the hiding pipeline variant, built on a worker
    at frames 8
    at key shift+H
    at frames 8
    at box 420 150 600 330
    at frames 6
    at key I
    at pipeline ready
    at frames 8
    at key shift+H
    at object base plate
    at frames 4
    for r in $("$idview" --list-renderers | awk '/^renderers:/{on=1; next} /^[^ ]/{on=0} on{print $1}'); do
        at renderer "$r"
        at pipeline ready
        at key ESC
        at box 420 150 600 330
        at frames 6
    done
    # X-ray over the big box's selection: a click where another part covered a selected one
    # selects the selected one, and the ID image then holds that part alone.
    at renderer vertex-fs
    at pipeline ready
    at key X
    at pipeline ready # the hiding variant, built on a worker
    at frames 6
    at click "${xray_x:-0}" "${xray_y:-0}"
    at pipeline ready
    at frames 8
    at xray off
    at frames 8
    at quit
} >"$work/parts.txt"
session parts --no-saved-settings
events=$(words "$work/parts.out" | grep -E '^(selected|hidden) ')
expect_event() { # expect_event N WORDS: the Nth selected/hidden record reads WORDS
    local got
    got=$(echo "$events" | sed -n "${1}p")
    if [[ $got == "$2" ]]; then echo "ok   $2"; else fail "event $1: '$got', expected '$2'"; fi
}
expect_event 1 "selected $(count "$big")"
expect_event 2 "selected $(count "$after_remove")"
expect_event 3 "selected $(count "$after_add")"
expect_event 4 "selected 0"
expect_event 5 "hidden $(count "$after_add")"
expect_event 6 "hidden 0"
expect_event 7 "selected $(count "$big")"
partcount=$("$idview" --stats --scene procedural:preset=small 2>/dev/null |
    sed -n 's/.*"parts":\([0-9]*\),.*/\1/p')
[[ -n $partcount ]] || fail "--stats gave no part count"
expect_event 8 "hidden $((partcount - $(count "$big")))"
expect_event 9 "hidden 0"
line=$(echo "$events" | sed -n 10p)
[[ $line =~ ^selected\ (part\ [0-9]+|[1-9][0-9]*)$ ]] && echo "ok   object list: $line" ||
    fail "selecting the object 'base plate' by name gave: $line"
# Every renderer's box: Esc clears, then the same parts as headless.
n=0
for r in $("$idview" --list-renderers | awk '/^renderers:/{on=1; next} /^[^ ]/{on=0} on{print $1}'); do
    n=$((n + 1))
    got=$(echo "$events" | grep -vx 'selected 0' | sed -n "$((9 + n))p")
    [[ $got == "selected $(count "$big")" ]] || fail "box with $r: '$got'"
done
echo "ok   box selection with each of $n renderers"
# X-ray: on, the click through, then off.
after_x=$(words "$work/parts.out" | sed -n '/^xray on$/,$p')
clicked=$(echo "$after_x" | grep -m1 '^selected ')
[[ $clicked == "selected part ${xray_part:-none}" ]] &&
    echo "ok   X-ray: a click through a translucent part selects part $xray_part behind it" ||
    fail "X-ray: the click at ${xray_x:-?},${xray_y:-?} gave '$clicked', expected part ${xray_part:-?}"
xray_seen=$(echo "$after_x" | sed -n '/^selected part/,/^xray off$/p' | sed -n 's/^visible //p' | tail -1)
[[ $xray_seen == 1 ]] && echo "ok   X-ray: the ID image holds the one selected part" ||
    fail "X-ray with one part selected: visible parts '$xray_seen', expected 1"
said "$work/parts.out" xray '.on == false' || fail "X-ray: no 'xray: off'"
# The visible part count the panel shows: once F has framed the scene (the count before the
# first box's selection, frames after F), the headless count of the same view; with the parts
# hidden fewer (not compared with headless: parts revealed behind the hidden ones are seen
# through a camera the viewer rebuilds from its orbit, which can differ from headless's in
# the last bits, enough to show or not a sliver); isolated, exactly the parts of the box (all
# of them were visible in it); and after Shift+H the first count again.
counts=$(events "$work/parts.out" visible .parts)
first_seen=$(words "$work/parts.out" | awk '/^selected /{exit} /^visible /{n = $2} END{print n}')
[[ $first_seen == "$visible_all" ]] && echo "ok   visible parts: $first_seen" ||
    fail "visible parts: viewer '$first_seen', headless '$visible_all'"
while_hidden=$(words "$work/parts.out" | awk '/^hidden [1-9]/{on=1} on && /^hidden 0$/{exit} on' |
    sed -n 's/^visible //p' | tail -1)
[[ -n $while_hidden && $while_hidden != "$visible_all" ]] &&
    echo "ok   visible parts with $(count "$after_add") hidden: $while_hidden (headless: $visible_hidden)" ||
    fail "hiding parts did not change the visible count ($while_hidden)"
isolated=$(words "$work/parts.out" | awk '/^hidden [1-9]/{n++} n==2{on=1} on && /^hidden 0$/{exit} on' |
    sed -n 's/^visible //p' | tail -1)
[[ $isolated == "$(count "$big")" ]] && echo "ok   visible parts isolated: $isolated" ||
    fail "visible parts after isolating $(count "$big") parts: $isolated"
[[ $(echo "$counts" | tail -1) == "$visible_all" ]] ||
    fail "visible parts after showing all: $(echo "$counts" | tail -1), expected $visible_all"

# The assembly tree: a node's checkbox hides every part under it and shows them again, a
# row click selects them, Ctrl+click adds another node's; the counts are those --tree gives.
node_parts() { # node_parts PATH...: the unique parts under these nodes, from --tree's JSON
    "$idview" --tree --scene procedural:preset=small | python3 -c '
import json, sys
wanted, parts = set(sys.argv[1:]), set()
def walk(node, path, inside):
    inside = inside or path in wanted
    if inside and "parts" in node:
        parts.update(range(node["parts"][0], node["parts"][0] + node["parts"][1]))
    for child in node.get("children", []):
        walk(child, path + "/" + child["name"] if path else child["name"], inside)
walk(json.load(sys.stdin), "", False)
print(len(parts))' "$@"
}
gearbox=$(node_parts "gearbox module")
plate=$(node_parts "gearbox module/base plate")
both=$(node_parts "gearbox module" "gearbox module/base plate")
{
    at node hide gearbox module
    at frames 4
    at node show gearbox module
    at frames 4
    at node select gearbox module/base plate
    at frames 2
    at node add gearbox module
    at frames 2
    at key ESC
    # Headless's opening view: the panel hidden and F (a model opens fitted beside the panel).
    at key F9
    at key F
    at frames 4
    at move 470 260
    at level solid
    at click 470 260
    at frames 6
    at level assembly
    at click 470 260
    at frames 6
    at level face
    at dblclick 470 260
    at frames 6
    # The Inspect panel's things: a face of the base plate (A), Ctrl+click a bolt's (B), a
    # third Ctrl+click a gear's (B again), then Esc. Each distance is worked out on the
    # Inspect worker: `inspect ready` waits for it, so the next click does not supersede it.
    at click 520 240
    at frames 6
    at click 350 180 ctrl
    at inspect ready
    at frames 6
    at click 350 240 ctrl
    at inspect ready
    at frames 6
    at key ESC
    at frames 2
    at quit
} >"$work/tree.txt"
session tree --no-saved-settings
tree_events=$(words "$work/tree.out" | grep -E '^(selected|hidden) ' | head -8 | tr '\n' '|')
# The click at 470,260 lands on the base plate, object 0 (headless --pick says so): level
# solid selects its parts, assembly every part under its group, a double-click the object.
object0=$("$idview" --tree --scene procedural:preset=small | python3 -c '
import json, sys
def find(node):
    if node.get("object") == 0:
        return node["parts"][1]
    return next((n for n in map(find, node.get("children", [])) if n is not None), None)
print(find(json.load(sys.stdin)))')
picked=$("$idview" --headless --scene procedural:preset=small --size 720x450 --frames 1 \
    --pick 470,260 2>/dev/null | sed -n 's/.*"object":\([0-9]*\),.*/\1/p')
[[ $picked == 0 ]] || fail "the click point shows object '$picked', not the base plate"
want="hidden $gearbox|hidden 0|selected $plate|selected $both|selected 0|selected $object0|"
want+="selected $gearbox|selected $object0|"
if [[ $gearbox -gt $plate && $plate -gt $object0 && $object0 -gt 1 && $tree_events == "$want" ]]; then
    echo "ok   assembly tree and selection levels: hide, show, select and add nodes; solid, assembly, double-click ($gearbox, $plate, $object0 parts)"
else
    fail "assembly tree events '$tree_events', expected '$want'"
fi

# The things the Inspect panel compares, named by their path and part as headless --pick
# names the parts under those pixels, each click's A and B in turn; the distance of A and B
# each time B is set, as headless --distance gives it for the same two parts.
pick() { # pick X,Y: "PART PATH · part LOCAL" of the part headless --pick finds there
    "$idview" --headless --scene procedural:preset=small --size 720x450 --frames 1 --pick "$1" \
        2>/dev/null | python3 -c '
import json, sys
p = json.load(sys.stdin)
print(p["part"], p["path"] + " \u00b7 part " + str(p["local_part"]))'
}
read -r plate_part plate_face < <(pick 520,240)
read -r bolt_part bolt_face < <(pick 350,180)
read -r gear_part gear_face < <(pick 350,240)
things=$(events "$work/tree.out" inspect_things '"\(.a // "none")|\(.b // "none")"' | paste -sd'#' -)
want="gearbox module/base plate|none#gearbox module|none#gearbox module/base plate|none#"
want+="$plate_face|none#$plate_face|$bolt_face#$plate_face|$gear_face#none|none"
[[ $things == "$want" ]] && echo "ok   inspect things: a click makes A, Ctrl+click B, again B, Esc none" ||
    fail "inspect things '$things', expected '$want'"
distances=($(events "$work/tree.out" inspect_distance 'select(.unit == "none") | .distance'))
if [[ ${#distances[@]} -ne 2 ]]; then
    fail "expected two inspect_distance records in unit none: $(events "$work/tree.out" inspect_distance)"
elif "$idview" --help 2>&1 | grep -q -- '--distance'; then
    n=0
    for b in "$bolt_part" "$gear_part"; do
        headless=$("$idview" --scene procedural:preset=small --distance "$plate_part,$b" \
            2>/dev/null | sed -n 's/.*"distance":\([0-9.e+-]*\).*/\1/p')
        awk -v a="${distances[$n]}" -v b="$headless" \
            'BEGIN{d = a - b; if (d < 0) d = -d; exit !(b != "" && d <= 1e-6 * (b < 1 ? 1 : b))}' &&
            echo "ok   inspect distance ${distances[$n]}: headless --distance $plate_part,$b says $headless" ||
            fail "inspect distance ${distances[$n]}, headless --distance $plate_part,$b '$headless'"
        n=$((n + 1))
    done
else
    echo "note headless --distance missing: inspect distances ${distances[*]} not compared"
fi

# Loads that must not take the scene: a drop past --max-triangles fails in one line and the
# scene stays (a click picks the very part it picked before); Cancel stops a slow CAD load
# (terrain.brep meshes for half a minute in one face) inside that face, and the scene stays.
motor=/usr/share/opencascade/data/occ/Motor-c.brep
terrain=/usr/share/opencascade/data/occ/terrain.brep
if [[ -f $motor && -f $terrain ]]; then
    t=0.5
    {
        at move 420 230
        at click 420 230
        at frames 6
        at drop "$motor"
        at loaded
        at key ESC
        at click 420 230
        at frames 6
        at drop "$terrain"
        at frames 10
        at cancel
        at loaded
        at quit
    } >"$work/refuse.txt"
    # Beside the session, from its first line about the terrain (--progress: at the start of
    # that load), the same load without a cancel (headless --stats --progress): when the
    # session's says "cancelled", that one must not have meshed half the face yet (where Cancel
    # waited for the face, both would be near its end). Two loads side by side, so the
    # machine's speed drops out; the polls wait for lines and assume no pace.
    race() {
        until grep -q "^idview: loading $terrain: " "$work/refuse.err" 2>/dev/null; do
            [[ -e $work/refuse.done ]] && return
            sleep 0.1
        done
        "$idview" --stats --no-cache --progress --max-triangles 1000 --model "$terrain" \
            >/dev/null 2>"$work/uncancelled.err" &
        local uncancelled=$!
        : >"$work/uncancelled.started"
        until grep -q "^idview: $terrain: cancelled$" "$work/refuse.err" || [[ -e $work/refuse.done ]]; do
            sleep 0.1
        done
        kill $uncancelled 2>/dev/null
        wait $uncancelled 2>/dev/null
    }
    race &
    racer=$!
    start=$(date +%s)
    session refuse --no-saved-settings --max-triangles 1000 --no-cache --progress
    took=$(($(date +%s) - start))
    touch "$work/refuse.done"
    wait $racer
    grep -q "^idview: $motor: the tessellation passes --max-triangles 1000 (about [0-9]* triangles at deflection [0-9.e+-]*); try --deflection [0-9.e+-]*$" \
        "$work/refuse.err" && echo "ok   a drop past --max-triangles is refused in one line" ||
        fail "no one-line refusal of $motor: $(grep -v '^idview: loading ' "$work/refuse.err" | head -c 500)"
    grep -q "^idview: $terrain: cancelled$" "$work/refuse.err" && echo "ok   Cancel stopped $terrain" ||
        fail "Cancel did not stop $terrain: $(grep -v '^idview: loading ' "$work/refuse.err" | head -c 500)"
    said "$work/refuse.out" opened && fail "a refused or cancelled model opened"
    picks=$(events "$work/refuse.out" selected 'select(.part != null)')
    if [[ $(wc -l <<<"$picks") -eq 2 && $(sort -u <<<"$picks" | wc -l) -eq 1 ]]; then
        echo "ok   the scene stayed: $(head -1 <<<"$picks")"
    else
        fail "the two clicks picked: $picks"
    fi
    meshed=$(sed -n "s|^idview: loading $terrain: tessellating \([0-9]*\)%$|\1|p" \
        "$work/uncancelled.err" 2>/dev/null | tail -1)
    # (It may not have printed a line yet: then it had meshed nothing.)
    if [[ -e $work/uncancelled.started ]] && ((${meshed:-0} < 50)) &&
        ! grep -q "^idview: error: " "$work/uncancelled.err" 2>/dev/null; then
        echo "ok   cancelled inside the face: the same load beside it had meshed ${meshed:-0} % (session $took s)"
    else
        fail "Cancel waited for $terrain's face: the load beside it had meshed ${meshed:-?} %: $(tail -2 "$work/uncancelled.err" 2>/dev/null)"
    fi
fi

# The views session: the standard view keys (1, Ctrl+7, 0), the script's view and ortho, O, and
# F fitting the selection, then the scene. Each says so in an event line; the top view in
# ortho shows the parts headless --view top --ortho shows for the same window size.
t=0.5
{
    at key 1
    at frames 3
    at key ctrl+7
    at frames 3
    at key 0
    at frames 3
    at key O
    at view top
    at frames 8
    at ortho off
    at frames 3
    at view front
    at frames 3
    at object base plate
    at frames 3
    at key F
    at frames 6
    at key I
    at key ESC
    at key F
    at frames 6
    at key shift+H
    at key F
    at frames 6
    at quit
} >"$work/views.txt"
session views --no-saved-settings
told=$(words "$work/views.out" | grep -E '^(view|projection|fit) ' | paste -sd'|' -)
expected='view front|view bottom|view isometric|projection orthographic|view top|projection perspective|view front|fit selection|fit shown parts|fit scene'
[[ $told == "$expected" ]] && echo "ok   views session: $told" || fail "views session said '$told', expected '$expected'"
# F on the base plate frames it (another set of parts shows); F with the plate isolated frames
# it alone; F with nothing selected or hidden frames the whole scene beside the panel.
visible_after() { # the last visible part count after the record reading $1, before the next event
    words "$work/views.out" | awk -v e="$1" '$0 == e {on=1; next} on && /^(view|projection|fit|selected) /{exit} on' |
        sed -n 's/^visible //p' | tail -1
}
front=$(visible_after "view front")
on_plate=$(visible_after "fit selection")
whole=$(visible_after "fit scene")
[[ -n $front && -n $on_plate && $on_plate != "$front" && -n $whole && $whole != "$on_plate" ]] &&
    echo "ok   F: selection shows $on_plate parts, then the scene $whole (front view: $front)" ||
    fail "F: selection '$on_plate', scene '$whole', front view '$front'"
top_viewer=$(words "$work/views.out" | awk '/^view top/{on=1} on && /^projection perspective/{exit} on' |
    sed -n 's/^visible //p' | tail -1)
top_headless=$("$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
    --view top --ortho --visible-parts 2>/dev/null | sed -n 's/^{"count":\([0-9]*\).*/\1/p')
iso_count=$(words "$work/views.out" | awk '/^view isometric/{on=1} on && /^projection orthographic/{exit} on' |
    sed -n 's/^visible //p' | tail -1)
[[ -n $top_viewer && $top_viewer == "$top_headless" && $top_viewer != "$iso_count" ]] &&
    echo "ok   top view in ortho shows $top_viewer parts, as headless (isometric: $iso_count)" ||
    fail "top view in ortho: viewer '$top_viewer' parts, headless '$top_headless' (isometric '$iso_count')"

# The open field as a newcomer types into it: Ctrl+L, a path, Enter pressed and released
# between two frames (a script's key always is), the model opens; the field is then empty,
# so the next path typed opens as it is, not joined to the last one.
cp "$work/small.glb" "$work/again.glb"
t=0.5
{
    at key ctrl+L
    at frames 3
    at type "$work/small.glb"
    at key ENTER
    at loaded
    at frames 3
    at key ctrl+L
    at frames 3
    at type "$work/again.glb"
    at key ENTER
    at loaded
    at frames 3
    at screenshot "$work/typed.png"
    at quit
} >"$work/typed.txt"
session typed --no-saved-settings
opened=$(events "$work/typed.out" opened .path | paste -sd' ' -)
[[ $opened == "$work/small.glb $work/again.glb" ]] && echo "ok   typed paths opened: Enter kept, field emptied" ||
    fail "typed paths opened '$opened' ($(head -c 300 "$work/typed.err"))"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer parts test passed"
