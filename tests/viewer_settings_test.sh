#!/usr/bin/env bash
# viewer_settings_test.sh IDVIEW LAVAPIPE_ICD - the viewer's settings kept between runs, as a
# user meets them: two runs under Xvfb on lavapipe with validation, the second opening on
# what the first closed with (viewer.conf under XDG_CONFIG_HOME, a folder of the test's own),
# a bad line costing one warning, Reset to defaults (the script's `defaults`) going back to
# vertex-fs + mdi-baseinstance and emptying the file; flags only headless runs read named
# in one line and ignored; and the window's size and place, the panel and the recent files
# restored by runs without --size, a place off the screen pulled onto it, the recent files'
# clear list emptying them. Without Xvfb it fails (viewer_lib.sh).
source "$(dirname "$0")/viewer_lib.sh"

conf=$XDG_CONFIG_HOME/idview/viewer.conf
t=0.5
{
    at sort off
    at msaa 4
    at frames 3
    at quit
} >"$work/kept1.txt"
session kept1 --renderer tri-fs --pick 1,1 --screenshot "$work/never.png"
grep -qx "idview: --screenshot, --pick: only read with --headless; ignored" "$work/kept1.err" &&
    [[ ! -e $work/never.png ]] && echo "ok   headless-only flags named and ignored" ||
    fail "headless-only flags: $(head -c 500 "$work/kept1.err")"
# The window's own lines (geometry, panel, recent files) are checked further down.
settings_only() { grep -v -e '^#' -e '^--size ' -e '^--window-pos ' -e '^viewer\.' "$conf"; }
kept=$(settings_only 2>/dev/null | sort | paste -sd' ' -)
[[ $kept == "--msaa 4 --no-sort-draws --renderer tri-fs" ]] && echo "ok   kept: $kept" ||
    fail "viewer.conf holds '$kept', expected --msaa 4 --no-sort-draws --renderer tri-fs"
echo "--bogus" >>"$conf"
t=0.5
{
    at frames 3
    at defaults
    at pipeline ready # the default renderer's pipeline, built on a worker
    at frames 3
    at quit
} >"$work/kept2.txt"
session kept2
titles=$(events "$work/kept2.out" title .text |
    sed -n 's/.*idview - \([^ ]* + [^ ]*\) - .*/\1/p' | uniq | paste -sd'|' -)
[[ $titles == "tri-fs + mdi-baseinstance|vertex-fs + mdi-baseinstance" ]] &&
    echo "ok   opened on the kept renderer, then the defaults: $titles" ||
    fail "second run's titles: '$titles'"
[[ $(grep -c "viewer.conf:[0-9]*: '--bogus' is not a setting the viewer keeps; ignored" \
    "$work/kept2.err") -eq 1 ]] && echo "ok   a bad line costs one warning" ||
    fail "bad line: $(head -c 500 "$work/kept2.err")"
settings_only | grep -q '^--' &&
    fail "after Reset to defaults viewer.conf still holds: $(cat "$conf")" ||
    echo "ok   Reset to defaults emptied viewer.conf of settings"

# The window: its size and place, the panel and the recent files come back; a place off the
# screen (another monitor, gone) is pulled onto it; the recent files' clear list empties it.
"$idview" --scene procedural:preset=small --export "$work/recent.glb" >/dev/null ||
    fail "exporting the model for the recent files"
t=0.5
{
    at resize 800 500
    at key F9 # the panel hidden
    at drop "$work/recent.glb"
    at loaded
    at frames 2
    at quit
} >"$work/window1.txt"
session window1 --window-pos 60,40
# Then runs without --size, as a person starts the viewer; the window line comes first.
session_sized() {
    local name=$1
    shift
    xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --validation \
        --scene procedural:preset=small --script "$work/$name.txt" --print-events "$@" \
        >"$work/$name.out" 2>"$work/$name.err" || fail "$name session: $(head -c 2000 "$work/$name.err")"
}
t=0.5
{
    at frames 2
    at quit
} >"$work/window2.txt"
session_sized window2
window=$(events "$work/window2.out" window '"\(.width)x\(.height) at \(.x),\(.y), \(.recent_files) recent files"' | head -1)
[[ $window == "800x500 at 60,40, 1 recent files" ]] &&
    echo "ok   size, place and recent files restored: $window" ||
    fail "second run's window: '$window', viewer.conf: $(cat "$conf")"
grep -qx "viewer.panel = hidden" "$conf" && grep -qx "viewer.recent = $work/recent.glb" "$conf" &&
    echo "ok   the panel stays hidden and the recent file kept through a restart" ||
    fail "viewer.conf after the restart: $(cat "$conf")"
t=0.5
{
    at clear-recent
    at frames 2
    at quit
} >"$work/window3.txt"
session_sized window3 --window-pos 5000,5000
window=$(events "$work/window3.out" window '"\(.width)x\(.height) at \(.x),\(.y), \(.recent_files) recent files"' | head -1)
[[ $window == "800x500 at 480,300, 1 recent files" ]] &&
    echo "ok   a place off the screen pulled onto it: $window" ||
    fail "off-screen place: '$window'"
grep -q '^viewer.recent' "$conf" && fail "clear list left: $(grep '^viewer.recent' "$conf")" ||
    echo "ok   clear list emptied the recent files"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer settings test passed"
