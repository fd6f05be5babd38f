#!/usr/bin/env bash
# chart_test.sh ROOT BUILD - scripts/benchmark_chart.py on the committed H100 runs (the full runs
# and the re-run of the part-vertex techniques): it writes a PNG, and the ratios it prints are
# the JSON's ratio_to_floor for every technique it plots, a later file's row winning. Then
# scripts/path_chart.py on a committed camera-path run, scripts/lod_chart.py on the
# levels-of-detail runs, and scripts/fixed_cost_chart.py on the clear paths' runs, likewise.
# Then the generated parts of the docs: docs/benchmarks.md's tables are what
# scripts/bench_tables.py prints from the runs they cite (the culling rework's table checked
# against the JSON too), and the counts of tests in
# docs/testing.md and docs/reliability.md what scripts/test_counts.py finds in BUILD, and
# docs/cad.md's tables of big STEP files what scripts/cad_bench.py prints from its run.
set -uo pipefail
root=$1
build=$2
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
# scripts/path_chart.py on the committed dolly run: a PNG, and a line per renderer and mode
# whose medians and ratios are the JSON's rows (culling off, frustum, occlusion).
dolly=$root/docs/benchmarks/h100-2026-11-25-culling/dolly-1x.json
/usr/bin/python3 "$root/scripts/path_chart.py" "$dolly" -o "$work/path.png" \
    --renderer vertex-fs,mesh-fs >"$work/path.txt" 2>"$work/err.txt" ||
    fail "path chart script: $(cat "$work/err.txt")"
[[ $(head -c 8 "$work/path.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "no path PNG written"
/usr/bin/python3 - "$work/path.txt" "$dolly" <<'PY' || fail "path table does not match the JSON"
import json, sys
table, path = sys.argv[1], sys.argv[2]
by = {}
for row in json.load(open(path))["results"]:
    by.setdefault((row["renderer"], row["mode"]), {})[row["culling"]] = row["gpu_ms_median"]
lines = open(table).read().splitlines()[1:]
if len(lines) != len(by):
    sys.exit(f"{len(lines)} lines for {len(by)} renderer x mode pairs")
for line in lines:
    name, mode, off, frustum, fx, occlusion, ox = line.split()
    want = by[(name, mode)]
    for got, key in ((off, "off"), (frustum, "frustum"), (occlusion, "occlusion")):
        if abs(float(got) - want[key]) > 5.01e-4:
            sys.exit(f"{name} {mode} {key}: {got} != {want[key]}")
    for got, key in ((fx, "frustum"), (ox, "occlusion")):
        if abs(float(got) - want[key] / want["off"]) > 5.01e-4:
            sys.exit(f"{name} {mode} {key} ratio: {got}")
PY
# scripts/lod_chart.py on the committed levels-of-detail runs: a PNG, and per run the GPU ms,
# ratio to culling off and triangles drawn of vertex-fs with culling off, occlusion and
# occlusion with levels chosen at 1 px, as the JSON has them.
lod=$root/docs/benchmarks/h100-2026-11-25-lod
/usr/bin/python3 "$root/scripts/lod_chart.py" "$lod/view-1x.json" "$lod/copies16-4x.json" \
    "$lod/dolly-1x.json" -o "$work/lod.png" --renderer vertex-fs >"$work/lod.txt" \
    2>"$work/err.txt" || fail "lod chart script: $(cat "$work/err.txt")"
[[ $(head -c 8 "$work/lod.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "no levels-of-detail PNG written"
/usr/bin/python3 - "$work/lod.txt" "$lod/view-1x.json" "$lod/copies16-4x.json" \
    "$lod/dolly-1x.json" <<'PY' || fail "levels-of-detail table does not match the JSON"
import json, sys
table, paths = sys.argv[1], sys.argv[2:]
lines = open(table).read().splitlines()[1:]
if len(lines) != len(paths):
    sys.exit(f"{len(lines)} lines for {len(paths)} runs")
for line, path in zip(lines, paths):
    rows = [r for r in json.load(open(path))["results"]
            if r["renderer"] == "vertex-fs" and r["mode"] == "mdi-baseinstance"]
    off = next(r for r in rows if r["culling"] == "off")
    want = [off, next(r for r in rows if r["culling"] == "occlusion" and not r["lod_applied"]),
            next(r for r in rows if r["lod_applied"] and r["lod_error"] == 1)]
    got = line.split()[1:]
    if len(got) != 9:
        sys.exit(f"{path}: {line}")
    for k, row in enumerate(want):
        ms, ratio, tris = (float(x) for x in got[3 * k:3 * k + 3])
        if (abs(ms - row["gpu_ms_median"]) > 5.01e-4 or
                abs(ratio - row["gpu_ms_median"] / off["gpu_ms_median"]) > 5.01e-4 or
                abs(tris - row["triangles_drawn"] / 1e3) > 0.51):
            sys.exit(f"{path} column {k}: {got[3 * k:3 * k + 3]}")
PY
# scripts/fixed_cost_chart.py on the H100 runs of every technique (1x and 4x MSAA, culling
# off and occlusion, h100-2026-11-26-clear): a PNG, and per renderer (floors first) and run
# the fixed cost, the part above it and their sum as the JSON has them; a run from before the
# fixed cost is refused by name.
clearRuns=$root/docs/benchmarks/h100-2026-11-26-clear
fixedRuns=("$clearRuns/techniques-1x.json" "$clearRuns/techniques-4x.json")
/usr/bin/python3 "$root/scripts/fixed_cost_chart.py" "${fixedRuns[@]}" -o "$work/fixed.png" \
    >"$work/fixed.txt" 2>"$work/err.txt" || fail "fixed cost chart script: $(cat "$work/err.txt")"
[[ $(head -c 8 "$work/fixed.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "no fixed cost PNG written"
/usr/bin/python3 - "$work/fixed.txt" "${fixedRuns[@]}" <<'PY' || fail "fixed cost table does not match the JSON"
import json, sys
table, paths = sys.argv[1], sys.argv[2:]
runs = [json.load(open(p)) for p in paths]
names = []
for run in runs:
    for row in run["results"]:
        if (row["mode"] == "mdi-baseinstance" and row["culling"] == "occlusion" and
                row["renderer"] not in names):
            names.append(row["renderer"])
floors = {r["floor"] for run in runs for r in run["results"]}
names.sort(key=lambda n: n not in floors)
lines = open(table).read().splitlines()[1:]
if [l.split()[0] for l in lines] != names:
    sys.exit(f"renderers {[l.split()[0] for l in lines]} != {names}")
for line in lines:
    got = [float(x) for x in line.split()[1:]]
    for k, run in enumerate(runs):
        row = next(r for r in run["results"] if r["renderer"] == line.split()[0] and
                   r["mode"] == "mdi-baseinstance" and r["culling"] == "occlusion")
        want = [run["fixed_cost"]["gpu_ms_median"], row["above_fixed_ms"], row["gpu_ms_median"]]
        if any(abs(g - w) > 5.01e-4 for g, w in zip(got[3 * k:3 * k + 3], want)):
            sys.exit(f"{line} != {want}")
        if abs(want[0] + want[1] - want[2]) > 1.5e-4:
            sys.exit(f"{paths[k]}: fixed + above != median for {row['renderer']}")
PY
out=$(/usr/bin/python3 "$root/scripts/fixed_cost_chart.py" "${files[0]}" -o "$work/old.png" 2>&1)
[[ $? -ne 0 && $out == *"no fixed_cost"* && ! -e $work/old.png ]] ||
    fail "a run without a fixed cost: $out"
# Every table of docs/benchmarks.md is what scripts/bench_tables.py prints from the run folder
# it cites, and every run the tables read is one scripts/gpu-runs.sh makes.
/usr/bin/python3 "$root/scripts/bench_tables.py" --check "$root/docs/benchmarks.md" \
    >"$work/tables.txt" 2>&1 || fail "docs/benchmarks.md: $(cat "$work/tables.txt")"
# A copy of the page with one number of a table changed fails, naming the number.
sed '0,/^| empty frame (`--visible 0`) | [0-9.]*/s//| empty frame (`--visible 0`) | 9.999/' \
    "$root/docs/benchmarks.md" >"$work/changed.md"
cmp -s "$root/docs/benchmarks.md" "$work/changed.md" && fail "the page has no empty frame row to change"
out=$(/usr/bin/python3 "$root/scripts/bench_tables.py" --check "$work/changed.md" 2>&1)
[[ $? -ne 0 && $out == *"9.999"* ]] || fail "a changed table passed: $out"
# docs/census.md's tables are what scripts/census_table.py prints from the runs they cite; a
# changed number fails, naming it.
/usr/bin/python3 "$root/scripts/census_table.py" --check "$root/docs/census.md" \
    >"$work/census.txt" 2>&1 || fail "docs/census.md: $(cat "$work/census.txt")"
sed '0,/^| 162 x 1024² | [0-9.]*/s//| 162 x 1024² | 9.999/' "$root/docs/census.md" \
    >"$work/census-changed.md"
cmp -s "$root/docs/census.md" "$work/census-changed.md" && fail "docs/census.md has no 162 x 1024² row"
out=$(/usr/bin/python3 "$root/scripts/census_table.py" --check "$work/census-changed.md" 2>&1)
[[ $? -ne 0 && $out == *"9.999"* ]] || fail "a changed census table passed: $out"
# The culling rework's before-and-after table at the still view: every row's times, their
# ratio to culling off and now over before, and the triangles, from the two builds' JSON.
/usr/bin/python3 - "$root/docs/benchmarks.md" "$root/docs/benchmarks" <<'PY' || fail "the rework table does not match the JSON"
import json, re, sys
page, bench = sys.argv[1], sys.argv[2]
text = open(page).read()
marker = ("<!-- generated: bench_tables.py rework h100-2026-11-27-still "
          "before=h100-2026-11-27-before runs=techniques-1x,techniques-4x -->")
if marker not in text:
    sys.exit("no rework block at the still view")
block = text.split(marker, 1)[1].split("<!-- end generated -->", 1)[0]
runs = {(b, m): json.load(open(f"{bench}/h100-2026-11-27-{b}/techniques-{m}x.json"))
        for b in ("before", "still") for m in (1, 4)}
def find(run, name, mode, cull):
    hits = [r for r in run["results"] if r["renderer"] == name and r["mode"] == mode
            and r["culling"] == cull and r["lod_error"] == 0]
    return hits[0] if len(hits) == 1 else None
def tris(n):
    return f"{n / 1e6:.2f} M" if n >= 1e6 else f"{n / 1e3:.0f} k"
seen = 0
for line in block.splitlines():
    m = re.match(r"^\| `([a-z-]+)` \| ([a-z-]+), occlusion \| (.*) \|$", line)
    if not m:
        continue
    name, mode, cells = m.group(1), m.group(2), m.group(3).split(" | ")
    for k, msaa in enumerate((1, 4)):
        want = []
        for b in ("before", "still"):
            r, off = find(runs[(b, msaa)], name, mode, "occlusion"), \
                find(runs[(b, msaa)], name, mode, "off")
            want.append((r["gpu_ms_median"], r["gpu_ms_median"] / off["gpu_ms_median"],
                         r["triangles_drawn"]))
        got = cells[4 * k:4 * k + 4]
        exp = [f"{want[0][0]:.3f} ({want[0][1]:.3f})", f"{want[1][0]:.3f} ({want[1][1]:.3f})",
               f"**{want[1][0] / want[0][0]:.3f}**", f"{tris(want[0][2])} / {tris(want[1][2])}"]
        if got != exp:
            sys.exit(f"{name} {mode} {msaa}x: {got} != {exp}")
    seen += 1
if seen != 14:
    sys.exit(f"{seen} rows, not 7 renderers in 2 modes")
PY
# --write --from moves a table to the new folder, but a comparison stays with the two builds
# it compares.
cp "$root/docs/benchmarks.md" "$work/moved.md"
/usr/bin/python3 "$root/scripts/bench_tables.py" --write "$work/moved.md" \
    --from h100-2026-11-27-culling >"$work/moved.txt" 2>&1 || fail "--from: $(cat "$work/moved.txt")"
grep -q '^<!-- generated: bench_tables.py techniques h100-2026-11-27-culling msaa=1 -->$' \
    "$work/moved.md" || fail "--from did not move the techniques table"
grep -q '^<!-- generated: bench_tables.py rework h100-2026-11-27-still before=h100-2026-11-27-before runs=techniques-1x,techniques-4x -->$' \
    "$work/moved.md" || fail "--from moved the before-and-after table"
# docs/cad.md's tables of big STEP files are what scripts/cad_bench.py prints from the run it
# cites; a number changed in one of them fails.
/usr/bin/python3 "$root/scripts/cad_bench.py" --check "$root/docs/cad.md" >"$work/cad.txt" 2>&1 ||
    fail "docs/cad.md: $(cat "$work/cad.txt")"
sed '0,/^| | idview `--stats` | [0-9.]*/s//| | idview `--stats` | 9.999/' "$root/docs/cad.md" \
    >"$work/cad-changed.md"
cmp -s "$root/docs/cad.md" "$work/cad-changed.md" && fail "docs/cad.md has no idview row to change"
out=$(/usr/bin/python3 "$root/scripts/cad_bench.py" --check "$work/cad-changed.md" 2>&1)
[[ $? -ne 0 && $out == *"cad-changed.md"* ]] || fail "a changed CAD table passed: $out"
# The counts of tests in docs/testing.md and docs/reliability.md are the build's.
/usr/bin/python3 "$root/scripts/test_counts.py" --check "$build" >"$work/counts.txt" 2>&1 ||
    fail "test counts: $(cat "$work/counts.txt")"
cat "$work/counts.txt" # says so where this build cannot tell
echo "chart_test: $failures failed"
exit $((failures > 0))
