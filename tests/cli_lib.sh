# cli_lib.sh IDVIEW LAVAPIPE_ICD - what the command-line tests share, sourced by them with
# their arguments: the lavapipe environment (ctest passes the ICD of build/lavapipe-25, Mesa
# 25, and sets LD_LIBRARY_PATH to its lib folder for the newer libdrm), a work folder that
# holds the CAD cache (never the cache of the user running the test), and fail().
set -uo pipefail
idview=$1
icd=$2
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd
work=$(mktemp -d)
export XDG_CACHE_HOME=$work/xdg-cache-home
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
    echo "FAIL $1"
    failures=$((failures + 1))
}
