"""bench_kinds_vis.py - docs/benchmarks.md's table of the visibility buffer (issue 46), for
bench_tables.py: per MSAA setting, each scene and culling of gpu-runs.sh's part 5, the GPU
time of the floors, vertex-fs, mesh-fs and visbuffer from one run, with the triangles drawn
and issue 46's target where it set one.
"""
from bench_runs import find, triangles, MDI

RENDERERS = ("no-id", "vertex-fs", "no-id-mesh", "mesh-fs", "visbuffer")
# (what, file stem, culling, LOD error px)
LINES = [
    ("benchmark view, culling off", "view", "off", 0.0),
    ("benchmark view, occlusion + LOD 1 px", "view", "occlusion", 1.0),
    ("16 copies, culling off", "copies16", "off", 0.0),
    ("16 copies, occlusion + LOD 1 px", "copies16", "occlusion", 1.0),
    ("dolly path, culling off", "dolly", "off", 0.0),
    ("dolly path, occlusion + LOD 1 px", "dolly", "occlusion", 1.0),
    ("Motor-c.brep, culling off", "motor", "off", 0.0),
    ("Motor-c.brep, occlusion + LOD 1 px", "motor", "occlusion", 1.0),
]
# Issue 46's targets for visbuffer's frame: ms at 1x and 4x, or a ratio to another renderer.
TARGETS = {
    ("view", "occlusion"): {1: ("ms", 1.0), 4: ("ms", 2.5)},
    ("copies16", "occlusion"): {1: ("ms", 2.0), 4: ("ms", 5.0)},
    ("copies16", "off"): {1: ("vertex-fs", 0.3), 4: ("vertex-fs", 0.3)},
    ("motor", "off"): {1: ("no-id", 1.0), 4: ("no-id", 1.0)},
}


def vis_files(params):
    m = params["msaa"]
    return [(f"vis-{stem}-{m}", ()) for stem in ("view", "copies16", "dolly", "motor")]


def target_cell(stem, cull, msaa, line):
    target = TARGETS.get((stem, cull), {}).get(msaa)
    if target is None:
        return ""
    vis = line["visbuffer"]["gpu_ms_median"]
    kind, limit = target
    if kind == "ms":
        return f"<= {limit} ms ({'met' if vis <= limit else 'missed'})"
    ratio = vis / line[kind]["gpu_ms_median"]
    return f"<= {limit}x `{kind}`: {ratio:.3f} ({'met' if ratio <= limit else 'missed'})"


def vis_table(runs, params):
    msaa = int(params["msaa"])
    first = runs[f"vis-view-{msaa}"]
    fixed = first["fixed_cost"]["gpu_ms_median"]
    out = [f"**{msaa}x MSAA**, mdi-baseinstance. GPU ms of the whole frame (the frame that "
           f"draws nothing costs {fixed:.3f} ms); visbuffer's time above that fixed cost, its "
           "ratio to vertex-fs and to its own floor (no-id-mesh: the same meshlets without "
           "IDs), and the triangles it drew:", "",
           "| frame | " + " | ".join(f"`{r}`" for r in RENDERERS) +
           " | visbuffer above fixed | x vertex-fs | x no-id-mesh | triangles | target |",
           "|---|" + "---:|" * (len(RENDERERS) + 5)]
    for what, stem, cull, lod_error in LINES:
        run = runs[f"vis-{stem}-{msaa}"]
        line = {r: find(run, r, MDI, cull, lod_error) for r in RENDERERS}
        if any(v is None for v in line.values()):
            out.append(f"| {what} | " + " | ".join(["not run"] * (len(RENDERERS) + 5)) + " |")
            continue
        vis = line["visbuffer"]
        cells = [f"{line[r]['gpu_ms_median']:.3f}" for r in RENDERERS]
        cells.append(f"{vis['above_fixed_ms']:.3f}")
        cells.append(f"**{vis['gpu_ms_median'] / line['vertex-fs']['gpu_ms_median']:.3f}**")
        cells.append(f"{vis['ratio_to_floor']:.3f}")
        cells.append(triangles(vis["triangles_drawn"]))
        cells.append(target_cell(stem, cull, msaa, line))
        out.append(f"| {what} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


KINDS = {
    "visibility": (vis_files, vis_table),
}
