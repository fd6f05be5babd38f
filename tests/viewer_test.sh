#!/usr/bin/env bash
# viewer_test.sh IDVIEW LAVAPIPE_ICD - the real window, as a user drives it: idview under Xvfb
# on lavapipe with validation (synchronization validation too), fed a --script that switches
# through every renderer (the floors included) and mode, changes MSAA, presses V twice,
# orbits, zooms, resizes, clicks the model, takes a screenshot and drops files on the window.
# Then the standard views, the projection and F on the selection (a session of its own), and
# paths typed into the panel's open field.
# Checks the exit code (3 means validation messages), the title following the renderer and
# vsync, the click selecting a part, the drops, and that the screenshot shows a picture; and
# that without --print-events the viewer writes nothing to stdout. Exit 77: skipped.
# The lavapipe environment, the Xvfb check, $work, fail and at: viewer_lib.sh. Each session
# opens on the viewer's defaults (--no-saved-settings), whatever the last one closed with;
# viewer_settings_test.sh tests the settings kept between runs.
source "$(dirname "$0")/viewer_lib.sh"

# The renderers and modes idview lists, so a new technique is covered without editing this.
renderers=$("$idview" --list-renderers | awk '/^renderers:/{on=1; next} /^[^ ]/{on=0} on{print $1}')
modes=$("$idview" --list-renderers | awk '/^per-draw modes:/{on=1; next} /^[^ ]/{on=0} on{print $1}')
floors=$("$idview" --list-renderers | awk '/^reference/{on=1; next} /^[^ ]/{on=0} on{print $1}')
floor=${floors%%[[:space:]]*} # the first floor, no-id
[[ -n $renderers && -n $modes && -n $floor ]] || fail "could not read --list-renderers"
renderers="$renderers $floors" # the viewer draws the floors too

# Commands queue behind slow ones (a pipeline compile), so the times are only an order.
# The window is 720x450; the procedural small preset sits in the middle, right of the panel.
t=0.5
# A STEP, an IGES and a BREP file to drop, from Debian's occt-misc where it is installed.
cad_files=()
for f in step/screw.step iges/bearing.iges occ/bottle.brep; do
    [[ -f /usr/share/opencascade/data/$f ]] && cad_files+=("/usr/share/opencascade/data/$f")
done
{
    at move 420 230
    for r in $renderers; do
        at renderer "$r"
        for m in $modes; do at mode "$m"; done
    done
    at renderer "${renderers%%[[:space:]]*}" # the first listed, and the first mode
    at mode "${modes%%[[:space:]]*}"
    at msaa 4
    at msaa 1
    at key M # measure mode: two clicks measure instead of selecting
    at click 470 260
    at frames 6
    at click 520 280
    at frames 6
    at key M
    at key V
    at key V
    at drag 600 300 560 320
    at scroll 1
    at key F
    at key R
    at copies 1000000 # cannot fit: refused in words, the scene stays
    at copies 2
    at copies 1
    at resize 800 500
    at move 470 260
    at click 470 260
    at frames 6 # the click's pick comes back a frame or two later, however slow frames are
    at screenshot "$work/window.png"
    at frames 3
    at key ESC
    at frames 3
    at screenshot "$work/uncut.png"
    at section z,0,flip # a plane through the plates, as the panel's Section sets one
    at frames 3
    at screenshot "$work/cut.png"
    at section off
    at drop "$work/broken.glb"
    at drop "$work/small.glb"
    at frames 6 # drops open between frames
    for f in "${cad_files[@]}"; do at drop "$f"; done
    # They load one after the other on a worker thread while frames go on.
    at loaded
    at quit
} >"$work/script.txt"
# Dropped files: one that is not glTF at all, and the same scene exported as .glb.
echo "not a model" >"$work/broken.glb"
"$idview" --scene procedural:preset=small --export "$work/small.glb" >/dev/null ||
    fail "could not export the small scene"

start=$(date +%s)
# It opens on the floor, as --renderer asks: the first title names it.
xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --no-saved-settings \
    --sync-validation --size 720x450 \
    --scene procedural:preset=small --renderer "$floor" --script "$work/script.txt" \
    --print-events >"$work/out.txt" 2>"$work/err.txt"
rc=$?
echo "viewer ran for $(($(date +%s) - start)) s"
if [[ $rc -ne 0 ]]; then
    fail "exit code $rc (3: validation messages)"
    head -c 4000 "$work/err.txt"
fi

# The title: vsync on, then off after the first V, then on again after the second.
vsync=$(sed -n 's/^idview: title: .* - vsync \(on\|off\).*/\1/p' "$work/out.txt" | uniq | tr '\n' ' ')
if [[ $vsync == *"on off on"* ]]; then
    echo "ok   title follows vsync: $vsync"
else
    fail "title should go vsync on, off, on; it went: $vsync"
    head -20 "$work/out.txt"
fi
for r in $renderers; do
    grep -q "^idview: title: idview - $r + " "$work/out.txt" || fail "title never named renderer $r"
done
first=$(grep -m1 '^idview: title:' "$work/out.txt")
[[ $first == "idview: title: idview - $floor + "* ]] || fail "--renderer $floor opened as: $first"

grep -q '^idview: shaders reloaded' "$work/out.txt" || fail "R did not reload the shaders"
grep -q '^idview: 1000000 copies make .* objects' "$work/err.txt" ||
    fail "1000000 copies were not refused in words"

# The click on the model selected a part; Esc cleared it (and so did not close the window).
if grep -q '^idview: selected: part [0-9]' "$work/out.txt"; then
    echo "ok   click selected: $(grep -m1 '^idview: selected: part' "$work/out.txt")"
else
    fail "the click selected no part"
fi
grep -q '^idview: selected: none' "$work/out.txt" || fail "Esc did not clear the selection"

# A broken drop names the file and keeps the scene; a good one opens.
grep -q "^idview: .*broken.glb" "$work/err.txt" || fail "the broken drop reported nothing"
if grep -q "^idview: opened: .*small.glb" "$work/out.txt"; then
    echo "ok   dropped model opened"
else
    fail "the dropped model did not open"
fi
# Each CAD file opened in the window with the counts headless --stats gives.
for f in "${cad_files[@]}"; do
    stats=$("$idview" --model "$f" --stats 2>/dev/null)
    objects=$(sed -n 's/.*"objects":\([0-9]*\).*/\1/p' <<<"$stats")
    parts=$(sed -n 's/.*"parts":\([0-9]*\).*/\1/p' <<<"$stats")
    if [[ -n $objects ]] && grep -q "^idview: opened: $f ($objects objects, $parts parts" "$work/out.txt"; then
        echo "ok   dropped $(basename "$f") opened: $objects objects, $parts parts"
    else
        fail "the dropped $f did not open with $objects objects and $parts parts"
    fi
done

# Measure mode: the second click's line holds both points, as headless --measure finds them
# in the same opening view (the viewer's orbit camera rebuilds it, so to float rounding).
measured=$(grep '^idview: measure: {' "$work/out.txt" | tail -1 | sed 's/^idview: measure: //')
expected=$("$idview" --headless --scene procedural:preset=small --size 720x450 --frames 1 \
    --measure 470,260,520,280 2>/dev/null)
if python3 - "$measured" "$expected" <<'EOF'
import json, sys
got, want = json.loads(sys.argv[1]), json.loads(sys.argv[2])
assert got["parts"] == want["parts"] and None not in got["parts"], (got, want)
for key in ("p0", "p1"):
    assert all(abs(a - b) <= 1e-4 for a, b in zip(got[key], want[key])), (key, got, want)
assert abs(got["distance"] - want["distance"]) <= 1e-4, (got, want)
EOF
then
    echo "ok   measure mode: $measured"
else
    fail "measure mode gave '$measured', headless --measure '$expected'"
fi
sed -n '/measure: on/,/measure: off/p' "$work/out.txt" | grep -q '^idview: selected: part' &&
    fail "a click in measure mode selected a part"

# The section plane changed the picture.
if [[ -s $work/cut.png && -s $work/uncut.png ]] && ! cmp -s "$work/cut.png" "$work/uncut.png"; then
    echo "ok   the section plane cut the picture"
else
    fail "the section plane did not change the screenshot"
fi

# The screenshot is a picture: the window's size and many distinct colours.
png=$work/window.png
if [[ ! -s $png ]]; then
    fail "no screenshot written"
elif command -v python3 >/dev/null; then
    if report=$(python3 - "$png" 2>&1 <<'EOF'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, head = 8, b"", None
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR": head = struct.unpack(">IIBBBBB", body)
    if kind == b"IDAT": idat += body
    pos += 12 + length
width, height, depth, colour = head[:4]
assert depth == 8 and colour == 6, "expected 8-bit RGBA"
raw, stride, rows, prev = zlib.decompress(idat), width * 4, [], bytearray(width * 4)
for y in range(height):  # undo the PNG row filters
    kind, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = row[i - 4] if i >= 4 else 0
        b, c = prev[i], (prev[i - 4] if i >= 4 else 0)
        p = a + b - c
        pred = [0, a, b, (a + b) // 2,
                a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c][kind]
        row[i] = (row[i] + pred) & 255
    rows.append(bytes(row))
    prev = row
colours = {r[i:i + 3] for r in rows for i in range(0, stride, 4)}
print(f"{width}x{height}, {len(colours)} distinct colours")
assert (width, height) == (800, 500), "expected the resized 800x500 window"
assert len(colours) >= 200, "too few colours for the model and the panel"
EOF
    ); then
        echo "ok   screenshot $report"
    else
        fail "screenshot check: $report"
    fi
elif [[ $(stat -c %s "$png") -lt 20000 ]]; then # without python3: a blank PNG is tiny
    fail "screenshot is suspiciously small ($(stat -c %s "$png") bytes)"
fi

# Quiet by default: the same kind of session without --print-events writes nothing to stdout.
t=0.5
{
    at renderer "$floor"
    at move 420 230
    at click 420 230
    at frames 4
    at key R
    at key V
    at screenshot "$work/quiet.png"
    at quit
} >"$work/quiet.txt"
xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --no-saved-settings \
    --validation --size 720x450 \
    --scene procedural:preset=small --script "$work/quiet.txt" >"$work/quiet.out" 2>"$work/quiet.err"
rc=$?
[[ $rc -eq 0 ]] || { fail "quiet run: exit code $rc"; head -c 2000 "$work/quiet.err"; }
[[ -s $work/quiet.png ]] || fail "quiet run: no screenshot (did the script run?)"
if [[ -s $work/quiet.out ]]; then
    fail "without --print-events the viewer wrote to stdout:"
    head -5 "$work/quiet.out"
else
    echo "ok   quiet without --print-events"
fi

# The parts session: box selections (Shift, Ctrl and Alt + drag), H, Shift+H, I and the object
# list's selection by name, with edges on, checked against what headless rendering of the
# same view (720x450, no camera move) reports for the same rectangles; then a box with every
# renderer. The panel covers the left of the window, the boxes lie right of it.
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
{
    at key E
    at box 420 150 600 330
    at frames 6
    at box 420 150 500 200 remove
    at frames 6
    at box 380 300 560 440 add
    at frames 6
    at key H
    at frames 8
    at key shift+H
    at frames 8
    at box 420 150 600 330
    at frames 6
    at key I
    at frames 8
    at key shift+H
    at object base plate
    at frames 4
    for r in $("$idview" --list-renderers | awk '/^renderers:/{on=1; next} /^[^ ]/{on=0} on{print $1}'); do
        at renderer "$r"
        at key ESC
        at box 420 150 600 330
        at frames 6
    done
    at quit
} >"$work/parts.txt"
xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --no-saved-settings \
    --validation --size 720x450 \
    --scene procedural:preset=small --script "$work/parts.txt" --print-events \
    >"$work/parts.out" 2>"$work/parts.err"
rc=$?
[[ $rc -eq 0 ]] || { fail "parts session: exit code $rc"; head -c 3000 "$work/parts.err"; }
events=$(grep -E '^idview: (selected|hidden):' "$work/parts.out")
expect_event() { # expect_event N LINE: the Nth selected/hidden event is LINE
    local got
    got=$(echo "$events" | sed -n "${1}p")
    if [[ $got == "idview: $2" ]]; then echo "ok   $2"; else fail "event $1: '$got', expected '$2'"; fi
}
expect_event 1 "selected: $(count "$big") parts"
expect_event 2 "selected: $(count "$after_remove") parts"
expect_event 3 "selected: $(count "$after_add") parts"
expect_event 4 "selected: none"
expect_event 5 "hidden: $(count "$after_add") parts"
expect_event 6 "hidden: 0 parts"
expect_event 7 "selected: $(count "$big") parts"
partcount=$("$idview" --stats --scene procedural:preset=small 2>/dev/null |
    sed -n 's/.*"parts":\([0-9]*\),.*/\1/p')
[[ -n $partcount ]] || fail "--stats gave no part count"
expect_event 8 "hidden: $((partcount - $(count "$big"))) parts"
expect_event 9 "hidden: 0 parts"
line=$(echo "$events" | sed -n 10p)
[[ $line =~ ^idview:\ selected:\ (part\ [0-9]+|[0-9]+\ parts) ]] && echo "ok   object list: $line" ||
    fail "selecting the object 'base plate' by name gave: $line"
# Every renderer's box: Esc clears, then the same parts as headless.
n=0
for r in $("$idview" --list-renderers | awk '/^renderers:/{on=1; next} /^[^ ]/{on=0} on{print $1}'); do
    n=$((n + 1))
    got=$(echo "$events" | grep -v 'selected: none' | sed -n "$((9 + n))p")
    [[ $got == "idview: selected: $(count "$big") parts" ]] || fail "box with $r: '$got'"
done
echo "ok   box selection with each of $n renderers"
# The visible part count the panel shows: at first the headless count of the same view;
# with the parts hidden fewer (not compared with headless: parts revealed behind the hidden
# ones are seen through a camera the viewer rebuilds from its orbit, which can differ from
# headless's in the last bits, enough to show or not a sliver); isolated, exactly the parts
# of the box (all of them were visible in it); and after Shift+H the first count again.
counts=$(sed -n 's/^idview: visible parts: //p' "$work/parts.out")
first_seen=$(echo "$counts" | sed -n '/^[1-9]/{p;q}')
[[ $first_seen == "$visible_all" ]] && echo "ok   visible parts: $first_seen" ||
    fail "visible parts: viewer '$first_seen', headless '$visible_all'"
while_hidden=$(awk '/^idview: hidden: [1-9]/{on=1} on && /^idview: hidden: 0 parts/{exit} on' \
    "$work/parts.out" | sed -n 's/^idview: visible parts: //p' | tail -1)
[[ -n $while_hidden && $while_hidden != "$visible_all" ]] &&
    echo "ok   visible parts with $(count "$after_add") hidden: $while_hidden (headless: $visible_hidden)" ||
    fail "hiding parts did not change the visible count ($while_hidden)"
isolated=$(awk '/^idview: hidden: [1-9]/{n++} n==2{on=1} on && /^idview: hidden: 0 parts/{exit} on' \
    "$work/parts.out" | sed -n 's/^idview: visible parts: //p' | tail -1)
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
    at quit
} >"$work/tree.txt"
xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --no-saved-settings \
    --validation --size 720x450 \
    --scene procedural:preset=small --script "$work/tree.txt" --print-events \
    >"$work/tree.out" 2>"$work/tree.err"
rc=$?
[[ $rc -eq 0 ]] || { fail "tree session: exit code $rc"; head -c 3000 "$work/tree.err"; }
tree_events=$(grep -E '^idview: (selected|hidden):' "$work/tree.out" | tr '\n' '|')
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
want="idview: hidden: $gearbox parts|idview: hidden: 0 parts|idview: selected: $plate parts|"
want+="idview: selected: $both parts|idview: selected: none|idview: selected: $object0 parts|"
want+="idview: selected: $gearbox parts|idview: selected: $object0 parts|"
if [[ $gearbox -gt $plate && $plate -gt $object0 && $object0 -gt 1 && $tree_events == "$want" ]]; then
    echo "ok   assembly tree and selection levels: hide, show, select and add nodes; solid, assembly, double-click ($gearbox, $plate, $object0 parts)"
else
    fail "assembly tree events '$tree_events', expected '$want'"
fi

# Loads that must not take the scene: a drop past --max-triangles fails in one line and the
# scene stays (a click picks the very part it picked before); Cancel stops a slow CAD load
# (terrain.brep meshes for half a minute in one face) within seconds, and the scene stays.
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
    start=$(date +%s)
    xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --no-saved-settings \
        --validation --size 720x450 \
        --scene procedural:preset=small --max-triangles 1000 --no-cache \
        --script "$work/refuse.txt" --print-events >"$work/refuse.out" 2>"$work/refuse.err"
    rc=$?
    took=$(($(date +%s) - start))
    [[ $rc -eq 0 ]] || { fail "refused loads: exit code $rc"; head -c 2000 "$work/refuse.err"; }
    grep -q "^idview: $motor: the tessellation passes --max-triangles 1000 (about [0-9]* triangles at deflection [0-9.e+-]*); try --deflection [0-9.e+-]*$" \
        "$work/refuse.err" && echo "ok   a drop past --max-triangles is refused in one line" ||
        fail "no one-line refusal of $motor: $(head -c 500 "$work/refuse.err")"
    grep -q "^idview: $terrain: cancelled$" "$work/refuse.err" && echo "ok   Cancel stopped $terrain" ||
        fail "Cancel did not stop $terrain: $(head -c 500 "$work/refuse.err")"
    grep -q "^idview: opened: " "$work/refuse.out" && fail "a refused or cancelled model opened"
    picks=$(grep '^idview: selected: part' "$work/refuse.out")
    if [[ $(wc -l <<<"$picks") -eq 2 && $(sort -u <<<"$picks" | wc -l) -eq 1 ]]; then
        echo "ok   the scene stayed: $(head -1 <<<"$picks")"
    else
        fail "the two clicks picked: $picks"
    fi
    ((took < 25)) && echo "ok   refused and cancelled in $took s" ||
        fail "the refused and cancelled loads took $took s"
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
xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --no-saved-settings \
    --validation --size 720x450 \
    --scene procedural:preset=small --script "$work/views.txt" --print-events \
    >"$work/views.out" 2>"$work/views.err"
rc=$?
[[ $rc -eq 0 ]] || { fail "views session: exit code $rc"; head -c 3000 "$work/views.err"; }
said=$(grep -E '^idview: (view|projection|fit):' "$work/views.out" | sed 's/^idview: //' | paste -sd'|' -)
expected='view: front|view: bottom|view: isometric|projection: orthographic|view: top|projection: perspective|view: front|fit: selection|fit: shown parts|fit: scene'
[[ $said == "$expected" ]] && echo "ok   views session: $said" || fail "views session said '$said', expected '$expected'"
# F on the base plate frames it (another set of parts shows); F with the plate isolated frames
# it alone; F with nothing selected or hidden frames the whole scene beside the panel.
visible_after() { # the last visible part count after the event line $1, before the next event
    awk -v e="idview: $1" '$0 == e {on=1; next} on && /^idview: (view|projection|fit|selected):/{exit} on' \
        "$work/views.out" | sed -n 's/^idview: visible parts: //p' | tail -1
}
front=$(visible_after "view: front")
on_plate=$(visible_after "fit: selection")
whole=$(visible_after "fit: scene")
[[ -n $front && -n $on_plate && $on_plate != "$front" && -n $whole && $whole != "$on_plate" ]] &&
    echo "ok   F: selection shows $on_plate parts, then the scene $whole (front view: $front)" ||
    fail "F: selection '$on_plate', scene '$whole', front view '$front'"
top_viewer=$(awk '/^idview: view: top/{on=1} on && /^idview: projection: perspective/{exit} on' \
    "$work/views.out" | sed -n 's/^idview: visible parts: //p' | tail -1)
top_headless=$("$idview" --headless --size 720x450 --scene procedural:preset=small --frames 1 \
    --view top --ortho --visible-parts 2>/dev/null | sed -n 's/^{"count":\([0-9]*\).*/\1/p')
iso_count=$(awk '/^idview: view: isometric/{on=1} on && /^idview: projection: orthographic/{exit} on' \
    "$work/views.out" | sed -n 's/^idview: visible parts: //p' | tail -1)
[[ -n $top_viewer && $top_viewer == "$top_headless" && $top_viewer != "$iso_count" ]] &&
    echo "ok   top view in ortho shows $top_viewer parts, as headless (isometric: $iso_count)" ||
    fail "top view in ortho: viewer '$top_viewer' parts, headless '$top_headless' (isometric '$iso_count')"

session() { # session NAME: the small scene driven by $work/NAME.txt, out in NAME.out and .err
    xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --validation --size 720x450 \
        --scene procedural:preset=small --script "$work/$1.txt" --print-events \
        >"$work/$1.out" 2>"$work/$1.err"
    local rc=$?
    [[ $rc -eq 0 ]] || { fail "$1 session: exit code $rc"; head -c 2000 "$work/$1.err"; }
}
# The open field as a newcomer types into it: Ctrl+O, a path, Enter pressed and released
# between two frames (a script's key always is), the model opens; the field is then empty,
# so the next path typed opens as it is, not joined to the last one.
cp "$work/small.glb" "$work/again.glb"
t=0.5
{
    at key ctrl+O
    at frames 3
    at type "$work/small.glb"
    at key ENTER
    at loaded
    at frames 3
    at key ctrl+O
    at frames 3
    at type "$work/again.glb"
    at key ENTER
    at loaded
    at frames 3
    at screenshot "$work/typed.png"
    at quit
} >"$work/typed.txt"
session typed
opened=$(sed -n 's/^idview: opened: \([^ ]*\) .*/\1/p' "$work/typed.out" | paste -sd' ' -)
[[ $opened == "$work/small.glb $work/again.glb" ]] && echo "ok   typed paths opened: Enter kept, field emptied" ||
    fail "typed paths opened '$opened' ($(head -c 300 "$work/typed.err"))"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer test passed"
