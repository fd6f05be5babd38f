# cli_lib.sh IDVIEW LAVAPIPE_ICD - what the command-line tests share, sourced by them with
# their arguments: the lavapipe environment (ctest passes the ICD of build/lavapipe-25, Mesa
# 25, and sets LD_LIBRARY_PATH to its lib folder for the newer libdrm), a work folder that
# holds the CAD cache (never the cache of the user running the test), and fail().
source "$(dirname "${BASH_SOURCE[0]}")/work_lib.sh"
idview=$1
icd=$2
export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd
export XDG_CACHE_HOME=$work/xdg-cache-home
