#!/usr/bin/env bash
# viewer_desktop_test.sh IDVIEW LAVAPIPE_ICD - what a desktop viewer is expected to do, under
# Xvfb on lavapipe with validation: a model opens fitted in the area beside the panel; the
# wheel zooms toward the surface point under the cursor (the part under it before is the part
# under it after, the point on the same pixel); Open... (Ctrl+O) asks a file chooser, here a
# fake zenity on PATH with no D-Bus session (so no portal), and opens what it chose; with
# neither, it says so and points to the open field. Exit 77: skipped (viewer_lib.sh).
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
# Neither: the viewer runs with a PATH that holds no zenity (it runs no other program);
# xvfb-run itself keeps the test's PATH.
printf '#!/bin/sh\nPATH=%s exec %s "$@"\n' "$work/nothing" "$idview" >"$work/idview-no-zenity"
chmod +x "$work/idview-no-zenity"
t=0.5
{
    at key ctrl+O
    at loaded
    at frames 2
    at quit
} >"$work/none.txt"
idview=$work/idview-no-zenity session none
grep -qx "idview: file chooser: none" "$work/none.out" &&
    [[ $(grep -c "^idview: no file chooser: neither the desktop portal nor zenity is there (zenity is not on PATH); type the model's path here$" \
        "$work/none.err") -eq 1 ]] &&
    echo "ok   no chooser: one line says so and points to the open field" ||
    fail "no chooser: $(grep chooser "$work/none.out" "$work/none.err" | head -3)"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer desktop test passed"
