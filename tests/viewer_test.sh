#!/usr/bin/env bash
# viewer_test.sh IDVIEW LAVAPIPE_ICD - the real window, as a user drives it: idview under Xvfb
# on lavapipe with validation (synchronization validation too), fed a --script that switches
# through every renderer (the floors included) and mode, changes MSAA, presses V twice,
# orbits, zooms, resizes, clicks the model, takes a screenshot and drops files on the window
# (CAD files too), measures, and cuts a section. Selections, the tree, views and typed paths:
# viewer_parts_test.sh.
# Checks the exit code (3 means validation messages), the title following the renderer and
# vsync, the click selecting a part, the drops, and that the screenshot shows a picture; and
# that without --print-events the viewer writes nothing to stdout. Without Xvfb it fails (viewer_lib.sh).
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
        at pipeline ready # built on a worker: drawn (and in the title) once it is done
        for m in $modes; do at mode "$m"; done
    done
    at renderer "${renderers%%[[:space:]]*}" # the first listed, and the first mode
    at mode "${modes%%[[:space:]]*}"
    at msaa 4
    at msaa 1
    # Headless's opening view: the panel hidden and F, which fits the scene in the whole window
    # (a model opens fitted beside the panel).
    at key F9
    at key F
    at key M # measure mode: two clicks measure instead of selecting
    at click 470 260
    at frames 6
    at click 520 280
    at frames 6
    at key M
    at key F9
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
    at pipeline ready   # its pipeline variant, built on a worker
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
vsync=$(events "$work/out.txt" title .text | sed -n 's/.* - vsync \(on\|off\).*/\1/p' | uniq |
    tr '\n' ' ')
if [[ $vsync == *"on off on"* ]]; then
    echo "ok   title follows vsync: $vsync"
else
    fail "title should go vsync on, off, on; it went: $vsync"
    head -20 "$work/out.txt"
fi
for r in $renderers; do
    said "$work/out.txt" title ".text | contains(\"idview - $r + \")" || fail "title never named renderer $r"
done
first=$(events "$work/out.txt" title .text | head -1)
[[ $first == *"idview - $floor + "* ]] || fail "--renderer $floor opened as: $first"

said "$work/out.txt" shaders_reloaded || fail "R did not reload the shaders"
grep -q '^idview: 1000000 copies make .* objects' "$work/err.txt" ||
    fail "1000000 copies were not refused in words"

# The click on the model selected a part; Esc cleared it (and so did not close the window).
if said "$work/out.txt" selected '.part != null'; then
    echo "ok   click selected: $(events "$work/out.txt" selected 'select(.part != null)' | head -1)"
else
    fail "the click selected no part"
fi
said "$work/out.txt" selected '.parts == 0' || fail "Esc did not clear the selection"

# A broken drop names the file and keeps the scene; a good one opens.
grep -q "^idview: .*broken.glb" "$work/err.txt" || fail "the broken drop reported nothing"
if said "$work/out.txt" opened '.path | endswith("small.glb")'; then
    echo "ok   dropped model opened"
else
    fail "the dropped model did not open"
fi
# Each CAD file opened in the window with the counts headless --stats gives.
for f in "${cad_files[@]}"; do
    stats=$("$idview" --model "$f" --stats 2>/dev/null)
    objects=$(sed -n 's/.*"objects":\([0-9]*\).*/\1/p' <<<"$stats")
    parts=$(sed -n 's/.*"parts":\([0-9]*\).*/\1/p' <<<"$stats")
    if [[ -n $objects ]] && said "$work/out.txt" opened ".path == \"$f\" and .objects == $objects and .parts == $parts"; then
        echo "ok   dropped $(basename "$f") opened: $objects objects, $parts parts"
    else
        fail "the dropped $f did not open with $objects objects and $parts parts"
    fi
done

# Measure mode: the second click's line holds both points, as headless --measure finds them
# in its opening view (F with the panel hidden frames the scene as it does, to float rounding).
measured=$(events "$work/out.txt" measure 'select(.measured) | .measured' | tail -1)
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
# The records from each "measure on" to the next "measure off" (the toggles, not the results).
jq -es '[foreach .[] as $r (false; if $r.event == "measure" and ($r | has("measured") | not)
    then $r.on else . end; . and $r.event == "selected" and $r.part != null)] | any' \
    "$work/out.txt" >/dev/null &&
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

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer test passed"
