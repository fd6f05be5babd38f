#!/usr/bin/env bash
# viewer_desktop_test.sh IDVIEW LAVAPIPE_ICD - what a desktop viewer is expected to do, under
# Xvfb on lavapipe with validation: a model opens fitted in the area beside the panel; the
# wheel zooms toward the surface point under the cursor (the part under it before is the part
# under it after, the point on the same pixel); Open... (Ctrl+O) asks a file chooser, here a
# fake zenity on PATH with no D-Bus session (so no portal), and opens what it chose; with
# neither, it says so in one line and opens the panel's own file browser, driven by the keys
# to a model that opens (the title names it), after which the keys are the viewer's again.
# Exit 77: skipped (viewer_lib.sh).
source "$(dirname "$0")/viewer_lib.sh"

# --- Fitted beside the panel, and the zoom toward the cursor --------------------------------
# 432,232 lies on the left bracket, far from the orbit target: a zoom toward the target moves
# what is under it by over a hundred pixels (under the panel).
t=0.5
{
    at click 432 232
    at frames 6 # the click's pick comes back a frame or two later, however slow frames are
    at key ESC
    at scroll 4
    at frames 6
    at rest 0.5 # a click right after the first would be a double-click (the object)
    at click 432 232
    at frames 6
    at quit
} >"$work/zoom.txt"
session zoom
fitted=$(sed -n 's/^idview: opened fitted: x \(-*[0-9]*\) to \(-*[0-9]*\), free \([0-9]*\) to \([0-9]*\) of .*/\1 \2 \3 \4/p' \
    "$work/zoom.out")
read -r left right free_left free_right <<<"$fitted"
[[ -n $fitted ]] && ((left >= free_left - 1 && right <= free_right + 1 && free_left > 300)) &&
    echo "ok   opened fitted beside the panel: x $left to $right in $free_left to $free_right" ||
    fail "the model opened outside the area beside the panel: '$fitted'"
picked=$(sed -n 's/^idview: selected: part \([0-9]*\) .*/\1/p' "$work/zoom.out" | paste -sd' ' -)
zoom=$(grep -m1 '^idview: zoom: ' "$work/zoom.out")
read -r before after <<<"$picked"
at_now=$(sed -n 's/^idview: zoom: toward part [0-9]* at 432,232, now at \([0-9.]*\),\([0-9.]*\)$/\1 \2/p' \
    "$work/zoom.out")
[[ -n $before && $before == "$after" && $zoom == "idview: zoom: toward part $before at 432,232, now at "* ]] &&
    awk -v p="$at_now" 'BEGIN{split(p, a, " "); exit !(p != "" && (a[1]-432)^2 + (a[2]-232)^2 <= 1)}' &&
    echo "ok   the wheel zoomed toward part $before under the cursor, which stays under it: $zoom" ||
    fail "zoom toward the cursor: parts picked '$picked', '$zoom'"

# --- Open... through zenity, then with no chooser at all --------------------------------------
"$idview" --scene procedural:preset=small --export "$work/chosen model.glb" >/dev/null ||
    fail "exporting the model the chooser picks"
mkdir -p "$work/bin" "$work/nothing"
# The fake zenity notes its arguments and answers as zenity does: the path and exit code 0.
cat >"$work/bin/zenity" <<FAKE
#!/bin/sh
printf '%s\n' "\$@" >"$work/zenity-args.txt"
echo "$work/chosen model.glb"
FAKE
chmod +x "$work/bin/zenity"
# No portal: a session bus address where none listens, so GLib never starts one either.
export DBUS_SESSION_BUS_ADDRESS=unix:path=$work/no-bus
t=0.5
{
    at key ctrl+O
    at loaded # the chooser's answer, then the model it chose
    at frames 2
    at quit
} >"$work/chooser.txt"
PATH=$work/bin:$PATH session chooser
grep -qx "idview: file chooser: $work/chosen model.glb (zenity)" "$work/chooser.out" &&
    grep -q "^idview: opened: $work/chosen model.glb" "$work/chooser.out" &&
    echo "ok   Ctrl+O: zenity chose a model, which opened" ||
    fail "Open... through zenity: $(grep -e chooser -e opened "$work/chooser.out" | head -5)"
grep -qx -- "--file-filter=Models | \*.gltf \*.GLTF \*.glb \*.GLB \*.step .*\*.brep \*.BREP \*.stl \*.STL" \
    "$work/zenity-args.txt" && grep -qx -- "--file-filter=All files | \*" "$work/zenity-args.txt" &&
    echo "ok   zenity was given the formats idview reads, and All files" ||
    fail "zenity's arguments: $(head -c 600 "$work/zenity-args.txt" 2>/dev/null)"
# Neither: the viewer runs with a PATH that holds no zenity (it runs no other program) and
# its home in the test's folder, and settings of its own (no recent files: it opens at home);
# xvfb-run itself keeps the test's PATH. Ctrl+O then opens the
# panel's own file browser there, which the keys drive: a filter typed, Enter into a folder,
# Enter on the model it highlights, which opens (the title names it); the keys are the
# viewer's again after it (M: measure), and Esc closes the browser opened again.
mkdir -p "$work/home/models" "$work/home/empty"
cp /usr/share/assimp/models/STL/triangle_with_two_solids.stl "$work/home/models/small.stl"
echo "not a model" >"$work/home/notes.txt"
printf '#!/bin/sh\nHOME=%s XDG_CONFIG_HOME=%s PATH=%s exec %s "$@"\n' "$work/home" \
    "$work/home/.config" "$work/nothing" "$idview" >"$work/idview-no-zenity"
chmod +x "$work/idview-no-zenity"
t=0.5
{
    at key ctrl+O
    at loaded
    at frames 3
    at type mod
    at frames 2
    at key ENTER
    at frames 2
    at key ENTER
    at loaded
    at frames 3
    at key M
    at frames 2
    at key ctrl+O
    at loaded
    at frames 3
    at key ESC
    at frames 2
    at key M
    at frames 2
    at quit
} >"$work/none.txt"
idview=$work/idview-no-zenity session none
out=$work/none.out
has_line() { grep -qxF "idview: $1" "$out"; }
# in_order LINE...: each line comes after the one before it.
in_order() {
    local from=0 at
    for line in "$@"; do
        at=$(tail -n +$((from + 1)) "$out" | grep -nxF -m1 "idview: $line" | cut -d: -f1)
        [[ -n $at ]] || return 1
        from=$((from + at))
    done
}
[[ $(grep -c "^idview: no desktop file chooser: neither the desktop portal nor zenity is there (zenity is not on PATH); browsing in the panel$" \
    "$work/none.err") -eq 1 && $(grep -c "^idview: file chooser: open$" "$out") -eq 1 ]] &&
    [[ $(grep -c "^idview: file chooser: none$" "$out") -eq 2 ]] &&
    echo "ok   no chooser: one line says so, the panel's browser opens, the second Ctrl+O goes to it at once" ||
    fail "no chooser: $(grep chooser "$out" "$work/none.err" | head -3)"
home=$work/home models=$work/home/models
in_order "file browser: $home: 3 of 3 entries: ../, empty/, models/; highlighted empty" &&
    in_order "file browser: $home: 1 of 3 entries: models/; highlighted models" \
        "file browser: $models: 2 of 2 entries: ../, small.stl; highlighted small.stl" \
        "file browser: chose $models/small.stl" &&
    grep -q "^idview: opened: $models/small.stl " "$out" &&
    echo "ok   the browser: home listed (folders and models only), filtered, a folder entered, its model opened" ||
    fail "the browser: $(grep -e 'file browser' -e opened "$out" | head -6 | paste -sd'|')"
grep -q "^idview: title: small.stl - idview - " "$out" &&
    echo "ok   the title names the open file" ||
    fail "title: $(grep '^idview: title:' "$out" | tail -1)"
in_order "file browser: chose $models/small.stl" "measure: on" \
    "file browser: $models: 2 of 2 entries: ../, small.stl; highlighted small.stl" \
    "file browser: closed" "measure: off" &&
    ! grep -q "^idview: file browser: .*: [0-9]* of [0-9]* entries: .*; highlighted .*M" "$out" &&
    echo "ok   after the browser the keys are the viewer's (M twice); Esc closed it opened again" ||
    fail "keys after the browser: $(grep -e 'file browser' -e measure "$out" | paste -sd'|')"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer desktop test passed"
