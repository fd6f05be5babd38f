#!/usr/bin/env bash
# viewer_commands_test.sh IDVIEW LAVAPIPE_ICD - the viewer's command table under Xvfb on
# lavapipe with validation, as a user presses its keys (issue 34) and as keys, panel and script
# ask for one command (issue 38): the help overlay (F1, ?),
# Esc cancelling one thing at a time and never quitting, Ctrl+Q quitting with exit code 0, keys
# typed into the open field reaching no command, a new model starting clean while new copies
# keep the section, the empty view saying why, undo and redo of hidden parts and section,
# F12's screenshot in the Pictures folder, and (with xdotool's real input) Esc during a box drag. Without Xvfb it fails (viewer_lib.sh). The lavapipe environment, the
# Xvfb check, $work, fail, at and session: viewer_lib.sh.
source "$(dirname "$0")/viewer_lib.sh"

ok() { echo "ok   $*"; }
# has NAME CONDITION: a record of the session's for which the jq CONDITION holds.
has() { jq -en "[inputs | select($2)] | length > 0" "$work/$1.out" >/dev/null; }
# count NAME CONDITION: how many of the session's records CONDITION holds for.
count() { jq -c "select($2)" "$work/$1.out" | wc -l; }
# after NAME FIRST LATER: a record LATER holds for comes after the first one FIRST holds for.
after() {
    local first
    first=$(event_lines "$work/$1.out" "$2" | head -1)
    [[ -n $first ]] && event_lines "$work/$1.out" "$3" | awk -v f="$first" '$1 > f {n = 1} END {exit !n}'
}
# The conditions the checks name: the measure mode's toggles (not a measurement's record), a
# screenshot of the window at PATH.
measure_on='.event == "measure" and .on and (has("measured") | not)'
measure_off='.event == "measure" and .on == false'
shot() { echo ".event == \"screenshot\" and .path == \"$1\" and .width == 720 and .height == 450"; }

# Esc and the help. Esc closes the help, then turns measure mode off, then clears the
# selection, then does nothing; the viewer runs on (a screenshot after, the M after it).
# Keys while the open field has the keyboard are the field's: M measures nothing, and Esc
# leaves the field, so the next M does. Ctrl+Q quits: the screenshot after it never comes.
t=0.5
{
    at key F1
    at frames 2
    at key shift+/
    at frames 2
    at key shift+/
    at frames 2
    at key ESC
    at object base plate
    at key M
    at key ESC
    at key ESC
    at key ESC
    at frames 3
    at screenshot "$work/running.png"
    at key ctrl+O
    at loaded # the chooser's answer (none here: the open field), however long it takes
    at frames 3
    at key M
    at key ESC
    at frames 3
    at key M
    at frames 2
    at key F9
    at frames 2
    at key F9
    at key ctrl+Q
    at frames 10
    at screenshot "$work/after-quit.png"
    at quit
} >"$work/esc.txt"
session esc --no-saved-settings
bindings=$(events "$work/esc.out" help 'select(.open) | .bindings' | sort -u)
[[ $bindings -gt 40 && $(count esc '.event == "help" and .open and (.bindings | type == "number")') -eq 2 &&
    $(count esc '.event == "help" and .open == false') -eq 2 ]] &&
    ok "F1 and ? open the help ($bindings bindings) and close it" ||
    fail "help: '$(events "$work/esc.out" help | paste -sd'|')'"
cancels=$(events "$work/esc.out" cancel .what | paste -sd' ')
[[ $cancels == "help measure selection" ]] && ok "Esc cancelled the help, measure, the selection" ||
    fail "Esc cancelled '$cancels', expected 'help measure selection'"
after esc "$measure_on" "$measure_off" &&
    after esc '.event == "cancel" and .what == "measure"' '.event == "selected" and .parts == 0' &&
    ok "measure went off, then the selection cleared" || fail "measure off / selection cleared"
[[ -s $work/running.png ]] && has esc "$(shot "$work/running.png")" &&
    ok "the viewer runs on after three Esc" || fail "no frame after Esc"
[[ $(count esc "$measure_on") -eq 2 ]] && after esc "$(shot "$work/running.png")" "$measure_on" &&
    ok "M typed into the open field measured nothing; after Esc left the field, M did" ||
    fail "measure records after the open field: $(count esc "$measure_on") 'on' in all"
[[ $(events "$work/esc.out" panel 'if .shown then "shown" else "hidden" end' | paste -sd' ') == "hidden shown" ]] &&
    ok "F9 hid the panel and showed it (F1 did not)" ||
    fail "panel records '$(events "$work/esc.out" panel | paste -sd'|')', expected hidden, shown"
[[ ! -e $work/after-quit.png ]] && ok "Ctrl+Q quit (exit code 0)" || fail "Ctrl+Q did not quit"

# A new model starts clean: planes that cut everything away explain the empty view, stay
# with new copies (the same model, the same world space) and are gone on the next model,
# whose parts show; its undo history is empty.
"$idview" --scene procedural:preset=small --export "$work/small.glb" >/dev/null ||
    fail "could not export the small scene"
t=0.5
{
    at section x,-1000
    at frames 8
    at copies 2
    at frames 8
    at key ctrl+Z
    at frames 2
    at screenshot "$work/cut.png"
    at drop "$work/small.glb"
    at loaded
    at frames 8
    at key ctrl+Z
    at frames 2
    at quit
} >"$work/clean.txt"
session clean --no-saved-settings
empties=$(events "$work/clean.out" empty '.reason // "no"' | paste -sd' ')
[[ $empties == "section no" ]] && ok "the empty view said why: section, and no more on the next model" ||
    fail "empty records '$empties', expected 'section no'"
# Copies renumber the parts: a history of hidden sets would name other parts, so it is gone
# (Ctrl+Z has nothing to undo), and the section stays.
section_off='.event == "section" and .on == false'
nothing_to_undo='.event == "undo" and .done == false'
cut=$(event_lines "$work/clean.out" "$(shot "$work/cut.png")")
off=$(event_lines "$work/clean.out" "$section_off" | paste -sd' ')
[[ -n $cut && $off =~ ^[0-9]+$ && $off -gt $cut ]] &&
    after clean '.event == "empty" and .reason == "section"' "$nothing_to_undo" &&
    ! has clean '.event == "undo" and .done' &&
    ok "new copies kept the section and started a new history" ||
    fail "copies: section off at line(s) '$off', the copies' screenshot at '$cut'"
[[ $off =~ ^[0-9]+$ && $off -gt $cut ]] && ok "the next model turned the section off" ||
    fail "no 'section: off' after the drop"
# The last visible count from the section's "off" on.
visible=$(jq -rs "[foreach .[] as \$r (false; . or (\$r | $section_off);
    if . and \$r.event == \"visible\" then \$r.parts else empty end)] | last // 0" "$work/clean.out")
[[ $visible -gt 0 ]] && ok "the next model shows $visible parts" || fail "no visible parts on the next model"
after clean "$section_off" "$nothing_to_undo" && ok "the next model's undo history is empty" ||
    fail "Ctrl+Z on the new model undid something"

# Undo and redo: H of a box's parts, the tree's root checkbox (everything hidden: the view
# says so) and a section plane; each undo gives back the set before exactly (its hash
# and the visible count), each redo the set after.
t=0.5
{
    at box 420 150 600 330
    at frames 6
    at key H
    at pipeline ready # the first hide builds the pipeline that hides, however long it takes
    at frames 6
    at key ctrl+Z
    at pipeline ready
    at frames 6
    at key ctrl+shift+Z
    at pipeline ready
    at frames 6
    at key ctrl+Z
    at pipeline ready
    at frames 6
    at key ctrl+Y
    at pipeline ready
    at frames 6
    at node hide
    at frames 4
    at key ctrl+Z
    at frames 4
    at section y,0
    at frames 4
    at key ctrl+Z
    at frames 6
    at quit
} >"$work/undo.txt"
session undo --no-saved-settings
# step EVENT N: the Nth record of EVENT (undo_step, undo, redo) as "HIDDEN HASH SECTION", or
# "nothing" (nothing to undo or redo).
step() {
    events "$work/undo.out" "$1" \
        'if .done == false then "nothing" else "\(.hidden) \(.hidden_hash) \(.section)" end' |
        sed -n "${2}p"
}
hidden=$(step undo_step 1)
none=$(step undo 1)
[[ $hidden =~ ^[1-9][0-9]*\  && $none =~ ^0\  ]] ||
    fail "H: step '$hidden', undo '$none'"
[[ $(step redo 1) == "$hidden" && $(step undo 2) == "$none" && $(step redo 2) == "$hidden" ]] &&
    ok "undo and redo (Ctrl+Shift+Z, Ctrl+Y) restore the hidden set exactly ($hidden)" ||
    fail "redo '$(step redo 1)' / '$(step redo 2)', undo '$(step undo 2)', expected '$hidden' / '$none'"
# The visible count is the count before H after each undo, the count after it after each redo:
# "MARK COUNT" with the count shown when the mark came, that is before it took effect.
marks=$(jq -rs '[foreach .[] as $r (null; if $r.event == "visible" then $r.parts else . end;
    if ($r.event | IN("undo", "redo", "undo_step")) and $r.done != false then "\($r.event) \(.)"
    else empty end)] | .[]' "$work/undo.out" | head -5 | paste -sd' ')
read -r _ v0 _ v1 _ v0b _ v1b _ v0c <<<"$marks"
[[ $v0 -gt 0 && $v1 -gt 0 && $v0 != "$v1" && $v0b == "$v0" && $v0c == "$v0" && $v1b == "$v1" ]] &&
    ok "visible parts $v0 after each undo, $v1 after each redo" ||
    fail "visible counts at the marks: '$marks'"
all_hidden='.event == "empty" and .reason == "all hidden"'
has undo "$all_hidden" && after undo "$all_hidden" '.event == "empty" and .reason == null' &&
    ok "the tree's root checkbox hid all: the view said so, and Ctrl+Z showed them again" ||
    fail "empty records: $(events "$work/undo.out" empty | paste -sd'|')"
[[ $(step undo_step 3) == "${hidden% false} true" && $(step undo 4) == "$hidden" ]] &&
    ok "a section plane was a step, and Ctrl+Z took it off" ||
    fail "section step '$(step undo_step 3)', undo '$(step undo 4)'"

# One command, three ways to ask (issue 38): H, the panel's hide button and the script's
# `hide` each run "command: hide" and hide the same parts (each undone and the parts selected
# again before the next); X,
# the panel's X-ray checkbox and `xray` run xray on, off, on; 1, the panel's front button and
# `view front` turn to the front. The panel's rows come from a first run's layout line (a
# window tall enough to show the hide buttons), as a user finds them on the screen.
{
    echo "0.5 box 420 150 600 330"
    echo "0.6 frames 6"
    echo "0.7 quit"
} >"$work/rows.txt"
session rows --no-saved-settings --size 720x760
rows=$(events "$work/rows.out" panel_rows .rows | tail -1)
at_row() { [[ -n $rows ]] && jq -r --arg n "$1" '.[] | select(.name == $n) | .y' <<<"$rows"; }
hide_y=$(at_row "hide buttons")
view_y=$(at_row view)
if [[ -z $hide_y || -z $view_y ]]; then
    fail "no hide buttons or view row in '$rows'"
else
    # A button's middle, 9 px below its row's top; the X-ray box on the line below the
    # buttons, the views' small buttons on the line below the edges box.
    t=0.5
    {
        at box 420 150 600 330
        at frames 6
        at key H
        at pipeline ready # the first hide builds the pipeline that hides, however long it takes
        at frames 4
        at key ctrl+Z
        at frames 4
        at box 420 150 600 330 # hidden parts left the selection: select them again
        at frames 6
        at click 30 $((hide_y + 9))
        at frames 4
        at key ctrl+Z
        at frames 4
        at box 420 150 600 330
        at frames 6
        at hide
        at frames 4
        at key X
        at frames 3
        at click 17 $((hide_y + 32))
        at frames 3
        at xray
        at frames 3
        at key 1
        at frames 2
        at click 20 $((view_y + 29))
        at frames 2
        at view front
        at frames 2
        at quit
    } >"$work/same.txt"
    session same --no-saved-settings --size 720x760
    asked=$(events "$work/same.out" command 'select(.command | test("^(hide|xray.*|view.*)$")) | .command' |
        paste -sd,)
    [[ $asked == "hide,hide,hide,xray on,xray off,xray on,view front,view front,view front" ]] &&
        ok "key, panel and script asked for the same commands: $asked" ||
        fail "commands asked: '$asked'"
    # The first hidden count after each hide command.
    hidden=$(jq -rs 'reduce .[] as $r ({h: false, counts: []};
        if $r.event == "command" and $r.command == "hide" then .h = true
        elif .h and $r.event == "hidden" then .counts += [$r.parts] | .h = false else . end) |
        .counts | map(tostring) | join(" ")' "$work/same.out")
    read -r h1 h2 h3 <<<"$hidden"
    [[ ${h1:-0} -gt 0 && $h2 == "$h1" && $h3 == "$h1" ]] && ok "each hid the same $h1 parts" ||
        fail "hidden after each hide: '$hidden'"
    fronts=$(count same '.event == "view" and .name == "front"')
    xrays=$(events "$work/same.out" xray 'if .on then "on" else "off" end' | paste -sd' ')
    [[ $fronts -eq 3 && $xrays == "on off on" ]] &&
        ok "the views turned to the front three times, X-ray went on, off, on" ||
        fail "views '$fronts', xray '$xrays'"
fi

# F12: a PNG named by the date and time in XDG_PICTURES_DIR of user-dirs.dirs, twice without
# overwriting.
mkdir -p "$work/home/Shots" "$XDG_CONFIG_HOME"
echo 'XDG_PICTURES_DIR="$HOME/Shots"' >"$XDG_CONFIG_HOME/user-dirs.dirs"
t=0.5
{
    at key F12
    at frames 3
    at key F12
    at frames 3
    at quit
} >"$work/shot.txt"
saved_home=$HOME
export HOME=$work/home
session shot --no-saved-settings
export HOME=$saved_home
shots=$(events "$work/shot.out" screenshot 'select(.width == 720 and .height == 450) | .path' |
    grep -x "$work/home/Shots/idview-[0-9]\{8\}-[0-9]\{6\}\(-2\)\?\.png")
pngs() { # every file named is a PNG
    local f
    for f in "$@"; do [[ $(head -c 4 "$f" | tail -c 3) == PNG ]] || return 1; done
}
[[ $(echo "$shots" | sort -u | grep -c .) -eq 2 ]] && pngs $shots &&
    ok "F12 wrote two PNGs in the Pictures folder: $(basename -a $shots | paste -sd' ')" ||
    fail "F12: '$(events "$work/shot.out" screenshot | paste -sd'|')'"

# Esc during a box drag, with real input (xdotool's XTEST events, in the order a hand makes
# them): Shift + left press in the view, a move, Esc, the release. The box is dropped: no
# selection comes, though three screenshots (each a finished frame) pass after the release,
# time enough for a box's parts to arrive.
if command -v xdotool >/dev/null; then
    mkdir -p "$work/real-shots"
    # The script only ends a viewer the hand below never reached (no input arrived); Ctrl+Q
    # ends it otherwise, and a broken chain of the hand's steps kills it.
    echo "200 quit" >"$work/real.txt"
    XDG_PICTURES_DIR=$work/real-shots xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
        out=$1/real.out
        "$2" --validation --size 720x450 --scene procedural:preset=small --no-saved-settings \
            --script "$1/real.txt" --print-events >"$out" 2>"$1/real.err" &
        pid=$!
        wait_for() { # N records of the viewer a jq condition holds for, while it runs
            until [[ $(jq -c "select($2)" "$out" 2>/dev/null | wc -l) -ge $1 ]]; do
                kill -0 $pid 2>/dev/null || return 1
                sleep 0.1
            done
        }
        wait_for 1 ".event == \"visible\" and .parts >= 1" &&
            xdotool mousemove 430 160 keydown shift mousedown 1 mousemove 500 240 \
                mousemove 590 320 keyup shift key Escape mouseup 1 &&
            xdotool key F12 && wait_for 1 ".event == \"screenshot\"" &&
            xdotool key F12 && wait_for 2 ".event == \"screenshot\"" &&
            xdotool key F12 && wait_for 3 ".event == \"screenshot\"" &&
            xdotool key ctrl+q || kill $pid
        wait $pid' real "$work" "$idview"
    rc=$?
    [[ $rc -eq 0 ]] || fail "real input session: exit code $rc $(head -c 500 "$work/real.err")"
    [[ $(count real '.event == "screenshot"') -eq 3 ]] && has real '.event == "cancel" and .what == "box"' &&
        ! has real '.event == "selected"' &&
        ok "Esc during a box drag dropped the box: nothing selected" ||
        fail "box and Esc: '$(jq -c 'select(.event | IN("cancel", "selected", "screenshot"))' "$work/real.out" | paste -sd'|')'"

    # A typed path's keys, real and fast: the letters of a run of one letter reach the panel
    # a change per key a frame (key_queue.h), so the Enter after them waits behind some fifty
    # changes. The viewer must draw the frames that hand them over with no other event to
    # wake it (the pointer rests over the panel: nothing blinks), open the file once, and
    # give the keys back to the commands after (M).
    mkdir -p "$work/typed"
    typed=$work/typed/aaaaaaaaaaaaaaaaaaaaaaaa.stl
    cp /usr/share/assimp/models/STL/triangle_with_two_solids.stl "$typed"
    echo "200 quit" >"$work/typed.txt"
    xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
        out=$1/typed.out
        "$2" --validation --size 720x450 --scene procedural:preset=small --no-saved-settings \
            --script "$1/typed.txt" --print-events >"$out" 2>"$1/typed.err" &
        pid=$!
        wait_for() {
            until [[ $(jq -c "select($2)" "$out" 2>/dev/null | wc -l) -ge $1 ]]; do
                kill -0 $pid 2>/dev/null || return 1
                sleep 0.1
            done
        }
        wait_for 1 ".event == \"visible\" and .parts >= 1" &&
            xdotool mousemove 100 420 key ctrl+l &&
            wait_for 1 ".event == \"command\" and (.command | startswith(\"type-path\"))" &&
            xdotool type --delay 1 "$3" && xdotool key Return &&
            wait_for 1 ".event == \"opened\" and .path == \"$3\"" && xdotool key m &&
            wait_for 1 ".event == \"measure\" and .on" &&
            xdotool key ctrl+q || kill $pid
        wait $pid' typed "$work" "$idview" "$typed"
    rc=$?
    [[ $rc -eq 0 ]] || fail "typed path session: exit code $rc $(head -c 500 "$work/typed.err")"
    [[ $(count typed ".event == \"command\" and .command == \"open $typed\"") -eq 1 &&
        $(count typed ".event == \"opened\" and .path == \"$typed\"") -eq 1 ]] && has typed "$measure_on" &&
        ok "a path typed fast, then Enter: opened once with no other event, the keys the viewer's after" ||
        fail "typed path: '$(jq -c 'select(.event | IN("command", "opened", "measure"))' "$work/typed.out" | paste -sd'|')'"
else
    fail "xdotool is missing: the real input sessions cannot run (Debian package xdotool)"
fi

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
echo "viewer commands test passed"
