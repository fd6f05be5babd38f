#!/usr/bin/env bash
# memory_limit_test.sh IDVIEW - running out of memory is a refusal: idview --stats under an
# address-space limit (prlimit --as) that its start and the default model fit in, asked for
# levels of detail or copies that do not, exits 1 with one line naming the file and what did
# not fit, and never crashes (a std::bad_alloc on a worker thread used to end the process).
# Label `memory`: AddressSanitizer reserves terabytes of address space for its shadow memory,
# so no address-space limit can hold under it, and scripts/sanitize-tests.sh leaves the
# label out.
set -uo pipefail
idview=$1
if ! command -v prlimit >/dev/null; then
    echo "FAIL prlimit is needed: apt-get install util-linux"
    exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# under MIB FLAGS...: idview --stats under an address space of MIB MiB, no core file; its
# stderr in $work/err, its exit code returned. (The subshell keeps bash's own "Aborted" line
# out of the log: far below the limit found, tinygltf's parser can end the process, its
# std::bad_alloc crossing a function that may not throw.)
under() {
    local mib=$1
    shift
    (prlimit --as=$((mib << 20)) --core=0 "$idview" --stats "$@" >/dev/null 2>"$work/err"
        exit $?) 2>/dev/null
}

# What idview maps at start (its libraries, Open CASCADE's, their threads) differs from one
# machine to the next: the limit is found, to 8 MiB, as the smallest under which --stats
# opens the default model, then given 16 MiB more.
low=16 high=4096
under $high || { echo "FAIL: --stats fails under $high MiB: $(head -c 300 "$work/err")"; exit 1; }
while ((high - low > 8)); do
    middle=$(((low + high) / 2))
    if under $middle; then high=$middle; else low=$middle; fi
done
limit=$((high + 16))
echo "the default model opens under $high MiB of address space; the refusals run under $limit"

# refused WHAT PATTERN FLAGS...: under the limit, exit code 1 and one line matching PATTERN.
refused() {
    local what=$1 pattern=$2
    shift 2
    under $limit "$@"
    local rc=$?
    local lines
    lines=$(wc -l <"$work/err")
    if [[ $rc -eq 1 && $lines -eq 1 ]] && grep -Eq "$pattern" "$work/err"; then
        echo "ok: $what: $(cat "$work/err")"
    else
        echo "FAIL: $what: exit code $rc, $lines lines, expected one matching '$pattern':"
        head -c 1000 "$work/err"
        failures=$((failures + 1))
    fi
}

# Four levels of detail take meshoptimizer's buffers on every hardware thread.
refused "levels of detail" \
    '^idview: error: .*default\.glb: out of memory building 4 levels of detail of 22 geometries$' \
    --lod-levels 4
# 500 copies: 1,130,000 objects, some 300 MB for their placements, names and paths alone.
refused "copies" \
    '^idview: error: .*default\.glb: out of memory making 500 copies \(1,130,000 objects\)$' \
    --copies 500
((failures == 0)) && echo "memory_limit_test: all passed" || echo "memory_limit_test: $failures failed"
((failures == 0))
