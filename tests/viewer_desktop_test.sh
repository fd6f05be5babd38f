#!/usr/bin/env bash
# viewer_desktop_test.sh IDVIEW LAVAPIPE_ICD - what a desktop viewer is expected to do, under
# Xvfb on lavapipe with validation: a model opens fitted in the area beside the panel; the
# wheel zooms toward the surface point under the cursor (the part under it before is the part
# under it after, the point on the same pixel); Open... (Ctrl+O) asks a file chooser, here a
# fake zenity on PATH with no D-Bus session (so no portal), and opens what it chose; with
# neither, it says so in one line and opens the panel's own file browser, driven by the keys
# to a model that opens (the title names it), after which the keys are the viewer's again.
# Without Xvfb it fails (viewer_lib.sh).
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
fitted=$(events "$work/zoom.out" opened_fitted '"\(.left) \(.right) \(.free_left) \(.free_right)"')
read -r left right free_left free_right <<<"$fitted"
[[ -n $fitted ]] && ((left >= free_left - 1 && right <= free_right + 1 && free_left > 300)) &&
    echo "ok   opened fitted beside the panel: x $left to $right in $free_left to $free_right" ||
    fail "the model opened outside the area beside the panel: '$fitted'"
picked=$(events "$work/zoom.out" selected 'select(.part != null) | .part' | paste -sd' ' -)
zoom=$(events "$work/zoom.out" zoom | head -1)
read -r before after <<<"$picked"
at_now=$(events "$work/zoom.out" zoom 'select(.pixel == [432, 232]) | .now_at | map(tostring) | join(" ")')
[[ -n $before && $before == "$after" && -n $zoom ]] &&
    jq -e ".part == $before and .pixel == [432, 232] and (.now_at | length) == 2" <<<"$zoom" >/dev/null &&
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
chosen=$work/chosen\ model.glb
said "$work/chooser.out" file_chooser ".state == \"chosen\" and .path == \"$chosen\" and .via == \"zenity\"" &&
    said "$work/chooser.out" opened ".path == \"$chosen\"" &&
    echo "ok   Ctrl+O: zenity chose a model, which opened" ||
    fail "Open... through zenity: $(jq -c 'select(.event | IN("file_chooser", "opened"))' "$work/chooser.out" | head -5)"
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
# in_order CONDITION...: a record each jq condition holds for, each after the one before.
in_order() {
    local from=0 at
    for condition in "$@"; do
        at=$(event_lines "$out" "$condition" | awk -v f="$from" '$1 > f {print; exit}')
        [[ -n $at ]] || return 1
        from=$at
    done
}
# listing FOLDER SHOWN OF ENTRIES HIGHLIGHTED: the browser's record of a listing (ENTRIES a
# JSON array of names).
listing() {
    echo ".event == \"file_browser\" and .state == \"listing\" and .folder == \"$1\" and .shown == $2 and
        .of == $3 and .entries == $4 and .highlighted == \"$5\""
}
browser() { echo ".event == \"file_browser\" and .state == \"$1\"${2:+ and .path == \"$2\"}"; }
chooser() { events "$out" file_chooser "select(.state == \"$1\")" | wc -l; }
[[ $(grep -c "^idview: no desktop file chooser: neither the desktop portal nor zenity is there (zenity is not on PATH); browsing in the panel$" \
    "$work/none.err") -eq 1 && $(chooser open) -eq 1 ]] && [[ $(chooser none) -eq 2 ]] &&
    echo "ok   no chooser: one line says so, the panel's browser opens, the second Ctrl+O goes to it at once" ||
    fail "no chooser: $(events "$out" file_chooser | head -3) $(grep chooser "$work/none.err" | head -3)"
home=$work/home models=$work/home/models
models_listed=$(listing "$models" 2 2 '["../", "small.stl"]' small.stl)
in_order "$(listing "$home" 3 3 '["../", "empty/", "models/"]' empty)" &&
    in_order "$(listing "$home" 1 3 '["models/"]' models)" "$models_listed" \
        "$(browser chose "$models/small.stl")" &&
    said "$out" opened ".path == \"$models/small.stl\"" &&
    echo "ok   the browser: home listed (folders and models only), filtered, a folder entered, its model opened" ||
    fail "the browser: $(jq -c 'select(.event | IN("file_browser", "opened"))' "$out" | head -6 | paste -sd'|')"
said "$out" title '.text | startswith("small.stl - idview - ")' &&
    echo "ok   the title names the open file" ||
    fail "title: $(events "$out" title .text | tail -1)"
in_order "$(browser chose "$models/small.stl")" '.event == "measure" and .on and (has("measured") | not)' "$models_listed" \
    "$(browser closed)" '.event == "measure" and .on == false' &&
    ! said "$out" file_browser '.state == "listing" and (.highlighted // "" | contains("M"))' &&
    echo "ok   after the browser the keys are the viewer's (M twice); Esc closed it opened again" ||
    fail "keys after the browser: $(jq -c 'select(.event | IN("file_browser", "measure"))' "$out" | paste -sd'|')"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer desktop test passed"
