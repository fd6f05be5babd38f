#!/usr/bin/env bash
# thumbnailer_test.sh IDVIEW LAVAPIPE_ICD BUILD_DIR - the thumbnailer as a file manager runs it:
# installed into a DESTDIR, its Exec line read from the installed .thumbnailer and its %s, %i
# (a path, or a file:// URI as Nautilus gives) and %o substituted, idview found on PATH. Each
# sample gives a 128-pixel PNG in the part colours; a broken file, a deadline passed and a
# memory cap passed each give one line, a non-zero exit and no file at all.
source "$(dirname "$0")/cli_lib.sh"
build=$3
here=$(cd "$(dirname "$0")/.." && pwd)
summary="$here/tests/png_summary.py"

DESTDIR=$work/dest cmake --install "$build" --prefix /usr >/dev/null ||
    { echo "FAIL cmake --install"; exit 1; }
entry=$work/dest/usr/share/thumbnailers/idview.thumbnailer
exec_line=$(sed -n 's/^Exec=//p' "$entry")
[[ -n $exec_line ]] || { echo "FAIL no Exec line in $entry"; exit 1; }
echo "Exec=$exec_line"
mkdir -p "$work/bin" && ln -s "$idview" "$work/bin/idview"
export PATH=$work/bin:$PATH
tryexec=$(sed -n 's/^TryExec=//p' "$entry")
command -v "$tryexec" >/dev/null || fail "TryExec=$tryexec is not on PATH"

# thumbnail INPUT OUTPUT [EXTRA...]: the Exec line with %s=128, %i=INPUT, %o=OUTPUT (and %u
# as the URI of INPUT, %% as %), each word one argument as the specification says; the
# exit code is returned, stderr kept in $work/err.
thumbnail() {
    local input=$1 output=$2 word
    shift 2
    local argv=()
    for word in $exec_line; do
        case $word in
        %s) argv+=(128) ;; %i) argv+=("$input") ;; %o) argv+=("$output") ;;
        %u) argv+=("file://$input") ;; %%) argv+=(%) ;; *) argv+=("$word") ;;
        esac
    done
    "${argv[@]}" "$@" 2>"$work/err"
}

# previewed NAME INPUT: exit 0, a 128x128 PNG with several saturated hues (the part colours),
# nothing on stderr, no temporary file left beside it.
previewed() {
    local name=$1 input=$2 out=$work/out/$1.png report
    mkdir -p "$work/out"
    # The default bound (10 s) is the file manager's; a machine twice as slow, or busy with
    # other tests, must still draw every sample, so the pictures get all the time they need
    # (the deadline case below checks the bound itself).
    if ! thumbnail "$input" "$out" --thumbnail-timeout 300; then
        fail "$name: exit code $?: $(head -c 300 "$work/err")"
    elif ! report=$(python3 "$summary" "$out" 2>&1); then
        fail "$name: $report"
    elif ! python3 -c 'import json,sys; r=json.loads(sys.argv[1]);
assert max(r["width"], r["height"]) == 128 and r["colours"] >= 20 and r["hues"] >= 3' "$report"
    then
        fail "$name: expected 128 on the long edge, >= 20 colours, >= 3 hues: $report"
    elif [[ -s $work/err ]]; then
        fail "$name: stderr: $(head -c 300 "$work/err")"
    elif [[ $(ls "$work/out" | grep -c -v '\.png$') -ne 0 ]]; then
        fail "$name: left behind: $(ls "$work/out")"
    else
        echo "ok   $name $report"
    fi
}

# refused NAME PATTERN INPUT [EXTRA...]: a non-zero exit, exactly one stderr line matching
# PATTERN, and no file at all where the PNG would go.
refused() {
    local name=$1 pattern=$2 input=$3 start=$SECONDS
    shift 3
    rm -rf "$work/refused" && mkdir -p "$work/refused"
    thumbnail "$input" "$work/refused/out.png" "$@"
    local rc=$?
    if [[ $rc -eq 0 || $(wc -l <"$work/err") -ne 1 ]] || ! grep -Eq "$pattern" "$work/err"; then
        fail "$name: exit code $rc, expected one line matching '$pattern':"
        head -c 600 "$work/err"
    elif [[ -n $(ls -A "$work/refused") ]]; then
        fail "$name: left files: $(ls -A "$work/refused")"
    else
        echo "ok   $name (exit $rc, $((SECONDS - start)) s): $(cat "$work/err")"
    fi
}

step=/usr/share/opencascade/data/step/screw.step
previewed step "$step"
previewed iges /usr/share/opencascade/data/iges/bearing.iges
previewed glb "$here/assets/default.glb"
# Thunar's tumbler makes the output file itself and reads the thumbnail back through the
# descriptor it keeps: the PNG must land in that file, not beside it.
kept=$work/kept/out.png
mkdir -p "$work/kept" && : >"$kept"
exec 7<"$kept"
if thumbnail "$step" "$kept" --thumbnail-timeout 300 && cp /proc/$$/fd/7 "$work/kept.png" &&
    python3 "$summary" "$work/kept.png" >/dev/null 2>&1; then
    echo "ok   the output file made by the caller holds the PNG, read through its descriptor"
else
    fail "the PNG did not land in the output file the caller made and holds open"
fi
exec 7<&-
# Nautilus hands a URI: a file:// with an escaped space.
cp "$here/assets/default.glb" "$work/a model.glb"
previewed uri "file://$work/a%20model.glb"
# The STEP tessellation went to the cache a later preview or the viewer reads.
ls "$XDG_CACHE_HOME"/idview/* >/dev/null 2>&1 || fail "nothing in the cache $XDG_CACHE_HOME/idview"

printf 'ISO-10303-21;\nHEADER;\nthis is not STEP\n' >"$work/broken.step"
refused broken "^idview: error: .*broken\.step" "$work/broken.step"
# A file that would block the reader forever is refused before it is read.
mkfifo "$work/fifo.step"
refused fifo "^idview: error: .*fifo\.step: not a regular file" "$work/fifo.step"
refused deadline "^idview: error: .*screw\.step: no thumbnail: gave up after 0\.1 s" \
    "$step" --no-cache --thumbnail-timeout 0.1
refused memory "^idview: error: .*screw\.step: no thumbnail: " "$step" --no-cache \
    --thumbnail-memory 64
# The watchdog's kill reached the whole process group: no idview or load worker of this
# test's environment (its cache folder) outlives the runs.
sleep 0.2
for proc in /proc/[0-9]*; do
    [[ $(cat "$proc/comm" 2>/dev/null) == idview* ]] &&
        tr '\0' '\n' <"$proc/environ" 2>/dev/null | grep -qx "XDG_CACHE_HOME=$XDG_CACHE_HOME" &&
        fail "left running: ${proc#/proc/} $(cat "$proc/comm")"
done

((failures == 0)) && echo "all passed" || echo "$failures failed"
((failures == 0))
