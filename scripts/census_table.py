#!/usr/bin/env python3
"""census_table.py --write|--check PAGE - the tables of docs/census.md, printed from the run
folder each names: a block opens with
    <!-- generated: census_table.py TABLE FOLDER -->
and ends with <!-- end generated -->; FOLDER lies in docs/benchmarks/ and holds what
scripts/census-gpu-runs.sh wrote. TABLE is one of: scale (views x size on the default
model), techniques (162x1024 per configuration), models (each model's answer and time).
--write puts what the runs give between the markers; --check fails naming the first
difference. Every time is the median of a census's three runs (the first warms up)."""
import json
import os
import re
import statistics
import sys

BENCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "benchmarks")


def load(folder, name):
    with open(os.path.join(BENCH, folder, name + ".json")) as f:
        return json.load(f)


def median(values):
    return statistics.median(values)


def per_view(run):
    return median(run["ms"]) / run["census_views"]


def scale(folder):
    empty = load(folder, "empty")
    floor = per_view(empty)
    rows = ["| views x size | census ms | per view ms | above the empty view ms | "
            "scene passes ms (GPU) |", "|---|---|---|---|---|"]
    for views in (42, 162, 642):
        for size in (512, 1024, 2048):
            run = load(folder, f"scale-{views}x{size}")
            ms = median(run["ms"])
            rows.append(f"| {views} x {size}² | {ms:.1f} | {ms / views:.3f} | "
                        f"{ms / views - floor:.3f} | {median(run['scene_pass_gpu_ms']):.1f} |")
    rows.append(f"| 162 x 1024², a scene of {empty['triangles']} triangles (the empty "
                f"view) | {median(empty['ms']):.1f} | {floor:.3f} | 0 | "
                f"{median(empty['scene_pass_gpu_ms']):.1f} |")
    return rows


TECHNIQUES = ["visbuffer-compute", "visbuffer", "vertex-fs", "mesh-fs", "per-draw", "no-id"]


def techniques(folder):
    rows = ["| drawn with | census ms | per view ms | scene passes ms (GPU) |",
            "|---|---|---|---|"]
    for name in TECHNIQUES:
        run = load(folder, f"tech-{name}")
        ms = median(run["ms"])
        rows.append(f"| {run['pipeline']} | {ms:.1f} | {ms / run['census_views']:.3f} | "
                    f"{median(run['scene_pass_gpu_ms']):.1f} |")
    return rows


MODELS = [("default", "default model (`assets/default.glb`)"), ("Motor-c", "Motor-c.brep"),
          ("video", "KiCad board `video.step`")]


def models(folder):
    rows = ["| model | triangles | parts | never seen | solids or objects never seen | "
            "triangles never seen | census ms |", "|---|---|---|---|---|---|---|"]
    for name, title in MODELS:
        answer = load(folder, f"answers-{name}")
        timed = load(folder, "scale-162x1024" if name == "default" else f"time-{name}")
        rows.append(f"| {title} | {answer['triangles']:,} | {answer['parts']:,} | "
                    f"{answer['parts_never_seen']:,} | {answer['objects_never_seen']} of "
                    f"{answer['objects']:,} | {answer['triangle_share_never_seen'] * 100:.1f} % | "
                    f"{median(timed['ms']):.1f} |")
    return rows


TABLES = {"scale": scale, "techniques": techniques, "models": models}
OPEN = re.compile(r"^<!-- generated: census_table\.py (\w+) ([\w.-]+) -->$")


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("--write", "--check"):
        sys.exit(__doc__)
    mode, page = sys.argv[1:]
    lines = open(page).read().split("\n")
    out, i, blocks = [], 0, 0
    while i < len(lines):
        out.append(lines[i])
        m = OPEN.match(lines[i])
        i += 1
        if not m:
            continue
        end = lines.index("<!-- end generated -->", i)
        want = TABLES[m.group(1)](m.group(2))
        have = lines[i:end]
        if mode == "--check" and have != want:
            diff = next((h, w) for h, w in zip(have + [""] * len(want), want + [""] * len(have))
                        if h != w)
            sys.exit(f"{page}: the {m.group(1)} table differs from the runs:\n  page: {diff[0]}\n"
                     f"  runs: {diff[1]}")
        out.extend(want)
        i, blocks = end, blocks + 1
    if blocks == 0:
        sys.exit(f"{page}: no generated census table")
    if mode == "--write":
        open(page, "w").write("\n".join(out))


if __name__ == "__main__":
    main()
