"""bench_kinds_vis.py - docs/benchmarks.md's tables of the visibility buffer and its compute
rasterizer (issue 46), for bench_tables.py: per MSAA setting, each scene and culling of
gpu-runs.sh's part 5, the GPU time of the floors, vertex-fs, mesh-fs, visbuffer and
visbuffer-compute from one run, with the triangles drawn, the compute rasterizer's share and
issue 46's target where it set one; then the compute rasterizer with every meshlet it can draw
and with other thresholds.
"""
from bench_runs import find, triangles, MDI

RENDERERS = ("no-id", "vertex-fs", "no-id-mesh", "mesh-fs", "visbuffer", "visbuffer-compute")
COMPUTE = "visbuffer-compute"
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
# Issue 46's targets for the visibility buffer's frame: ms at 1x and 4x, or a ratio to another
# renderer.
TARGETS = {
    ("view", "occlusion"): {1: ("ms", 1.0), 4: ("ms", 2.5)},
    ("copies16", "occlusion"): {1: ("ms", 2.0), 4: ("ms", 5.0)},
    ("copies16", "off"): {1: ("vertex-fs", 0.3), 4: ("vertex-fs", 0.3)},
    ("motor", "off"): {1: ("no-id", 1.0), 4: ("no-id", 1.0)},
}


def vis_files(params):
    m = params["msaa"]
    return [(f"vis-{stem}-{m}", ()) for stem in ("view", "copies16", "dolly", "motor")]


def target_cell(stem, cull, msaa, line, renderer):
    target = TARGETS.get((stem, cull), {}).get(msaa)
    if target is None:
        return ""
    vis = line[renderer]["gpu_ms_median"]
    kind, limit = target
    if kind == "ms":
        return f"<= {limit} ms: {vis:.3f} ({'met' if vis <= limit else 'missed'})"
    ratio = vis / line[kind]["gpu_ms_median"]
    return f"<= {limit}x `{kind}`: {ratio:.3f} ({'met' if ratio <= limit else 'missed'})"


def vis_table(runs, params):
    msaa = int(params["msaa"])
    first = runs[f"vis-view-{msaa}"]
    fixed = first["fixed_cost"]["gpu_ms_median"]
    out = [f"**{msaa}x MSAA**, mdi-baseinstance. GPU ms of the whole frame (the frame that "
           f"draws nothing costs {fixed:.3f} ms); the compute rasterizer's time above that "
           "fixed cost, the two visibility buffers' ratios to vertex-fs, the triangles drawn "
           "and the compute rasterizer's share of them, and issue 46's targets:", "",
           "| frame | " + " | ".join(f"`{r}`" for r in RENDERERS) +
           " | compute above fixed | visbuffer x vertex-fs | compute x vertex-fs | triangles "
           "| in compute | target: visbuffer | target: compute |",
           "|---|" + "---:|" * (len(RENDERERS) + 7)]
    for what, stem, cull, lod_error in LINES:
        run = runs[f"vis-{stem}-{msaa}"]
        line = {r: find(run, r, MDI, cull, lod_error) for r in RENDERERS}
        if any(v is None for v in line.values()):
            out.append(f"| {what} | " + " | ".join(["not run"] * (len(RENDERERS) + 7)) + " |")
            continue
        vis, comp, vfs = line["visbuffer"], line[COMPUTE], line["vertex-fs"]
        cells = [f"{line[r]['gpu_ms_median']:.3f}" for r in RENDERERS]
        cells.append(f"{comp['above_fixed_ms']:.3f}")
        cells.append(f"{vis['gpu_ms_median'] / vfs['gpu_ms_median']:.3f}")
        cells.append(f"**{comp['gpu_ms_median'] / vfs['gpu_ms_median']:.3f}**")
        cells.append(triangles(comp["triangles_drawn"]))
        share = comp["triangles_drawn_compute"] / max(comp["triangles_drawn"], 1)
        cells.append(f"{100 * share:.1f} %")
        cells.append(target_cell(stem, cull, msaa, line, "visbuffer"))
        cells.append(target_cell(stem, cull, msaa, line, COMPUTE))
        out.append(f"| {what} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


# The compute rasterizer's own runs: every meshlet it can draw (--raster-all), and the
# thresholds around its default (--raster-pixels), against its default in part 5's runs.
SHARES = [("rasterall", "every meshlet it can draw (`--raster-all`)"),
          ("rasterpx8", "`--raster-pixels 8`"), ("vis", "`--raster-pixels 32` (the default)"),
          ("rasterpx128", "`--raster-pixels 128`")]


def raster_files(params):
    m = params["msaa"]
    stems = ("view", "copies16", "motor") if m == "4" else ("view", "copies16")
    return [(f"{kind}-{stem}-{m}", ()) for kind, _ in SHARES for stem in stems
            if not (kind.startswith("rasterpx") and m == "4")
            and not (kind.startswith("rasterpx") and stem == "motor")]


def raster_table(runs, params):
    msaa = int(params["msaa"])
    out = [f"**{msaa}x MSAA**, mdi-baseinstance, `visbuffer-compute`: GPU ms of the whole "
           "frame, and the share of the triangles drawn in compute, by which meshlets go to the "
           "compute rasterizer:", "",
           "| meshlets in compute | scene | culling off | occlusion + LOD 1 px | in compute (off "
           "/ occlusion + LOD) |", "|---|---|---:|---:|---:|"]
    for kind, what in SHARES:
        for stem in ("view", "copies16", "motor"):
            name = f"{kind}-{stem}-{msaa}"
            if name not in runs:
                continue
            off = find(runs[name], COMPUTE, MDI, "off", 0.0)
            occ = find(runs[name], COMPUTE, MDI, "occlusion", 1.0)
            shares = [100 * r["triangles_drawn_compute"] / max(r["triangles_drawn"], 1)
                      for r in (off, occ)]
            scene = {"view": "benchmark view", "copies16": "16 copies",
                     "motor": "Motor-c.brep"}[stem]
            out.append(f"| {what} | {scene} | {off['gpu_ms_median']:.3f} | "
                       f"{occ['gpu_ms_median']:.3f} | {shares[0]:.1f} % / {shares[1]:.1f} % |")
    return "\n".join(out) + "\n"


KINDS = {
    "visibility": (vis_files, vis_table),
    "compute-raster": (raster_files, raster_table),
}
