#!/usr/bin/env bash
# launcher_test.sh IDVIEW LAVAPIPE_ICD BUILD - the applications menu's entry as a desktop starts
# it: installed into a DESTDIR, the Exec line read from the installed idview.desktop, its %f
# given a STEP file and idview found on PATH. The window opens on that model under Xvfb with
# validation: its title names the file and the model's parts are drawn.
source "$(dirname "$0")/viewer_lib.sh"
build=$3

DESTDIR=$work/dest cmake --install "$build" --prefix /usr >/dev/null ||
    { echo "FAIL cmake --install"; exit 1; }
entry=$work/dest/usr/share/applications/idview.desktop
exec_line=$(sed -n 's/^Exec=//p' "$entry")
[[ $exec_line == *%f* ]] || { echo "FAIL the Exec line '$exec_line' takes no %f"; exit 1; }
mkdir -p "$work/bin" && ln -s "$idview" "$work/bin/idview"
step=/usr/share/opencascade/data/step/screw.step
argv=()
for word in $exec_line; do
    case $word in
    %f) argv+=("$step") ;; *) argv+=("$word") ;;
    esac
done
printf '0.5 loaded\n0.6 frames 3\n0.7 quit\n' >"$work/launch.txt"
PATH=$work/bin:$PATH xvfb-run -a -s "-screen 0 1280x800x24" "${argv[@]}" --validation \
    --no-saved-settings --size 720x450 --script "$work/launch.txt" --print-events \
    >"$work/launch.out" 2>"$work/launch.err"
rc=$?
[[ $rc -eq 0 ]] || fail "'$exec_line' with %f=$step: exit code $rc: $(head -c 600 "$work/launch.err")"
title=$(events "$work/launch.out" title '.text' | tail -1)
[[ $title == "screw.step - idview - "* ]] && echo "ok   the launcher opened screw.step: '$title'" ||
    fail "the title does not name screw.step: '$title'"
visible=$(events "$work/launch.out" visible '.parts' | tail -1)
[[ $visible =~ ^[0-9]+$ && $visible -gt 0 ]] && echo "ok   $visible parts drawn" ||
    fail "no parts drawn: '$visible'"

[[ $failures -eq 0 ]] && echo "the launcher's Exec line opened the model"
exit $((failures > 0))
