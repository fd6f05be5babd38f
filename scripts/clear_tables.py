#!/usr/bin/python3
"""clear_tables.py - the Markdown tables of docs/benchmarks.md's "The frame's fixed cost"
section, printed from the JSON that `idview --benchmark --benchmark-out` wrote, so the page
repeats the runs and nothing else.

    scripts/clear_tables.py targets FOLDER
        FOLDER holds {view,motor}-{1,4}-{auto,pass,compute}.json: the target configurations
        (vertex-fs + mdi-baseinstance, culling off and occlusion, LOD error 0 and 1) on the
        benchmark view and Motor-c.brep, each MSAA setting on each clear path.
    scripts/clear_tables.py techniques RUN-1x.json RUN-4x.json
        every technique against its floor, one table per run: culling off in each mode,
        occlusion in mdi-baseinstance, and occlusion over culling off.
"""
import json
import os
import sys


def load(path):
    with open(path) as f:
        run = json.load(f)
    if "fixed_cost" not in run:
        sys.exit(f"{path}: no fixed_cost (a run from before the fixed-cost row)")
    return run


def row(run, renderer, mode, culling, lod):
    for r in run["results"]:
        if (r["renderer"], r["mode"], r["culling"]) == (renderer, mode, culling) and \
                abs(r["lod_error"] - lod) < 1e-6:
            return r
    sys.exit(f"no row {renderer} + {mode}, culling {culling}, LOD error {lod}")


def cell(ms, fixed):
    return f"{ms:.3f} ({ms - fixed:.3f})"


def targets(folder):
    # (what, file stem, renderer, culling, LOD error, target ms at 1x and 4x)
    lines = [
        ("empty frame (`--visible 0`)", "view", None, None, None, {1: 0.35, 4: 1.2}),
        ("benchmark view, `vertex-fs`, occlusion + LOD 1 px", "view", "vertex-fs",
         "occlusion", 1.0, {1: 1.4, 4: 3.2}),
        ("benchmark view, `no-id` floor, occlusion + LOD 1 px", "view", "no-id",
         "occlusion", 1.0, None),
        ("Motor-c.brep, `no-id` floor, culling off", "motor", "no-id", "off", 0.0,
         {1: 0.6, 4: 2.1}),
        ("Motor-c.brep, `vertex-fs`, culling off", "motor", "vertex-fs", "off", 0.0, None),
        ("Motor-c.brep, `vertex-fs`, occlusion + LOD 1 px", "motor", "vertex-fs", "occlusion",
         1.0, None),
    ]
    for msaa in (1, 4):
        runs = {(stem, p): load(os.path.join(folder, f"{stem}-{msaa}-{p}.json"))
                for stem in ("view", "motor") for p in ("auto", "pass", "compute")}
        auto = runs[("view", "auto")]
        timing = auto["clear_timing"]
        print(f"**{msaa}x MSAA.** `--clear auto` ran the {auto['clear_path']} path (an empty "
              f"1920x1080 frame timed at {timing['pass_ms']:.3f} ms on the pass path, "
              f"{timing['compute_ms']:.3f} ms on the compute path). GPU ms, and in brackets "
              "above that run's empty frame:\n")
        print("| frame | pass path | compute path | `--clear auto` | target (auto) |")
        print("|---|---:|---:|---:|---:|")
        for what, stem, renderer, culling, lod, target in lines:
            cells = []
            for p in ("pass", "compute", "auto"):
                run = runs[(stem, p)]
                fixed = run["fixed_cost"]["gpu_ms_median"]
                ms = fixed if renderer is None else \
                    row(run, renderer, "mdi-baseinstance", culling, lod)["gpu_ms_median"]
                cells.append((ms, fixed))
            goal = "" if target is None else \
                f"<= {target[msaa]} ({'met' if cells[2][0] <= target[msaa] else 'missed'})"
            print(f"| {what} | " + " | ".join(cell(*c) for c in cells) + f" | {goal} |")
        print()


def techniques(paths):
    modes = ("push", "mdi-baseinstance", "mdi-attribute")
    for path in paths:
        run = load(path)
        s = run["settings"]
        fixed = run["fixed_cost"]["gpu_ms_median"]
        print(f"**{s['msaa']}x MSAA**, `--clear {run['clear']}` (ran: {run['clear_path']}); "
              f"empty frame {fixed:.3f} ms. GPU ms (x floor); the last two columns: "
              "occlusion in mdi-baseinstance, and its time over culling off's.\n")
        print("| renderer | floor | " + " | ".join(modes) +
              " | mdi-baseinstance, occlusion | occlusion x off |")
        print("|---|---|" + "---:|" * (len(modes) + 2))
        names = []
        for r in run["results"]:
            if r["renderer"] not in names:
                names.append(r["renderer"])
        for name in names:
            cells = []
            for m in modes:
                r = row(run, name, m, "off", 0.0)
                cells.append(f"{r['gpu_ms_median']:.3f} ({r['ratio_to_floor']:.3f})")
            occ = row(run, name, "mdi-baseinstance", "occlusion", 0.0)
            off = row(run, name, "mdi-baseinstance", "off", 0.0)
            cells.append(f"{occ['gpu_ms_median']:.3f} ({occ['ratio_to_floor']:.3f})")
            cells.append(f"**{occ['gpu_ms_median'] / off['gpu_ms_median']:.3f}**")
            floor = row(run, name, "push", "off", 0.0)["floor"]
            print(f"| `{name}` | {floor} | " + " | ".join(cells) + " |")
        print()


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "targets":
        targets(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "techniques":
        techniques(sys.argv[2:])
    else:
        sys.exit(__doc__)
