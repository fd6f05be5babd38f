"""bench_kinds_size.py - the tables of docs/benchmarks.md on what grows with the model and
the passes beside the scene: model size, per-draw's CPU, the ID-image passes, hidden parts,
memory, and the shader experiments (bench_kinds.py lists every kind).
"""
import sys

from bench_runs import names, row, f3, span, FLOORS, MDI

SIZE_RENDERERS = "no-id,no-id-mesh,vertex-fs,mesh-fs,mesh-vertex-fs"


def size_files(params):
    return [(f"copies{c}-{m}x", ()) for c in (1, 4, 16) for m in (1, 4)]


def size_table(runs, params):
    chosen = params.get("renderers", SIZE_RENDERERS).split(",")
    frames = sorted({run["settings"]["frames"] for run in runs.values()})
    out = [f"Culling off, mdi-baseinstance, {' or '.join(map(str, frames))} timed frames; "
           "GPU ms (x floor):", "",
           "| copies (triangles) | MSAA | " + " | ".join(chosen) + " |",
           "|---|---|" + "---:|" * len(chosen)]
    for stem, _ in size_files(params):
        run = runs[stem]
        cells = []
        for name in chosen:
            r = row(run, name, MDI, where=stem)
            ratio = "" if name in FLOORS else f" ({r['ratio_to_floor']:.3f})"
            cells.append(f3(r["gpu_ms_median"]) + ratio)
        tris = row(run, chosen[0], MDI, where=stem)["triangles"]
        out.append(f"| {run['settings']['copies']} ({tris / 1e6:.1f} M) | "
                   f"{run['settings']['msaa']}x | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def perdraw_files(params):
    return [(f"copies{c}", ()) for c in (1, 2, 4, 8)]


def perdraw_table(runs, params):
    first = runs["copies1"]["settings"]
    out = [f"{first['msaa']}x MSAA, {first['frames']} timed frames; `per-draw` with push "
           "constants against `tri-fs` in mdi-baseinstance, each divided by `no-id` in its own "
           "mode:", "",
           "| copies | triangles | no-id ms (push) | per-draw + push ms (x) | its CPU ms | "
           "CPU per draw | tri-fs + mdi-baseinstance ms (x) | its CPU ms |",
           "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for stem, _ in perdraw_files(params):
        run = runs[stem]
        floor, floor_mdi = row(run, "no-id", "push", where=stem), row(run, "no-id", MDI, where=stem)
        pd, tri = row(run, "per-draw", "push", where=stem), row(run, "tri-fs", MDI, where=stem)
        cells = [str(run["settings"]["copies"]), f"{pd['triangles'] / 1e6:.3g} M",
                 f"{floor['gpu_ms_median']:.2f}",
                 f"{pd['gpu_ms_median']:.2f} ({pd['gpu_ms_median'] / floor['gpu_ms_median']:.3f})",
                 f"{pd['cpu_ms_median']:.2f}",
                 f"{pd['cpu_ms_median'] / max(pd['draws'], 1) * 1e6:.0f} ns",
                 f"{tri['gpu_ms_median']:.2f} "
                 f"({tri['gpu_ms_median'] / floor_mdi['gpu_ms_median']:.3f})",
                 f"{tri['cpu_ms_median']:.3f}"]
        out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


ID_PASSES = [("part edges, 1 px (with the selection's and hovered part's outlines)", "edges-w1",
              ()),
             ("part edges, 3 px", "edges-w3", ()),
             ("visible part count, whole image (`--visible-parts`)", "visible",
              ("--visible-parts",))]


def idpasses_files(params):
    return [(f"{stem}-{m}", extra) for _, stem, extra in ID_PASSES for m in (1, 4)]


def idpasses_table(runs, params):
    out = ["| ID passes | 1x MSAA | 4x MSAA |", "|---|---|---|"]
    for what, stem, _ in ID_PASSES:
        cells = []
        for m in (1, 4):
            found = runs[f"{stem}-{m}"]["results"]
            ms = [r["id_pass_ms_median"] for r in found]
            share = [100 * r["id_pass_ms_median"] / (r["gpu_ms_median"] + r["id_pass_ms_median"])
                     for r in found]
            cells.append(f"{span(ms, f3)} ms, {span(share, lambda x: f'{x:.2f}')} % of the "
                         "frame")
        out.append(f"| {what} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


HOW_HIDDEN = {"tri-fs": "tri-fs (fragment discard)",
              "tri-gs": "tri-gs, passthrough (fragment discard)",
              "vertex-fs": "vertex-fs (fragment discard)",
              "mesh-fs": "mesh-fs (dropped by the mesh shader)",
              "mesh-vertex-fs": "mesh-vertex-fs (dropped by the mesh shader)"}


def hide_stem(params, what, m):
    folder = params.get("dir", "")
    return f"{folder + '/' if folder else ''}{params.get('prefix', 'hide-')}{what}-{m}"


def hide_files(params):
    whats = ["base", "hide", "isolate"]
    files = [(hide_stem(params, w, m), ()) for w in whats for m in (1, 4)]
    if params.get("gsord", "yes") == "yes":
        files += [(hide_stem(params, w, m), ("--gs-ordinary",)) for w in ("gsord-base",
                                                                          "gsord-hide")
                  for m in (1, 4)]
    return files


def hide_ratio(runs, params, base, what, m, name):
    r = row(runs[hide_stem(params, what, m)], name, MDI, where=what)
    b = row(runs[hide_stem(params, base, m)], name, MDI, where=base)
    return f3(r["gpu_ms_median"] / b["gpu_ms_median"])


def hide_table(runs, params):
    base = runs[hide_stem(params, "base", 1)]
    isolated = runs[hide_stem(params, "isolate", 1)]["settings"]["hidden_parts"]
    chosen = params.get("renderers")
    chosen = chosen.split(",") if chosen else names(base, floors=False)
    out = [f"Hiding 1,000 parts (every third ID below 3,000) and isolating them ({isolated:,} "
           "hidden), mdi-baseinstance, culling off, ratio to the same technique with nothing "
           "hidden:", "",
           "| technique (how it hides) | 1x hide | 1x isolate | 4x hide | 4x isolate |",
           "|---|---:|---:|---:|---:|"]
    for name in chosen:
        cells = [hide_ratio(runs, params, "base", w, m, name) for m in (1, 4)
                 for w in ("hide", "isolate")]
        out.append(f"| {HOW_HIDDEN.get(name, name)} | " + " | ".join(cells) + " |")
        if name == "tri-gs" and params.get("gsord", "yes") == "yes":
            cells = [c for m in (1, 4) for c in
                     (hide_ratio(runs, params, "gsord-base", "gsord-hide", m, name), "not run")]
            out.append("| tri-gs, ordinary (`--gs-ordinary`; not emitted) | " +
                       " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


ID_DATA = {"no-id": "0", "no-id-mesh": "0", "per-draw": "0 (the part is in the draw)",
           "tri-fs": "{} B (a part index per triangle)",
           "tri-gs": "{} B (a part index per triangle)", "search-fs": "{} B (per part)",
           "search-gs": "{} B (per part)", "bsearch-fs": "{} B (per part)",
           "nsearch-fs": "{} B (per part)", "nsearch-gs": "{} B (per part)",
           "vertex-fs": "{} B (a part index per vertex)",
           "mesh-fs": "{} B (per meshlet triangle)",
           "mesh-vertex-fs": "{} B (per meshlet vertex)"}


def memory_table(runs, params):
    run = runs[f"techniques-{params.get('msaa', '1')}x"]
    groups = []  # [names, cells], techniques whose cells are alike share a line
    for name in names(run):
        r = row(run, name, MDI, where="memory")
        if name not in ID_DATA:
            sys.exit(f"memory: no description of {name}'s ID data")
        geometry = "none"
        if r["geometry_bytes"]:
            what = "its copy of vertices and indices" if not r["meshlets"] else \
                f"part vertices, {r['meshlets']:,} meshlets drawn"
            geometry = f"{r['geometry_bytes'] / 1e6:.2f} MB ({what})"
        cells = [f"{r['draws']:,}", ID_DATA[name].format(f"{r['id_bytes']:,}"), geometry]
        if groups and groups[-1][1] == cells:
            groups[-1][0].append(name)
        else:
            groups.append([[name], cells])
    out = ["| technique | draws | ID data | derived geometry drawn instead of the scene's |",
           "|---|---:|---:|---:|"]
    for group, cells in groups:
        out.append(f"| {', '.join(group)} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


SHADERS = [("as shipped", ""),
           ("no pick, hover read, highlight or part colour; constant ID", "-constid"),
           ("gs without its lookup (no `gl_PrimitiveIDIn`)", "-gsnolookup")]


def shaders_files(params):
    return [(f"experiments/exp-shaders{v}-{m}", {"--shader-dir": "COPY"} if v else {})
            for m in (1, 4) for _, v in SHADERS]


def shaders_table(runs, params):
    shown = ["no-id", "per-draw", "tri-fs", "tri-gs"]
    out = ["| shaders | MSAA | " + " | ".join(shown) + " |", "|---|---|" + "---:|" * len(shown)]
    for m in (1, 4):
        for what, v in SHADERS:
            run = runs[f"experiments/exp-shaders{v}-{m}"]
            cells = [f"{row(run, n, MDI, where=v)['gpu_ms_median']:.2f}" for n in shown]
            if v == "-gsnolookup":
                cells[-1] = f"**{cells[-1]}**"
            out.append(f"| {what} | {m}x | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


KINDS = {
    "size": (size_files, size_table),
    "perdraw": (perdraw_files, perdraw_table),
    "idpasses": (idpasses_files, idpasses_table),
    "hide": (hide_files, hide_table),
    "memory": (lambda p: [(f"techniques-{p.get('msaa', '1')}x", ())], memory_table),
    "shaders": (shaders_files, shaders_table),
}
