"""bench_kinds.py - the kinds of table docs/benchmarks.md has, for bench_tables.py. Each kind
is a pair: files(params), the runs it reads as (stem, flags their JSON does not record), and
table(runs, params), the Markdown (a caption line and the table) from those runs by stem.
"""
import sys

from bench_runs import find, names, row, rows, FLOORS

MDI = "mdi-baseinstance"


def f3(x):
    return f"{x:.3f}"


def span(values, fmt):
    """'lo-hi' of the values as formatted, or the one value where they print alike."""
    lo, hi = fmt(min(values)), fmt(max(values))
    return lo if lo == hi else f"{lo}-{hi}"


def msaa_stems(pattern, msaas=(1, 4)):
    return [(pattern.format(m=m), ()) for m in msaas]


# --- The frame's fixed cost: each clear path against the targets of issue 37 ---------------

TARGET_LINES = [
    # (what, file stem, renderer, culling, LOD error, target ms at 1x and 4x)
    ("empty frame (`--visible 0`)", "view", None, None, None, {1: 0.35, 4: 1.2}),
    ("benchmark view, `vertex-fs`, occlusion + LOD 1 px", "view", "vertex-fs", "occlusion",
     1.0, {1: 1.4, 4: 3.2}),
    ("benchmark view, `no-id` floor, occlusion + LOD 1 px", "view", "no-id", "occlusion", 1.0,
     None),
    ("Motor-c.brep, `no-id` floor, culling off", "motor", "no-id", "off", 0.0, {1: 0.6, 4: 2.1}),
    ("Motor-c.brep, `vertex-fs`, culling off", "motor", "vertex-fs", "off", 0.0, None),
    ("Motor-c.brep, `vertex-fs`, occlusion + LOD 1 px", "motor", "vertex-fs", "occlusion", 1.0,
     None),
]
PATHS = ("pass", "compute", "auto")


def targets_files(params):
    m = params["msaa"]
    return [(f"{stem}-{m}-{p}", ()) for stem in ("view", "motor") for p in PATHS]


def targets_table(runs, params):
    msaa = int(params["msaa"])
    auto = runs[f"view-{msaa}-auto"]
    timing = auto["clear_timing"]
    out = [f"**{msaa}x MSAA.** `--clear auto` ran the {auto['clear_path']} path (an empty "
           f"1920x1080 frame timed at {timing['pass_ms']:.3f} ms on the pass path, "
           f"{timing['compute_ms']:.3f} ms on the compute path). GPU ms, and in brackets "
           "above that run's empty frame:", "",
           "| frame | pass path | compute path | `--clear auto` | target (auto) |",
           "|---|---:|---:|---:|---:|"]
    for what, stem, renderer, cull, lod_error, target in TARGET_LINES:
        cells = []
        for p in PATHS:
            run = runs[f"{stem}-{msaa}-{p}"]
            fixed = run["fixed_cost"]["gpu_ms_median"]
            ms = fixed if renderer is None else \
                row(run, renderer, MDI, cull, lod_error, stem)["gpu_ms_median"]
            cells.append(f"{ms:.3f} ({ms - fixed:.3f})")
            last = ms
        goal = "" if target is None else \
            f"<= {target[msaa]} ({'met' if last <= target[msaa] else 'missed'})"
        out.append(f"| {what} | " + " | ".join(cells) + f" | {goal} |")
    return "\n".join(out) + "\n"


# --- Every technique against its floor ---------------------------------------------------

def techniques_files(params):
    return [(f"techniques-{params['msaa']}x", ())]


def techniques_table(runs, params):
    run = runs[f"techniques-{params['msaa']}x"]
    modes = ("push", MDI, "mdi-attribute")
    fixed = run["fixed_cost"]["gpu_ms_median"]
    out = [f"**{run['settings']['msaa']}x MSAA**, `--clear {run['clear']}` (ran: "
           f"{run['clear_path']}); empty frame {fixed:.3f} ms. GPU ms (x floor); the last two "
           "columns: occlusion in mdi-baseinstance, and its time over culling off's.", "",
           "| renderer | floor | " + " | ".join(modes) +
           " | mdi-baseinstance, occlusion | occlusion x off |",
           "|---|---|" + "---:|" * (len(modes) + 2)]
    for name in names(run):
        cells = []
        for m in modes:
            r = row(run, name, m, where="techniques")
            cells.append(f"{r['gpu_ms_median']:.3f} ({r['ratio_to_floor']:.3f})")
        occ = row(run, name, MDI, "occlusion", where="techniques")
        off = row(run, name, MDI, where="techniques")
        cells.append(f"{occ['gpu_ms_median']:.3f} ({occ['ratio_to_floor']:.3f})")
        cells.append(f"**{occ['gpu_ms_median'] / off['gpu_ms_median']:.3f}**")
        out.append(f"| `{name}` | {off['floor']} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


# --- Culling at 16 copies, along camera paths, and on one CAD part ---------------------------

def copies16_table(runs, params):
    one, four = runs["copies16-1x"], runs["copies16-4x"]
    first = row(one, "no-id", MDI, where="copies16")
    out = [f"**16 copies** ({first['triangles'] / 1e6:.1f} M triangles, {first['draws']:,} "
           f"objects; {one['settings']['frames']} timed frames), mdi-baseinstance. Culling off "
           "x floor is in brackets after off; CPU record ms is the median time to record a "
           "frame's commands (`cpu_record_ms_median`):", "",
           "| renderer | 1x off (x floor) | 1x occlusion (x off) | 4x off (x floor) | "
           "4x occlusion (x off) | CPU record ms, 1x off / occl. | 4x off / occl. |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for name in names(one):
        cells, record = [], []
        for run in (one, four):
            off = row(run, name, MDI, where="copies16")
            occ = row(run, name, MDI, "occlusion", where="copies16")
            cells.append(f"{off['gpu_ms_median']:.2f} ({off['ratio_to_floor']:.3f})")
            cells.append(f"{occ['gpu_ms_median']:.2f} "
                         f"(**{occ['gpu_ms_median'] / off['gpu_ms_median']:.3f}**)")
            record.append(f"{off['cpu_record_ms_median']:.3f} / "
                          f"{occ['cpu_record_ms_median']:.3f}")
        out.append(f"| `{name}` | " + " | ".join(cells + record) + " |")
    return "\n".join(out) + "\n"


def against(run, name, mode, cull, base_mode, bold=False):
    """'ms (x off)' of a row against the same renderer in base_mode with culling off."""
    r, off = find(run, name, mode, cull), find(run, name, base_mode, "off")
    if r is None or off is None:
        return "not run"
    x = f3(r["gpu_ms_median"] / off["gpu_ms_median"])
    return f"{r['gpu_ms_median']:.2f} ({'**' + x + '**' if bold else x})"


def paths_table(runs, params):
    dolly1, dolly4, orbit = runs["dolly-1x"], runs["dolly-4x"], runs["orbit-1x"]
    out = [f"Camera paths ({dolly1['settings']['frames']} timed frames each; the median frame), "
           "GPU ms of culling off and of occlusion culling in mdi-baseinstance, and of push "
           "mode's CPU frustum culling against push mode culling off:", "",
           "| renderer | dolly 1x off | occlusion (x off) | push frustum (x push off) | "
           "dolly 4x off | occlusion (x off) | push frustum (x push off) | "
           "orbit 1x occlusion (x off) |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for name in names(dolly1):
        cells = []
        for run in (dolly1, dolly4):
            off = row(run, name, MDI, where="dolly")
            cells.append(f"{off['gpu_ms_median']:.2f}")
            cells.append(against(run, name, MDI, "occlusion", MDI, bold=True))
            cells.append(against(run, name, "push", "frustum", "push"))
        cells.append(against(orbit, name, MDI, "occlusion", MDI))
        out.append(f"| `{name}` | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def cad_table(runs, params):
    one, four = runs["motor-all-1x"], runs["motor-all-4x"]
    floor = row(one, "no-id", MDI, where="motor-all")
    modes = [m for m in (MDI, "push") if rows(one, mode=m, cull="occlusion")]
    occl = ["occlusion x off"] if modes == [MDI] else [f"{m} occlusion x off" for m in modes]
    head = [h for m in (1, 4) for h in [f"{m}x off ms"] + occl + ["triangles drawn"]]
    out = [f"`Motor-c.brep` ({floor['draws']} objects, one per solid; {floor['triangles']:,} "
           f"triangles), copies 1, {one['settings']['frames']} timed frames. GPU ms with culling "
           "off, occlusion culling's time over culling off's, and the share of the triangles "
           "occlusion culling drew (mdi-baseinstance):", "",
           "| renderer | " + " | ".join(head) + " |", "|---|" + "---:|" * len(head)]
    for name in names(one):
        cells = []
        for run in (one, four):
            off = row(run, name, MDI, where="motor-all")
            cells.append(f3(off["gpu_ms_median"]))
            for m in modes:
                r, base = row(run, name, m, "occlusion"), row(run, name, m)
                cells.append(f3(r["gpu_ms_median"] / base["gpu_ms_median"]))
            occ = row(run, name, MDI, "occlusion")
            cells.append(f"{100 * occ['triangles_drawn'] / max(occ['triangles'], 1):.1f} %")
        out.append(f"| `{name}` | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


# --- Levels of detail ------------------------------------------------------------------------

LOD_RENDERERS = "no-id,no-id-mesh,per-draw,tri-fs,vertex-fs,mesh-fs"


def lod_cell(run, name):
    off = row(run, name, MDI, where="lod")
    occ = row(run, name, MDI, "occlusion", where="lod")
    lod = row(run, name, MDI, "occlusion", 1.0, where="lod")
    ms = [r["gpu_ms_median"] for r in (off, occ, lod)]
    return (" / ".join(f3(x) for x in ms) +
            f" (**{ms[2] / ms[0]:.3f}**, {lod['ratio_to_floor']:.3f})")


def lod_table(columns):
    def table(runs, params):
        out = ["| renderer | " + " | ".join(label for label, _ in columns) + " |",
               "|---|" + "---:|" * len(columns)]
        for name in params.get("renderers", LOD_RENDERERS).split(","):
            cells = [lod_cell(runs[stem], name) for _, stem in columns]
            out.append(f"| `{name}` | " + " | ".join(cells) + " |")
        return "\n".join(out) + "\n"
    return table


LOD_STILL = [("benchmark view, 1x", "view-1x"), ("benchmark view, 4x", "view-4x"),
             ("16 copies, 1x", "copies16-1x"), ("16 copies, 4x", "copies16-4x")]
LOD_PATHS = [("`orbit` path, 1x", "orbit-1x"), ("`dolly` path, 1x", "dolly-1x"),
             ("`dolly` path, 4x", "dolly-4x")]
LOD_LEVELS = [("benchmark view, 1x", "view-1x"), ("benchmark view, 4x", "view-4x"),
              ("16 copies, 1x", "copies16-1x"), ("`orbit` path, 1x", "orbit-1x"),
              ("`dolly` path, 1x", "dolly-1x")]


def triangles(n, millions):
    if millions:
        return f"{n / 1e6:.2f} M"
    return "0" if n == 0 else f"{n / 1e3:.0f} k"


def levels_table(runs, params):
    name = params.get("renderer", "vertex-fs")
    out = ["| view | occlusion | + LOD 1 px | level 0 | level 1 | level 2 | level 3 |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for label, stem in LOD_LEVELS:
        occ = row(runs[stem], name, MDI, "occlusion", where=stem)
        lod = row(runs[stem], name, MDI, "occlusion", 1.0, where=stem)
        big = occ["triangles_drawn"] >= 1e6
        cells = [triangles(occ["triangles_drawn"], big), triangles(lod["triangles_drawn"], big)]
        cells += [triangles(n, n >= 1e6) for n in lod["triangles_drawn_by_level"]]
        out.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def stems_of(columns):
    return lambda params: [(stem, ()) for _, stem in columns]


# --- Model size, per-draw's CPU, ID-image passes, hidden parts, memory ----------------------

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
    "targets": (targets_files, targets_table),
    "techniques": (techniques_files, techniques_table),
    "copies16": (lambda p: msaa_stems("copies16-{m}x"), copies16_table),
    "paths": (lambda p: [("dolly-1x", ()), ("dolly-4x", ()), ("orbit-1x", ())], paths_table),
    "cad": (lambda p: msaa_stems("motor-all-{m}x"), cad_table),
    "lod-still": (stems_of(LOD_STILL), lod_table(LOD_STILL)),
    "lod-paths": (stems_of(LOD_PATHS), lod_table(LOD_PATHS)),
    "lod-levels": (stems_of(LOD_LEVELS), levels_table),
    "size": (size_files, size_table),
    "perdraw": (perdraw_files, perdraw_table),
    "idpasses": (idpasses_files, idpasses_table),
    "hide": (hide_files, hide_table),
    "memory": (lambda p: [(f"techniques-{p.get('msaa', '1')}x", ())], memory_table),
    "shaders": (shaders_files, shaders_table),
}
# Kinds of experiments (shader copies): runs h100-runs.sh does not make.
EXPERIMENTS = {"shaders"}
