"""bench_kinds_lod.py - the levels-of-detail tables of docs/benchmarks.md (bench_kinds.py lists
every kind): each renderer's time without and with levels chosen at 1 px, culling off and
occlusion, and the triangles each level drew.
"""
from bench_runs import row, f3, triangles, MDI

# What a run shows, as a column's heading (every run gpu-runs.sh makes with levels).
LABELS = {"view-1x": "benchmark view, 1x", "view-4x": "benchmark view, 4x",
          "copies16-1x": "16 copies, 1x", "copies16-4x": "16 copies, 4x",
          "orbit-1x": "`orbit` path, 1x", "dolly-1x": "`dolly` path, 1x",
          "dolly-4x": "`dolly` path, 4x"}
RENDERERS = "no-id,no-id-mesh,per-draw,tri-fs,vertex-fs,mesh-fs"


def lod_files(params):
    return [(stem, ()) for stem in params["runs"].split(",")]


def lod_cell(run, name, where):
    ms = [row(run, name, MDI, cull, error, where=where)["gpu_ms_median"]
          for cull, error in (("off", 0.0), ("off", 1.0), ("occlusion", 0.0),
                              ("occlusion", 1.0))]
    floor = row(run, name, MDI, "occlusion", 1.0, where=where)["ratio_to_floor"]
    return " / ".join(f3(x) for x in ms) + f" (**{ms[3] / ms[0]:.3f}**, {floor:.3f})"


def lod_table(runs, params):
    stems = params["runs"].split(",")
    out = ["| renderer | " + " | ".join(LABELS[s] for s in stems) + " |",
           "|---|" + "---:|" * len(stems)]
    for name in params.get("renderers", RENDERERS).split(","):
        out.append(f"| `{name}` | " + " | ".join(lod_cell(runs[s], name, s) for s in stems) +
                   " |")
    return "\n".join(out) + "\n"


def levels_table(runs, params):
    name = params.get("renderer", "vertex-fs")
    out = ["| view | culling off + LOD 1 px | occlusion | occlusion + LOD 1 px | level 0 | "
           "level 1 | level 2 | level 3 |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for stem in params["runs"].split(","):
        off = row(runs[stem], name, MDI, "off", 1.0, where=stem)
        occ = row(runs[stem], name, MDI, "occlusion", where=stem)
        lod = row(runs[stem], name, MDI, "occlusion", 1.0, where=stem)
        cells = [triangles(r["triangles_drawn"]) for r in (off, occ, lod)]
        cells += [triangles(n) for n in lod["triangles_drawn_by_level"]]
        out.append(f"| {LABELS[stem]} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


KINDS = {
    "lod": (lod_files, lod_table),
    "lod-levels": (lod_files, levels_table),
}
