#!/usr/bin/python3
"""benchmark_chart.py - each technique's GPU time over its floor, per MSAA setting, as a
bar chart (PNG) and a table (stdout), from the JSON that `idview --benchmark --benchmark-out`
writes.

    scripts/benchmark_chart.py RUN.json... -o chart.png [--mode mdi-baseinstance]

Runs are grouped by their MSAA setting, one bar colour each; where several runs have the same
setting, a later file's rows replace an earlier one's for the same renderer and mode (a
re-run of some techniques). Each bar is gpu_ms_median / the floor's gpu_ms_median in the
same mode and run (the JSON's ratio_to_floor; older files carry ratio_to_no_id). The dashed
line marks 1.02, the target of issue 14 for the techniques without gl_PrimitiveID.
"""
import argparse
import json
import sys


def load(path):
    with open(path) as f:
        run = json.load(f)
    rows = {}
    for row in run["results"]:
        ratio = row.get("ratio_to_floor", row.get("ratio_to_no_id"))
        rows[(row["renderer"], row["mode"])] = (ratio, row.get("floor", "no-id"), row)
    return run, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="benchmark JSON files, one per MSAA setting")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--mode", default="mdi-baseinstance", help="per-draw mode to plot")
    parser.add_argument("--target", type=float, default=1.02, help="dashed line (0: none)")
    args = parser.parse_args()

    runs = [load(path) for path in args.runs]
    by_msaa = {}  # msaa -> (renderer, mode) -> (ratio, floor, row), later files winning
    names = []    # techniques in the order the files list them, floors left out
    for run, rows in runs:
        by_msaa.setdefault(run["settings"]["msaa"], {}).update(rows)
        for (renderer, mode), (ratio, floor, _) in rows.items():
            if mode == args.mode and renderer != floor and renderer not in names:
                names.append(renderer)
    if not names:
        sys.exit(f"no rows in mode {args.mode}")

    labels = [f"{msaa}x MSAA" for msaa in sorted(by_msaa)]
    series = [[by_msaa[msaa].get((n, args.mode), (float("nan"),))[0] for n in names]
              for msaa in sorted(by_msaa)]
    floors = {n: next(rows[(n, args.mode)][1] for rows in by_msaa.values() if (n, args.mode) in rows)
              for n in names}

    print(f"{'renderer':<16}" + "".join(f"{label:>12}" for label in labels) + "  floor")
    for i, name in enumerate(names):
        print(f"{name:<16}" + "".join(f"{values[i]:>12.3f}" for values in series) +
              f"  {floors[name]}")

    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    width = 0.8 / len(series)
    fig, ax = plt.subplots(figsize=(11, 4.8), dpi=110)
    for k, (label, values) in enumerate(zip(labels, series)):
        xs = [i + (k - (len(series) - 1) / 2) * width for i in range(len(names))]
        bars = ax.bar(xs, values, width, label=label)
        ax.bar_label(bars, fmt="%.2f", fontsize=7, padding=2)
    ax.axhline(1.0, color="black", linewidth=0.8)
    if args.target:
        ax.axhline(args.target, color="grey", linestyle="--", linewidth=0.8,
                   label=f"{args.target:.2f}x target")
    ax.set_xticks(range(len(names)), names, rotation=20, ha="right")
    ax.set_ylabel("GPU time / floor (same mode, same run)")
    low = min(min(v) for v in series)
    ax.set_ylim(min(0.9, low - 0.05), max(max(v) for v in series) + 0.1)
    device = runs[0][0]["device"]["name"]
    s = runs[0][0]["settings"]
    ax.set_title(f"{device}, {s['size']}, {s['scene']} x{s['copies']}, {args.mode}: "
                 "each technique against its floor (no-id, or no-id-mesh for mesh shaders)",
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output)


if __name__ == "__main__":
    main()
