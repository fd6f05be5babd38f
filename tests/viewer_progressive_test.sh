#!/usr/bin/env bash
# viewer_progressive_test.sh IDVIEW LAVAPIPE_ICD - a big CAD file shown as it loads, under Xvfb
# on lavapipe with validation and the real worker processes: 8 copies of linkrods.step made
# by idview-step-copies (8 pieces). The worker handed piece 0 stops itself (SIGSTOP, through
# the workers' fault injection, cad_worker.cpp), so the load holds at 7 of 8 solids for as long
# as the test likes, whatever the machine's pace: a part picked, selected in the tree and hidden
# meanwhile is the same part once the test lets the worker go on (SIGCONT) and the load ends;
# the tree lists every object before all are meshed; Esc stops a first model (what is shown
# stays, marked incomplete) and cancels a dropped one (back to the model before, its view and
# selection); and closing the window ends a load that would never end, its workers gone.
source "$(dirname "$0")/viewer_lib.sh"

copies=$(dirname "$idview")/idview-step-copies
linkrods=/usr/share/opencascade/data/step/linkrods.step
[[ -x $copies ]] || { echo "FAIL $copies is not built"; exit 1; }
[[ -f $linkrods ]] || { echo "FAIL needs $linkrods from Debian's occt-misc: apt-get install occt-misc"; exit 1; }
model=$work/l8.step
"$copies" -n 8 -o "$model" "$linkrods" || fail "idview-step-copies could not write $model"
ok() { echo "ok   $*"; }

# start NAME FLAGS...: the viewer (FLAGS say on which model) running
# $work/NAME.txt, in the background; `finish` waits for it (a hang guard, not a clock: a load
# held by the stopped worker never ends by itself) and checks its exit code.
start() {
    local name=$1
    shift
    # The worker handed piece 0 stops (the viewer's sessions only).
    IDVIEW_TEST_WORKER_SIGNAL=0:19 timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" \
        "$idview" --validation --size 720x450 \
        --no-saved-settings --no-cache --load-workers 2 --script "$work/$name.txt" \
        --print-events "$@" >"$work/$name.out" 2>"$work/$name.err" &
    runner=$!
    session_name=$name
}
finish() {
    wait $runner
    local rc=$?
    [[ $rc -eq 124 ]] && fail "$session_name: the viewer did not end (hang guard)"
    [[ $rc -eq 0 || $rc -eq 124 ]] || { fail "$session_name: exit code $rc"; head -c 2000 "$work/$session_name.err"; }
}
# wait_line CONDITION: until the session has a record the jq CONDITION holds for; false if it
# ended first.
wait_line() {
    until jq -en "[inputs | select($1)] | length > 0" "$work/$session_name.out" >/dev/null 2>&1; do
        kill -0 $runner 2>/dev/null || return 1
        sleep 0.2
    done
}
# The viewer's process (not xvfb-run's shell, which has the same arguments), and its workers.
# A worker being started is a copy of the viewer until it runs its own program: not its parent.
viewer_pid() {
    local pid parent exe
    exe=$(readlink -f "$idview")
    for pid in $(pgrep -f -- "--script $work/$session_name.txt"); do
        [[ $(readlink "/proc/$pid/exe") == "$exe" ]] || continue
        parent=$(awk '{print $4}' "/proc/$pid/stat" 2>/dev/null)
        [[ -n $parent && $(readlink "/proc/$parent/exe" 2>/dev/null) == "$exe" ]] || echo "$pid"
    done
}
stopped_worker() { ps -o pid=,stat= --ppid "$(viewer_pid)" | awk '$2 ~ /^T/ {print $1}'; }
# ev EVENT [FILTER]: the session's records of EVENT (viewer_lib.sh's events).
ev() { events "$work/$session_name.out" "$@"; }
# before A B: the first record jq condition A holds for comes before the first one B holds for.
before() {
    local a b
    a=$(event_lines "$work/$session_name.out" "$1" | head -1)
    b=$(event_lines "$work/$session_name.out" "$2" | head -1)
    [[ -n $a && -n $b && $a -lt $b ]]
}

tree_nodes=$("$idview" --model "$model" --tree 2>/dev/null | grep -o '"name"' | wc -l)
objects=$("$idview" --model "$model" --stats 2>/dev/null | sed -n 's/.*"objects":\([0-9]*\).*/\1/p')

# (a, b) The model given at start, held at 7 of 8 solids: a click picks a part of a copy
# meshed, the tree selects the copy still loading (copy 1, piece 0) and hides copy 3; the
# worker goes on once the hide is told; then the same click picks the same part, the selection
# and hidden parts have stayed (Esc clears a selection, Shift+H shows more parts).
t=0.5
{
    at solids 7
    at frames 3
    at click 560 250
    at frames 6
    at node select l8/copy 1/the product name
    at frames 3
    at node hide l8/copy 3
    at frames 6
    at loaded
    at frames 8
    at escape
    at frames 3
    at show-all
    at frames 8
    at click 560 250
    at frames 6
    at quit
} >"$work/pick.txt"
start pick --model "$model"
if wait_line '.event == "hidden" and .parts == 37'; then
    worker=$(stopped_worker)
    [[ -n $worker ]] && kill -CONT $worker || fail "pick: no stopped worker to go on"
fi
finish
# The part, its path, its face and the kind of the face's surface; not the surface's numbers,
# which are rounded to the model's precision (scene/precision.h): the B-rep's tolerance is known
# only once the model is whole, so while it loads they show finer.
picks=$(ev selected 'select(.part != null) | "\(.part) \(.object) \(.local_part) \(.path) face \(.face) \((.surface // "") | capture("^(?<kind>[a-z]*)").kind)"')
during=$(head -1 <<<"$picks")
after=$(sed -n 2p <<<"$picks")
[[ -n $during && $during == "$after" && $during =~ \ face\ [0-9]+\ [a-z]+$ ]] &&
    ok "a part picked while loading is the same once loaded: $during" ||
    fail "picked while loading '$during', at the same pixel once loaded '$after'"
complete='.event == "loading" and .state == "complete"'
before '.event == "loading" and .state == "partial" and .shown == 7 and .of == 8' \
    '.event == "selected" and .part != null' &&
    before '.event == "hidden" and .parts == 37' "$complete" &&
    before "$complete" '.event == "cancel" and .what == "selection"' &&
    ok "picked, selected and hid during the load; the selection stayed once it was complete" ||
    fail "pick: the events came in another order: $(jq -c 'select(.event | IN("loading", "selected", "hidden", "cancel"))' "$work/pick.out" | paste -sd'|')"
tree=$(ev loading 'select(.state == "tree") | "\(.nodes) nodes, \(.objects) objects"')
[[ $tree == "$tree_nodes nodes, $objects objects" ]] &&
    said "$work/pick.out" selected '.parts == 37 and .part == null' &&
    ok "the tree had its $tree_nodes nodes before the solids; the copy still loading was selected in it" ||
    fail "tree while loading: '$tree', --tree $tree_nodes nodes, $objects objects; selections: $(ev selected | paste -sd'|')"
# The count just before Shift+H, the model whole: the record may come before the load's
# "complete" where the last piece's partial scene was drawn first (the same parts) and none
# after it.
hidden_kept=$(jq -rs 'first(foreach .[] as $r (null; if $r.event == "visible" then $r.parts else . end;
    if $r.event == "hidden" and $r.parts == 0 then . else empty end)) // empty' "$work/pick.out")
shown_all=$(jq -rs '[foreach .[] as $r (false; . or ($r.event == "hidden" and $r.parts == 0);
    if . and $r.event == "visible" then $r.parts else empty end)] | last // empty' "$work/pick.out")
[[ -n $hidden_kept && -n $shown_all && $shown_all -gt $hidden_kept ]] &&
    ok "copy 3 stayed hidden once loaded: $hidden_kept visible parts, $shown_all after Shift+H" ||
    fail "visible parts once loaded '$hidden_kept', after showing all '$shown_all'"

# (c) Esc on the model given at start (no model before it): Stop, what is shown stays, marked
# incomplete in the title; the same file dropped again and cancelled brings the incomplete
# model back, still marked.
t=0.5
{
    at solids 7
    at frames 3
    at key ESC
    at loaded
    at frames 6
    at drop "$model"
    at solids 7
    at key ESC
    at loaded
    at frames 6
    at quit
} >"$work/stop.txt"
start stop --model "$model"
finish
said "$work/stop.out" command '.command == "stop"' &&
    [[ $(ev loading 'select(.state == "stopped" and has("of")) | "\(.shown) \(.of) \(.missing)"') == "7 8 1" ]] &&
    said "$work/stop.out" title '.text | test("idview - .* - incomplete: 1 of 8 solids missing - ")' &&
    ! said "$work/stop.out" loading '.state == "complete"' &&
    ok "Esc stopped the first model: 7 of 8 solids shown, marked incomplete" ||
    fail "stop: $(jq -c 'select(.event | IN("command", "loading", "title"))' "$work/stop.out" | tail -4 | paste -sd'|')"
# The visible count when the next load shows its assembly or is cancelled, after the stop.
visible=$(jq -rs 'first(foreach .[] as $r ({v: null, on: false};
    (if $r.event == "visible" then .v = $r.parts else . end) |
    (if $r.event == "loading" and $r.state == "stopped" then .on = true else . end);
    if .on and $r.event == "loading" and ($r.state | IN("assembly", "cancelled")) then .v
    else empty end)) // empty' "$work/stop.out")
[[ ${visible:-0} -gt 0 ]] && ok "what the stopped load showed stayed: $visible visible parts" ||
    fail "nothing visible after Stop"
back_to='select(.state == "cancelled" and .after == "back") | .back_to'
[[ $(ev loading "$back_to") == "$model" ]] &&
    [[ $(ev title .text | tail -1) == *" - incomplete: 1 of 8 solids missing - "* ]] &&
    ok "a load cancelled over the stopped model brought it back, still incomplete" ||
    fail "cancel over the stopped model: $(jq -c 'select(.event == "title" or (.event == "loading" and .state == "cancelled"))' "$work/stop.out" | tail -2 | paste -sd'|')"

# (c, d) Esc on a dropped model (the small scene before it): Cancel, the small scene back with
# its view and selection; then the model again, and the window closed while it loads.
t=0.5
{
    at move 420 230
    at click 420 230
    at frames 6
    at drop "$model"
    at solids 7
    at frames 3
    at key ESC
    at loaded
    at frames 6
    at escape
    at frames 3
    at click 420 230
    at frames 6
    at drop "$model"
    at solids 7
    at quit
} >"$work/cancel.txt"
start cancel --scene procedural:preset=small
# Every worker the viewer starts, noted while it runs (each lives for seconds: the pieces take
# that long, and the held one until the end) as PID:START, its start time in the kernel's ticks,
# so that a number used again by another process later is not taken for it.
started() { awk '{print $22}' "/proc/$1/stat" 2>/dev/null; }
workers=
while kill -0 $runner 2>/dev/null; do
    viewer=$(viewer_pid)
    for pid in $([[ -n $viewer ]] && pgrep -P "$viewer"); do workers="$workers $pid:$(started $pid)"; done
    sleep 0.2
done
workers=$(tr ' ' '\n' <<<"$workers" | sed '/^$/d; /:$/d' | sort -u | paste -sd' ')
finish
picks=$(ev selected 'select(.part != null)')
[[ -n $(head -1 <<<"$picks") && $(head -1 <<<"$picks") == "$(sed -n 2p <<<"$picks")" ]] &&
    said "$work/cancel.out" command '.command == "cancel"' && [[ $(ev loading "$back_to") == "procedural:preset=small" ]] &&
    grep -q "^idview: $model: cancelled$" "$work/cancel.err" &&
    before '.event == "loading" and .state == "cancelled" and .after == "back"' \
        '.event == "cancel" and .what == "selection"' &&
    ok "Esc cancelled the drop: the small scene back, its view and selection ($(head -1 <<<"$picks"))" ||
    fail "cancel: picks '$(paste -sd'|' <<<"$picks")', $(jq -c 'select(.event | IN("command", "loading", "cancel"))' "$work/cancel.out" | paste -sd'|')"
said "$work/cancel.out" loading '.state == "cancelled" and .after == "window closed"' &&
    ok "closing the window cancelled a load that would never end, and the viewer ended" ||
    fail "close: $(tail -3 "$work/cancel.out" | paste -sd'|')"
left=
for worker in $workers; do
    [[ $(started ${worker%%:*}) == "${worker#*:}" ]] && left="$left ${worker%%:*}"
done
[[ $(wc -w <<<"$workers") -ge 4 && -z $left ]] && ok "the workers of both loads are gone: $(sed 's/:[0-9]*//g' <<<"$workers")" ||
    fail "workers while loading '$workers', still there '$left'"

((failures == 0)) || { echo "$failures check(s) failed"; exit 1; }
