#!/usr/bin/env bash
# install_test.sh IDVIEW LAVAPIPE_ICD BUILD - `cmake --install` into a DESTDIR, the tree then
# moved away so no path points back to the build: the installed idview prints the build's
# version line and draws the same ID images byte for byte (a STEP file, through its own
# libexec worker; a glTF file), and it reads its own share/idview copies, not the source
# tree's (a broken installed shader or default model makes it fail, naming the installed file).
source "$(dirname "$0")/cli_lib.sh"
build=$3
step=/usr/share/opencascade/data/step/screw.step
gltf=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb

if ! DESTDIR=$work/stage cmake --install "$build" --prefix /usr >"$work/install.log" 2>&1; then
    fail "cmake --install: $(tail -3 "$work/install.log")"
    exit 1
fi
mv "$work/stage/usr" "$work/moved"
root=$work/moved
installed=$root/bin/idview
for file in bin/idview bin/idview-step-copies libexec/idview/idview-load-worker \
    share/idview/shaders/shared.h share/idview/shaders/scene.frag \
    share/idview/assets/default.glb share/doc/idview/copyright; do
    [[ -f $root/$file ]] || fail "not installed: $file"
done

built_version=$("$idview" --version)
out=$("$installed" --version 2>&1)
[[ $out =~ ^idview\ [0-9]+\.[0-9]+\.[0-9]+\ \(.+\)$ && $out == "$built_version" ]] &&
    echo "ok   version: $out" || fail "version: '$out', the build says '$built_version'"

# same-ids NAME ARGS...: the installed and the built idview draw the same ID image.
same_ids() {
    local name=$1 out
    shift
    for who in built installed; do
        local program=$idview
        [[ $who == installed ]] && program=$installed
        if ! out=$("$program" --headless --validation --no-cache --frames 1 --size 160x120 \
            --id-image "$work/$name.$who.ids" "$@" 2>&1); then
            fail "$name: the $who idview: $out"
            return
        fi
    done
    cmp -s "$work/$name.built.ids" "$work/$name.installed.ids" &&
        echo "ok   $name: ID images equal ($(stat -c %s "$work/$name.built.ids") bytes)" ||
        fail "$name: the installed idview's ID image differs from the build's"
}
same_ids step --model "$step"
same_ids gltf --model "$gltf"

# refused-installed NAME FILE ARGS...: with FILE of the installed tree broken, the installed
# idview fails and names it: it read that file, not the source tree's or the build's copy.
refused_installed() {
    local name=$1 file=$2 out
    shift 2
    if out=$("$installed" --headless --no-cache --frames 1 --size 64x48 "$@" 2>&1); then
        fail "$name: ran with $file broken: it read another copy"
    elif [[ $out != *"$file"* ]]; then
        fail "$name: the error does not name $file: $(head -3 <<<"$out")"
    else
        echo "ok   $name: reads $file"
    fi
}
shaders=$root/share/idview/shaders
cp "$shaders/shared.h" "$work/shared.h"
echo '#error the installed copy' >>"$shaders/shared.h"
refused_installed installed-shaders "$shaders/shared.h" --model "$gltf"
cp "$work/shared.h" "$shaders/shared.h"
printf 'not a glb' >"$root/share/idview/assets/default.glb"
refused_installed installed-default-model "$root/share/idview/assets/default.glb"

# The worker: a stand-in that says who it is and exits, so the STEP load fails with its words.
worker=$root/libexec/idview/idview-load-worker
printf '#!/bin/sh\necho "the installed stand-in ran" >&2\nexit 1\n' >"$worker"
out=$("$installed" --headless --no-cache --frames 1 --size 64x48 --model "$step" 2>&1)
[[ $out == *"the installed stand-in ran"* ]] &&
    echo "ok   installed-worker: the STEP load ran $worker" ||
    fail "installed-worker: the STEP load did not run $worker: $(tail -2 <<<"$out")"

[[ $failures -eq 0 ]] && echo "all install checks passed"
exit $((failures > 0))
