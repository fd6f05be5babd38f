#!/usr/bin/python3
"""path_chart.py - GPU time of every frame along a camera path, one line per culling mode (and
level-of-detail error, where levels were chosen), as a chart (PNG), and each one's median
against culling off as a table (stdout),
from the JSON that `idview --benchmark --camera-path PATH --benchmark-out` writes.

    scripts/path_chart.py RUN.json -o chart.png [--renderer vertex-fs,mesh-fs] [--mode M]

The table has a line per renderer and mode of the run: its median frame with culling off,
then per culling mode the median frame and its ratio to off (ratio of the medians, the rows'
gpu_ms_median). The chart draws the frames' times (gpu_ms_frames) of the chosen renderers in
one mode, a panel each.
"""
import argparse
import json
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="benchmark JSON written with --camera-path")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--renderer", default="vertex-fs,mesh-fs",
                        help="comma list of renderers to plot, a panel each")
    parser.add_argument("--mode", default="mdi-baseinstance", help="per-draw mode to plot")
    args = parser.parse_args()

    with open(args.run) as f:
        run = json.load(f)
    s = run["settings"]
    if s.get("camera_path", "none") == "none":
        sys.exit(f"{args.run}: not a camera path run (settings.camera_path)")
    rows = {}  # (renderer, mode) -> setting -> row, in the file's order
    cullings = []  # the settings: culling modes, with the error where levels were chosen
    for row in run["results"]:
        setting = row["culling"]
        if row.get("lod_applied"):
            setting += f"+LOD{row['lod_error']:g}px"
        rows.setdefault((row["renderer"], row["mode"]), {})[setting] = row
        if setting not in cullings:
            cullings.append(setting)
    others = [c for c in cullings if c != "off"]

    print(f"{'renderer':<16}{'mode':<18}{'off ms':>8}" +
          "".join(f"{c + ' ms':>{max(14, len(c) + 5)}}{'x off':>7}" for c in others))
    for (renderer, mode), by in rows.items():
        if "off" not in by:
            continue
        off = by["off"]["gpu_ms_median"]
        line = f"{renderer:<16}{mode:<18}{off:>8.3f}"
        for c in others:
            ms = by[c]["gpu_ms_median"] if c in by else float("nan")
            line += f"{ms:>{max(14, len(c) + 5)}.3f}{ms / off:>7.3f}"
        print(line)

    names = [n for n in args.renderer.split(",") if (n, args.mode) in rows]
    if not names:
        sys.exit(f"none of {args.renderer} in mode {args.mode}")

    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(names), figsize=(5.5 * len(names), 4.2), dpi=110,
                             sharey=True, squeeze=False)
    for ax, name in zip(axes[0], names):
        for culling, row in rows[(name, args.mode)].items():
            frames = row.get("gpu_ms_frames")
            if not frames:
                continue
            ax.plot(range(len(frames)), frames, linewidth=1.2,
                    label=f"{culling} (median {row['gpu_ms_median']:.2f} ms)")
        ax.set_title(f"{name} + {args.mode}", fontsize=9)
        ax.set_xlabel(f"frame of the {s['camera_path']} path")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("scene pass GPU ms")
    fig.suptitle(f"{run['device']['name']}, {s['size']}, {s['msaa']}x MSAA, {s['scene']} "
                 f"x{s['copies']}: GPU time along the {s['camera_path']} path", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output)


if __name__ == "__main__":
    main()
