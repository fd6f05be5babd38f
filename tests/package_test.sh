#!/usr/bin/env bash
# package_test.sh BUILD VERSION LAVAPIPE_ICD - the Debian package as `cpack -G DEB` makes it
# from BUILD (written here into a work folder, so the build's own package is left alone): its
# name, the files it installs, its control fields (Depends from dpkg-shlibdeps), lintian with no
# error, and the program unpacked as dpkg puts it, run from there.
source "$(dirname "$0")/work_lib.sh"
build=$1
version=$2
icd=$3

if ! (cd "$build" && cpack -G DEB -B "$work" >"$work/cpack.log" 2>&1); then
    fail "cpack -G DEB: $(tail -5 "$work/cpack.log")"
    exit 1
fi
deb=$work/idview_${version}_$(dpkg --print-architecture).deb
[[ -f $deb ]] || { fail "no $(basename "$deb"): $(ls "$work")"; exit 1; }
echo "ok   $(basename "$deb"), $(stat -c %s "$deb") bytes"

files=$(dpkg-deb -c "$deb" | awk '{print $6}')
for file in ./usr/bin/idview ./usr/bin/idview-step-copies ./usr/libexec/idview/idview-load-worker \
    ./usr/share/idview/shaders/shared.h ./usr/share/idview/shaders/scene.vert \
    ./usr/share/idview/assets/default.glb ./usr/share/doc/idview/copyright \
    ./usr/share/doc/idview/changelog.gz; do
    grep -qxF "$file" <<<"$files" && echo "ok   has $file" || fail "no $file in the package"
done
# Nothing outside /usr, nothing of the build or the source tree.
outside=$(grep -vE '^\./(usr/.*)?$' <<<"$files")
[[ -z $outside ]] && echo "ok   everything under /usr" || fail "outside /usr: $outside"

field() { dpkg-deb -f "$deb" "$1"; }
[[ $(field Package) == idview ]] && echo "ok   Package: idview" || fail "Package: $(field Package)"
[[ $(field Version) == "$version" ]] && echo "ok   Version: $version" ||
    fail "Version: '$(field Version)', the project's is $version"
[[ $(field Section) == graphics ]] && echo "ok   Section: graphics" || fail "Section: $(field Section)"
[[ -n $(field Maintainer) ]] || fail "no Maintainer"
depends=$(field Depends)
for library in libvulkan1 libglfw3 libc6 libstdc++6; do
    [[ $depends =~ (^|, )"$library"( |,|$) ]] && echo "ok   Depends: $library" ||
        fail "Depends has no $library: '$depends'"
done
recommends=$(field Recommends)
for package in zenity mesa-vulkan-drivers; do
    [[ $recommends == *"$package"* ]] && echo "ok   Recommends: $package" ||
        fail "Recommends has no $package: '$recommends'"
done

# lintian: no E: line (its warnings are listed in docs/install.md).
if ! command -v lintian >/dev/null; then
    fail "lintian is not installed (Debian package lintian; scripts/setup.sh test installs it)"
else
    lintian --tag-display-limit 0 "$deb" >"$work/lintian.log" 2>&1
    errors=$(grep '^E: ' "$work/lintian.log")
    [[ -z $errors ]] && echo "ok   lintian: no errors ($(grep -c '^W: ' "$work/lintian.log") warnings)" ||
        fail "lintian errors:"$'\n'"$errors"
fi

# The package's files as dpkg unpacks them, run from there: its version line, and a headless
# frame of a STEP file through the packaged load worker, shaders and default settings.
dpkg-deb -x "$deb" "$work/root"
installed=$work/root/usr/bin/idview
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd XDG_CACHE_HOME=$work/cache \
    XDG_CONFIG_HOME=$work/config
line=$("$installed" --version 2>&1)
[[ $line == "idview $version ("*")" ]] && echo "ok   unpacked: $line" ||
    fail "unpacked --version: '$line'"
step=/usr/share/opencascade/data/step/screw.step
if "$installed" --headless --model "$step" --frames 1 --stats >"$work/stats.json" 2>"$work/err" &&
    [[ $(jq -r .parts "$work/stats.json") == 10 ]]; then
    echo "ok   unpacked: screw.step drawn headless, 10 parts"
else
    fail "unpacked headless run: $(head -c 400 "$work/err")"
fi

[[ $failures -eq 0 ]] && echo "all package checks passed"
exit $((failures > 0))
