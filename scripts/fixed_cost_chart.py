#!/usr/bin/python3
"""fixed_cost_chart.py - each technique's GPU time split into the frame's fixed cost (a frame
that draws nothing) and what drawing adds above it, per MSAA setting, as a stacked bar chart
(PNG) and a table (stdout), from the JSON that `idview --benchmark --benchmark-out` writes.

    scripts/fixed_cost_chart.py RUN.json... -o chart.png [--mode mdi-baseinstance]
        [--culling occlusion] [--lod-error 0]

Runs are grouped by their MSAA setting, side by side within each technique; where several
runs have the same setting, a later file's rows (and fixed cost) replace an earlier one's.
A bar's lower part is the run's fixed_cost gpu_ms_median (the clears and resolve, which no
culling or level of detail touches), its upper part the row's above_fixed_ms; together they
are the row's gpu_ms_median. The floors are plotted too (they are what a technique is
measured against). Files written before the fixed cost existed are refused.
"""
import argparse
import json
import sys


def load(path, mode, culling, lod_error):
    with open(path) as f:
        run = json.load(f)
    if "fixed_cost" not in run:
        sys.exit(f"{path}: no fixed_cost (a run from before the fixed-cost row)")
    rows = {}
    for row in run["results"]:
        if (row["mode"] == mode and row["culling"] == culling and
                abs(row["lod_error"] - lod_error) < 1e-6):
            rows[row["renderer"]] = row
    return run, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="benchmark JSON files, one per MSAA setting")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--mode", default="mdi-baseinstance", help="per-draw mode to plot")
    parser.add_argument("--culling", default="occlusion", help="culling mode to plot")
    parser.add_argument("--lod-error", type=float, default=0.0,
                        help="the rows' --lod-error, in pixels")
    args = parser.parse_args()

    fixed = {}   # msaa -> the fixed cost's gpu_ms_median, later files winning
    clear = {}   # msaa -> the clear path that ran
    by_msaa = {}  # msaa -> renderer -> row
    names = []   # floors first, then techniques, in the order the files list them
    runs = [load(path, args.mode, args.culling, args.lod_error) for path in args.runs]
    for run, rows in runs:
        msaa = run["settings"]["msaa"]
        fixed[msaa] = run["fixed_cost"]["gpu_ms_median"]
        clear[msaa] = run.get("clear_path", "pass")
        by_msaa.setdefault(msaa, {}).update(rows)
        for name, row in rows.items():
            if name not in names:
                names.append(name)
    floors = {row["floor"] for rows in by_msaa.values() for row in rows.values()}
    names.sort(key=lambda n: n not in floors)  # stable: the files' order within each group
    if not names:
        sys.exit(f"no rows in mode {args.mode}, culling {args.culling}, "
                 f"LOD error {args.lod_error:g}")

    msaas = sorted(by_msaa)
    nan = float("nan")

    def cell(msaa, name):
        row = by_msaa[msaa].get(name)
        return (nan, nan, nan) if row is None else (
            fixed[msaa], row["above_fixed_ms"], row["gpu_ms_median"])

    print(f"{'renderer':<16}" + "".join(
        f"{f'{m}x fixed':>10}{f'{m}x above':>10}{f'{m}x total':>10}" for m in msaas))
    for name in names:
        print(f"{name:<16}" + "".join(
            "".join(f"{v:>10.3f}" for v in cell(m, name)) for m in msaas))

    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    width = 0.8 / len(msaas)
    fig, ax = plt.subplots(figsize=(11, 4.8), dpi=110)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, msaa in enumerate(msaas):
        xs = [i + (k - (len(msaas) - 1) / 2) * width for i in range(len(names))]
        cells = [cell(msaa, n) for n in names]
        ax.bar(xs, [c[0] for c in cells], width, color="0.75", edgecolor=colours[k % 10],
               hatch="//", label=f"{msaa}x fixed cost ({clear[msaa]} clear)")
        bars = ax.bar(xs, [c[1] for c in cells], width, bottom=[c[0] for c in cells],
                      color=colours[k % 10], label=f"{msaa}x above the fixed cost")
        ax.bar_label(bars, labels=[f"{c[2]:.2f}" for c in cells], fontsize=7, padding=2)
    ax.set_xticks(range(len(names)), names, rotation=20, ha="right")
    ax.set_ylabel("GPU ms (median)")
    first = runs[0][0]
    s = first["settings"]
    ax.set_title(f"{first['device']['name']}, {s['size']}, {s['scene']} x{s['copies']}, "
                 f"{args.mode}, culling {args.culling}, LOD error {args.lod_error:g} px\n"
                 "a frame that draws nothing (hatched) and what drawing adds above it",
                 fontsize=9)
    top = max((c for m in msaas for n in names for c in cell(m, n)[2:] if c == c), default=1)
    ax.set_ylim(0, top * 1.25)  # room for the legend above the tallest bar
    ax.legend(fontsize=8, ncol=len(msaas), loc="upper left")
    fig.tight_layout()
    fig.savefig(args.output)


if __name__ == "__main__":
    main()
