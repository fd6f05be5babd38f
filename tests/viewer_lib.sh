# viewer_lib.sh IDVIEW LAVAPIPE_ICD - what the viewer tests share, sourced by them with their
# arguments: the lavapipe environment, the Xvfb check (without it they fail, never skip), a
# work folder that
# holds the CAD cache and the viewer's kept settings, fail(), at() and the readers of the
# event records.
set -uo pipefail
idview=$1
icd=$2
# ctest passes the ICD of build/lavapipe-25 (Mesa 25) and sets LD_LIBRARY_PATH to its lib
# folder, for the newer libdrm (tests/CMakeLists.txt).
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd
if ! command -v xvfb-run >/dev/null || ! command -v xauth >/dev/null; then
    echo "FAIL xvfb-run and xauth are needed: apt-get install xvfb xauth (scripts/setup.sh test)"
    exit 1
fi
# The tests read the viewer's event records (JSON Lines, docs/viewer.md) by field, with jq:
# without it they fail, never skip.
if ! command -v jq >/dev/null; then
    echo "FAIL jq is needed to read the event records (Debian package jq; scripts/setup.sh test)"
    exit 1
fi
# events FILE EVENT [FILTER]: the records of EVENT in FILE, one a line, compact; with FILTER
# (jq), what it makes of each record, strings raw: events out.txt selected .parts
events() {
    jq -rc --arg e "$2" "select(.event == \$e) | ${3:-.}" "$1"
}
# said FILE EVENT [CONDITION]: whether a record of EVENT (for which the jq CONDITION holds) is
# in FILE.
said() {
    jq -en --arg e "$2" "[inputs | select(.event == \$e and (${3:-true}))] | length > 0" "$1" \
        >/dev/null
}
# event_lines FILE CONDITION: the line numbers of FILE's records for which the jq CONDITION
# holds, for tests of the order of events of different kinds.
event_lines() {
    jq -r -s "to_entries[] | select(.value | $2) | .key + 1" "$1"
}
work=$(mktemp -d)
# CAD tessellations are cached here, never in the cache of the user running the test.
export XDG_CACHE_HOME=$work/xdg-cache-home
# The viewer keeps its settings here, never in the config of the user running the test.
export XDG_CONFIG_HOME=$work/xdg-config-home
# VIEWER_TEST_KEEP=1 keeps the scripts, outputs and screenshots for a look.
[[ ${VIEWER_TEST_KEEP:-} == 1 ]] && echo "keeping $work" || trap 'rm -rf "$work"' EXIT
failures=0
fail() {
    echo "FAIL $*"
    failures=$((failures + 1))
}
# at COMMAND...: one script line, 0.1 s after the previous one ($t, which each session sets).
at() {
    echo "$t $*"
    t=$(awk -v t="$t" 'BEGIN{print t + 0.1}')
}
# session NAME [FLAGS...]: the viewer at 720x450 on the small procedural scene with
# validation, running $work/NAME.txt with event records into $work/NAME.out, stderr into
# $work/NAME.err; a failing exit code is a failure, with the start of stderr.
session() {
    local name=$1
    shift
    xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --validation --size 720x450 \
        --scene procedural:preset=small --script "$work/$name.txt" --print-events "$@" \
        >"$work/$name.out" 2>"$work/$name.err"
    local rc=$?
    [[ $rc -eq 0 ]] || { fail "$name session: exit code $rc"; head -c 2000 "$work/$name.err"; }
}
