# work_lib.sh - what every shell test starts with, sourced first: strict pipes, a work folder
# removed at exit, and fail(), which counts failures for the test's exit code.
set -uo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
    echo "FAIL $1"
    failures=$((failures + 1))
}
