#!/usr/bin/env bash
# idle-cpu.sh [MODEL] - how much CPU the viewer takes at rest with a part hovered: the
# viewer under Xvfb on lavapipe (build/lavapipe-25), the cursor moved to the middle of the
# area beside the panel, and, once it hovers a part and has settled, the process's CPU time
# (user + system, all threads, from /proc) over 10 seconds, as a share of one core. MODEL
# defaults to the default model; any file idview opens will do. Prints one line. Needs the
# Release build in build/ and xvfb-run; settings and caches go to a temporary folder.
set -euo pipefail
cd "$(dirname "$0")/.."
model=${1:-assets/default.glb}
icd=$PWD/build/lavapipe-25/lvp_icd.json
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd LD_LIBRARY_PATH=$PWD/build/lavapipe-25/lib
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME=$work/config XDG_CACHE_HOME=$work/cache
cat >"$work/script.txt" <<'SCRIPT'
0.5 frames 3
1.0 move 840 360
1.1 frames 5
1.2 rest 40
1.3 quit
SCRIPT
xvfb-run -a -s "-screen 0 1280x800x24" build/idview --size 1280x720 --model "$model" \
    --script "$work/script.txt" --print-events >"$work/out.txt" 2>"$work/err.txt" &
runner=$!
pid=
for _ in $(seq 600); do # the model loads first: up to 5 minutes
    pid=$(pgrep -n -f "build/idview --size 1280x720" || true)
    grep -q '^idview: hovered: part' "$work/out.txt" 2>/dev/null && [[ -n $pid ]] && break
    sleep 0.5
done
grep -q '^idview: hovered: part' "$work/out.txt" || {
    echo "idle-cpu: no part came under the cursor; see $work/out.txt" >&2
    kill "$runner" 2>/dev/null
    exit 1
}
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
sleep 2 # the settle frames after the hover
before=$(ticks)
sleep 10
after=$(ticks)
hz=$(getconf CLK_TCK)
scenes() { grep '^idview: rest:' "$work/out.txt" | tail -1; }
echo "$model: $(awk -v t=$((after - before)) -v hz="$hz" 'BEGIN{printf "%.1f", 100 * t / hz / 10}')" \
    "% of a core over 10 s at rest, hovering $(grep -m1 '^idview: hovered:' "$work/out.txt" |
        cut -d' ' -f3-); last $(scenes | cut -d' ' -f2-)"
kill "$pid" 2>/dev/null || true
wait "$runner" 2>/dev/null || true
