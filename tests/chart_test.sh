#!/usr/bin/env bash
# chart_test.sh ROOT - scripts/benchmark_chart.py on the committed H100 runs (the full runs and
# the re-run of the part-vertex techniques): it writes a PNG, and the ratios it prints are the
# JSON's ratio_to_floor for every technique it plots, a later file's row winning.
set -uo pipefail
root=$1
runs=$root/docs/benchmarks/h100-2026-11-23-issue14/final
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

files=("$runs/defaults-1x.json" "$runs/defaults-4x.json" "$runs/part-vertices-1x.json"
    "$runs/part-vertices-4x.json")
/usr/bin/python3 "$root/scripts/benchmark_chart.py" "${files[@]}" -o "$work/chart.png" \
    >"$work/table.txt" 2>"$work/err.txt" || fail "chart script: $(cat "$work/err.txt")"
[[ $(head -c 8 "$work/chart.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "no PNG written"
# Every non-floor renderer in mdi-baseinstance with its 1x and 4x ratios, the re-run's where
# it has the renderer, and nothing else.
/usr/bin/python3 - "$work/table.txt" "${files[@]}" <<'PY' || fail "table does not match the JSON"
import json, sys
table, paths = sys.argv[1], sys.argv[2:]
want = {}
for path in paths:
    run = json.load(open(path))
    k = 0 if run["settings"]["msaa"] == 1 else 1
    for row in run["results"]:
        if row["mode"] == "mdi-baseinstance" and row["renderer"] != row["floor"]:
            want.setdefault(row["renderer"], [None, None])[k] = row["ratio_to_floor"]
got = {}
for line in open(table).read().splitlines()[1:]:
    name, one, four, floor = line.split()
    got[name] = [float(one), float(four)]
if got != want:
    sys.exit(f"table {got} != JSON {want}")
PY
echo "chart_test: $failures failed"
exit $((failures > 0))
