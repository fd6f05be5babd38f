#!/usr/bin/env bash
# viewer_settings_test.sh IDVIEW LAVAPIPE_ICD - the viewer's settings kept between runs, as a
# user meets them: two runs under Xvfb on lavapipe with validation, the second opening on
# what the first closed with (viewer.conf under XDG_CONFIG_HOME, a folder of the test's own),
# a bad line costing one warning, Reset to defaults (the script's `defaults`) going back to
# vertex-fs + mdi-baseinstance and emptying the file; and flags only headless runs read named
# in one line and ignored. Exit 77: skipped (viewer_lib.sh).
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
kept=$(grep -v '^#' "$conf" 2>/dev/null | sort | paste -sd' ' -)
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
titles=$(sed -n 's/^idview: title: idview - \([^ ]* + [^ ]*\) - .*/\1/p' "$work/kept2.out" | uniq |
    paste -sd'|' -)
[[ $titles == "tri-fs + mdi-baseinstance|vertex-fs + mdi-baseinstance" ]] &&
    echo "ok   opened on the kept renderer, then the defaults: $titles" ||
    fail "second run's titles: '$titles'"
[[ $(grep -c "viewer.conf:[0-9]*: '--bogus' is not a setting the viewer keeps; ignored" \
    "$work/kept2.err") -eq 1 ]] && echo "ok   a bad line costs one warning" ||
    fail "bad line: $(head -c 500 "$work/kept2.err")"
grep -q '^--' "$conf" && fail "after Reset to defaults viewer.conf still holds: $(cat "$conf")" ||
    echo "ok   Reset to defaults emptied viewer.conf"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer settings test passed"
