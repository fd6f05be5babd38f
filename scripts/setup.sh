#!/usr/bin/env bash
# setup.sh run|test [ARGS...] - the two commands of the README.
# Installs the Debian 12 packages idview needs (only the missing ones, so a second call is
# quick), configures and builds Release in build/, then
#   run:  starts idview on the default scene (ARGS are passed to it);
#   test: runs the whole ctest suite on lavapipe, Mesa's CPU Vulkan driver.
# The tests use lavapipe from Mesa 25, which scripts/fetch-lavapipe.sh unpacks into
# build/lavapipe-25 (once; nothing is installed and apt's sources stay as they are).
set -euo pipefail
cd "$(dirname "$0")/.."

what=${1:-}
case $what in
run | test) shift ;;
*)
    echo "usage: scripts/setup.sh run|test [ARGS...]" >&2
    exit 2
    ;;
esac

# Build-time libraries, then what running and testing need. mesa-vulkan-drivers brings
# lavapipe, so idview has a Vulkan device even on a machine without a GPU driver, and the
# libraries (libLLVM-15...) that the tests' Mesa 25 lavapipe links too.
# Open CASCADE for STEP/IGES/BREP: the data-exchange package pulls in the other libocct-*-dev
# ones; libtbb-dev only for the libtbb.so symlink that Debian's OCCT CMake config names.
packages=(cmake g++ make pkg-config libglfw3-dev libglm-dev glslang-dev glslang-tools libtinygltf-dev
    libimgui-dev libvulkan-dev libstb-dev libmeshoptimizer-dev mesa-vulkan-drivers
    libocct-data-exchange-dev libocct-ocaf-dev libocct-modeling-algorithms-dev libtbb-dev
    libportal-dev) # Open...: the desktop portal's file chooser (optional to the build)
if [[ $what == test ]]; then
    # occt-misc: the STEP, IGES and BREP samples the CAD loader tests read; xdotool: the viewer
    # tests' real input; jq: the viewer tests read the event records by field; lintian: the
    # Debian package's check (tests/package_test.sh); desktop-file-utils, shared-mime-info,
    # libglib2.0-bin (gio): the desktop files' tests validate the launcher and ask the MIME
    # database each sample's type.
    packages+=(vulkan-validationlayers xvfb xauth googletest libgtest-dev assimp-testmodels clang
        libclang-rt-14-dev python3-matplotlib occt-misc xdotool jq lintian desktop-file-utils
        shared-mime-info libglib2.0-bin)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}"
    sudo=()
    [[ $(id -u) -ne 0 ]] && sudo=(sudo)
    "${sudo[@]}" apt-get update -qq
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        "${missing[@]}"
fi

scripts/fetch-lavapipe.sh
[[ -f build/CMakeCache.txt ]] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"

if [[ $what == run ]]; then
    exec build/idview "$@"
fi
(cd build && ctest --output-on-failure -j"$(nproc)" "$@")
# Then the unit and lavapipe tests again under ASan + UBSan + LeakSanitizer, in build-asan/.
# Only for the whole suite (CI): with ctest arguments, run scripts/sanitize-tests.sh yourself.
if (($#)); then
    echo "setup: ctest arguments given, sanitizer pass skipped (scripts/sanitize-tests.sh)"
    exit 0
fi
exec scripts/sanitize-tests.sh
