#!/usr/bin/python3
"""lod_chart.py - what culling and levels of detail take off a frame: for one renderer and
mode, the GPU time and the triangles drawn with culling off, with occlusion culling, and with
occlusion culling and each level-of-detail error the runs hold, as a chart (PNG) of two
panels, and as a table (stdout), from JSON that `idview --benchmark --lod-error 0,1
--benchmark-out` writes (one file per view, MSAA or copy count).

    scripts/lod_chart.py RUN.json... -o chart.png [--renderer vertex-fs] [--mode M]

The table has a line per run: its label (size of the view, copies, MSAA, camera path), then
per setting the median GPU ms, its ratio to culling off and the median triangles drawn (in
thousands), the rows' gpu_ms_median and triangles_drawn. Camera paths give medians over the
path's frames.
"""
import argparse
import json
import sys


def label(run):
    s = run["settings"]
    text = f"x{s['copies']} {s['msaa']}x"
    if s.get("camera_path", "none") != "none":
        text += f" {s['camera_path']}"
    return text


def setting(row):
    """The column a row belongs to: its culling, and the error where levels were chosen."""
    if row.get("lod_applied"):
        return f"{row['culling']} + LOD {row['lod_error']:g} px"
    return row["culling"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="benchmark JSON files")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--renderer", default="vertex-fs", help="the renderer to show")
    parser.add_argument("--mode", default="mdi-baseinstance", help="its per-draw mode")
    args = parser.parse_args()

    runs = []  # (label, {setting: row})
    settings = []
    for path in args.runs:
        with open(path) as f:
            run = json.load(f)
        by = {}
        for row in run["results"]:
            if row["renderer"] != args.renderer or row["mode"] != args.mode:
                continue
            by[setting(row)] = row
            if setting(row) not in settings:
                settings.append(setting(row))
        if "off" not in by:
            sys.exit(f"{path}: no {args.renderer} + {args.mode} row with culling off")
        runs.append((label(run), by))

    print(f"{'run':<18}" + "".join(f"{s.replace(' ', ''):>24}" for s in settings))
    for name, by in runs:
        off = by["off"]["gpu_ms_median"]
        line = f"{name.replace(' ', '_'):<18}"
        for s in settings:
            row = by.get(s)
            if row is None:
                line += f"{'-':>24}"
                continue
            ms = row["gpu_ms_median"]
            line += f"{ms:>9.3f}{ms / off:>7.3f}{row['triangles_drawn'] / 1e3:>8.0f}"
        print(line)

    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    fig, (time_ax, tri_ax) = plt.subplots(1, 2, figsize=(12, 4.4), dpi=110)
    width = 0.8 / len(settings)
    for k, s in enumerate(settings):
        xs = [i + (k - (len(settings) - 1) / 2) * width for i in range(len(runs))]
        ms = [by[s]["gpu_ms_median"] if s in by else 0 for _, by in runs]
        tris = [by[s]["triangles_drawn"] / 1e6 if s in by else 0 for _, by in runs]
        time_ax.bar(xs, ms, width, label=s)
        tri_ax.bar(xs, tris, width, label=s)
        for x, (_, by) in zip(xs, runs):
            if s in by and s != "off":
                ratio = by[s]["gpu_ms_median"] / by["off"]["gpu_ms_median"]
                time_ax.annotate(f"{ratio:.2f}x", (x, by[s]["gpu_ms_median"]), ha="center",
                                 va="bottom", fontsize=6)
    for ax, title in ((time_ax, "scene pass GPU ms (median)"),
                      (tri_ax, "triangles drawn, millions (median, log scale)")):
        ax.set_xticks(range(len(runs)))
        ax.set_xticklabels([name for name, _ in runs], fontsize=8)
        ax.set_title(title, fontsize=9)
        ax.grid(axis="y", alpha=0.3)
    tri_ax.set_yscale("log")  # culling off draws tens of times what the others do
    time_ax.legend(fontsize=7)
    first = json.load(open(args.runs[0]))
    fig.suptitle(f"{first['device']['name']}, {first['settings']['size']}, "
                 f"{args.renderer} + {args.mode}: culling and levels of detail", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output)


if __name__ == "__main__":
    main()
