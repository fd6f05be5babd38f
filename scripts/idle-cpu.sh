#!/usr/bin/env bash
# idle-cpu.sh [MODEL [X Y]] - how much CPU the viewer takes at rest: the viewer under Xvfb on
# lavapipe (build/lavapipe-25) at 1280x720 (IDLE_SIZE=1400x850 for another size), the real
# pointer (xdotool) moved to X,Y (default 824,360: the middle of the area beside the panel,
# where the model opens fitted; a model with nothing there needs another point), and once it
# hovers a part and has settled, the process's CPU time (user + system, all threads, from
# /proc) over 10 seconds as a share of one core; then the same with the pointer over the
# background, and with the pointer moved out of the window (the hover must end).
# MODEL defaults to the default model; any file idview opens will do.
# Needs the Release build in build/, Xvfb, xdotool and jq; settings and caches go to a temporary
# folder (IDLE_KEEP=1 keeps it). Prints three lines.
set -euo pipefail
cd "$(dirname "$0")/.."
model=${1:-assets/default.glb}
x=${2:-824}
y=${3:-360}
size=${IDLE_SIZE:-1280x720}
width=${size%x*}
height=${size#*x}
icd=$PWD/build/lavapipe-25/lvp_icd.json
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd LD_LIBRARY_PATH=$PWD/build/lavapipe-25/lib
work=$(mktemp -d)
export XDG_CONFIG_HOME=$work/config XDG_CACHE_HOME=$work/cache
display=:$((90 + RANDOM % 500))
Xvfb "$display" -screen 0 $((width + 200))x$((height + 200))x24 >/dev/null 2>&1 &
xvfb=$!
viewer=
cleanup() {
    [[ -n $viewer ]] && kill "$viewer" 2>/dev/null
    kill "$xvfb" 2>/dev/null
    [[ -n ${IDLE_KEEP:-} ]] && echo "kept $work" >&2 || rm -rf "$work"
}
trap cleanup EXIT
export DISPLAY=$display
for _ in $(seq 50); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done
build/idview --size "$size" --window-pos 0,0 --model "$model" --print-events \
    >"$work/out.txt" 2>"$work/err.txt" &
viewer=$!
seen=0 # event records before the last action: wait_for looks after them
# wait_for CONDITION: a record of the viewer's events (JSON Lines, docs/viewer.md) the jq
# CONDITION holds for, up to 5 minutes (a model loads)
wait_for() {
    for _ in $(seq 3000); do
        tail -n +$((seen + 1)) "$work/out.txt" 2>/dev/null |
            jq -en "[inputs | select($1)] | length > 0" >/dev/null 2>&1 && return 0
        sleep 0.1
    done
    echo "idle-cpu: no '$1' from the viewer; see $work/out.txt" >&2
    exit 1
}
ticks() { awk '{print $14 + $15}' "/proc/$viewer/stat"; }
# measure WHAT: CPU over 10 s, once the frames after the last event have settled.
measure() {
    sleep 2
    local before after
    before=$(ticks)
    sleep 10
    after=$(ticks)
    echo "$model, $1: $(awk -v t=$((after - before)) -v hz="$(getconf CLK_TCK)" \
        'BEGIN{printf "%.1f", 100 * t / hz / 10}') % of a core over 10 s at rest;" \
        "$(jq -c 'select(.event == "rest")' "$work/out.txt" | tail -1)"
}

hover_on='.event == "hovered" and .part != null'
hover_off='.event == "hovered" and .part == null'
wait_for '.event == "rest"'
seen=$(wc -l <"$work/out.txt")
xdotool mousemove "$x" "$y"
wait_for "$hover_on"
edge=$(jq -c 'select(.event == "edge_hovered") | .edge' "$work/out.txt" | tail -1)
measure "hovered part $(jq 'select(.event == "hovered") | .part' "$work/out.txt" | tail -1)${edge:+, edge $edge}"
seen=$(wc -l <"$work/out.txt")
xdotool mousemove $((width - 5)) $((height - 5))
wait_for "$hover_off"
measure "nothing hovered"
seen=$(wc -l <"$work/out.txt")
xdotool mousemove "$x" "$y"
wait_for "$hover_on"
seen=$(wc -l <"$work/out.txt")
xdotool mousemove $((width + 100)) $((height + 100))
wait_for "$hover_off"
measure "the pointer out of the window"
