"""bench_kinds.py - the kinds of table docs/benchmarks.md has, for bench_tables.py. Each kind
is a pair: files(params), the runs it reads as (stem, flags their JSON does not record) in the
block's folder, or (stem, flags, folder) in another; and table(runs, params), the Markdown (a
caption line and the table) from those runs by stem (FOLDER/STEM for another folder's). Here
the frame's fixed cost, the techniques, culling and the culling rework's before and after;
bench_kinds_lod.py, bench_kinds_size.py and bench_kinds_vis.py hold the rest.
"""
import bench_kinds_lod
import bench_kinds_size
import bench_kinds_vis
from bench_runs import find, names, row, rows, f3, triangles, MDI


def msaa_stems(pattern, msaas=(1, 4)):
    return [(pattern.format(m=m), ()) for m in msaas]


# --- The frame's fixed cost: each clear path against the targets of issue 37 ---------------

# Issue 37's targets, GPU ms at 1x and 4x MSAA on `--clear auto`.
TARGETS = {"empty": {1: 0.35, 4: 1.2}, "view": {1: 1.4, 4: 3.2}, "motor": {1: 0.6, 4: 2.1}}
TARGET_LINES = [
    # (what, file stem, renderer, culling, LOD error, target)
    ("empty frame (`--visible 0`)", "view", None, None, None, "empty"),
    ("benchmark view, `vertex-fs`, culling off", "view", "vertex-fs", "off", 0.0, None),
    ("benchmark view, `vertex-fs`, culling off + LOD 1 px", "view", "vertex-fs", "off", 1.0,
     None),
    ("Motor-c.brep, `no-id` floor, culling off", "motor", "no-id", "off", 0.0, "motor"),
    ("Motor-c.brep, `vertex-fs`, culling off", "motor", "vertex-fs", "off", 0.0, None),
    ("Motor-c.brep, `vertex-fs`, culling off + LOD 1 px", "motor", "vertex-fs", "off", 1.0,
     None),
]
PATHS = ("pass", "compute", "auto")


def goal(target, msaa, ms):
    if target is None:
        return ""
    limit = TARGETS[target][msaa]
    return f"<= {limit} ({'met' if ms <= limit else 'missed'})"


def targets_files(params):
    m = params["msaa"]
    return [(f"{stem}-{m}-{p}", ()) for stem in ("view", "motor") for p in PATHS]


def targets_table(runs, params):
    msaa = int(params["msaa"])
    auto = runs[f"view-{msaa}-auto"]
    timing = auto["clear_timing"]
    out = [f"**{msaa}x MSAA**, culling off. `--clear auto` ran the {auto['clear_path']} path (an "
           f"empty 1920x1080 frame timed at {timing['pass_ms']:.3f} ms on the pass path, "
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
        out.append(f"| {what} | " + " | ".join(cells) + f" | {goal(target, msaa, ms)} |")
    return "\n".join(out) + "\n"


CULLED_LINES = [
    # (what, file stem, renderer, culling, LOD error, target)
    ("empty frame (`--visible 0`)", "view", None, None, None, "empty"),
    ("benchmark view, `vertex-fs`, occlusion", "view", "vertex-fs", "occlusion", 0.0, None),
    ("benchmark view, `vertex-fs`, occlusion + LOD 1 px", "view", "vertex-fs", "occlusion", 1.0,
     "view"),
    ("benchmark view, `no-id` floor, occlusion + LOD 1 px", "view", "no-id", "occlusion", 1.0,
     None),
    ("Motor-c.brep, `no-id` floor, occlusion", "motor-all", "no-id", "occlusion", 0.0, None),
    ("Motor-c.brep, `vertex-fs`, occlusion", "motor-all", "vertex-fs", "occlusion", 0.0, None),
]


def culled_table(runs, params):
    first = runs["view-1x"]
    out = [f"`--clear {first['clear']}` (ran: {first['clear_path']}), mdi-baseinstance, "
           "occlusion culling. GPU ms, and in brackets above that run's empty frame:", "",
           "| frame | 1x | target | 4x | target |", "|---|---:|---:|---:|---:|"]
    for what, stem, renderer, cull, lod_error, target in CULLED_LINES:
        cells = []
        for msaa in (1, 4):
            run = runs[f"{stem}-{msaa}x"]
            fixed = run["fixed_cost"]["gpu_ms_median"]
            ms = fixed if renderer is None else \
                row(run, renderer, MDI, cull, lod_error, stem)["gpu_ms_median"]
            cells += [f"{ms:.3f} ({ms - fixed:.3f})", goal(target, msaa, ms)]
        out.append(f"| {what} | " + " | ".join(cells) + " |")
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
           f"objects; {one['settings']['frames']} timed frames), mdi-baseinstance, culling off, "
           "without and with levels of detail chosen at 1 px. Culling off x floor is in "
           "brackets after off, LOD x off after LOD; CPU record ms is the median time to "
           "record a frame's commands (`cpu_record_ms_median`):", "",
           "| renderer | 1x off (x floor) | 1x off + LOD 1 px (x off) | 4x off (x floor) | "
           "4x off + LOD 1 px (x off) | CPU record ms, 1x off / LOD | 4x off / LOD |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for name in names(one):
        cells, record = [], []
        for run in (one, four):
            off = row(run, name, MDI, where="copies16")
            lod = row(run, name, MDI, "off", 1.0, where="copies16")
            cells.append(f"{off['gpu_ms_median']:.2f} ({off['ratio_to_floor']:.3f})")
            cells.append(f"{lod['gpu_ms_median']:.2f} "
                         f"(**{lod['gpu_ms_median'] / off['gpu_ms_median']:.3f}**)")
            record.append(f"{off['cpu_record_ms_median']:.3f} / "
                          f"{lod['cpu_record_ms_median']:.3f}")
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


# --- The culling rework (issue 38): the build before against the build after -----------------

REWORK_RENDERERS = "no-id,no-id-mesh,per-draw,tri-fs,vertex-fs,mesh-fs,mesh-vertex-fs"
REWORK_LINES = [(MDI, "occlusion", 0.0, "mdi-baseinstance, occlusion"),
                (MDI, "occlusion", 1.0, "mdi-baseinstance, occlusion + LOD 1 px"),
                ("push", "occlusion", 0.0, "push, occlusion")]
RUN_LABELS = dict(bench_kinds_lod.LABELS, **{"techniques-1x": "benchmark view, 1x",
                                             "techniques-4x": "benchmark view, 4x"})


def rework_files(params):
    stems = params["runs"].split(",")
    return [(s, (), params["before"]) for s in stems] + [(s, ()) for s in stems]


def rework_cells(old, new, line, name):
    """Before and now of one row: 'ms (x off)' each, now over before, and the triangles."""
    mode, cull, error, _ = line
    got = []
    for run in (old, new):
        r, off = find(run, name, mode, cull, error), find(run, name, mode, "off")
        got.append(None if r is None or off is None else (r, off))
    if None in got:
        return ["not run"] * 4
    (a, a_off), (b, b_off) = got
    ms = [f"{r['gpu_ms_median']:.3f} ({r['gpu_ms_median'] / off['gpu_ms_median']:.3f})"
          for r, off in got]
    return ms + [f"**{b['gpu_ms_median'] / a['gpu_ms_median']:.3f}**",
                 f"{triangles(a['triangles_drawn'])} / {triangles(b['triangles_drawn'])}"]


def rework_table(runs, params):
    stems, before = params["runs"].split(","), params["before"]
    lines = [line for line in REWORK_LINES
             if any(rows(runs[s], mode=line[0], cull=line[1], lod_error=line[2])
                    for s in stems)]
    out = ["GPU ms (x culling off at full detail of the same build, technique and mode), now "
           "over before (bold), and the triangles drawn in the median frame, before / now:", "",
           "| renderer | mode, culling | " + " | ".join(
               f"{RUN_LABELS[s]}: before | now | now / before | triangles" for s in stems) +
           " |", "|---|---|" + "---:|" * 4 * len(stems)]
    for name in params.get("renderers", REWORK_RENDERERS).split(","):
        for line in lines:
            cells = [c for s in stems
                     for c in rework_cells(runs[f"{before}/{s}"], runs[s], line, name)]
            out.append(f"| `{name}` | {line[3]} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


KINDS = {
    "targets": (targets_files, targets_table),
    "targets-culled": (lambda p: msaa_stems("view-{m}x") + msaa_stems("motor-all-{m}x"),
                       culled_table),
    "techniques": (techniques_files, techniques_table),
    "copies16": (lambda p: msaa_stems("copies16-{m}x"), copies16_table),
    "paths": (lambda p: [("dolly-1x", ()), ("dolly-4x", ()), ("orbit-1x", ())], paths_table),
    "cad": (lambda p: msaa_stems("motor-all-{m}x"), cad_table),
    "rework": (rework_files, rework_table),
    **bench_kinds_lod.KINDS,
    **bench_kinds_size.KINDS,
    **bench_kinds_vis.KINDS,
}
# Kinds of experiments (shader copies): runs gpu-runs.sh does not make.
EXPERIMENTS = {"shaders"}
# Kinds that compare two named builds (before=FOLDER): --from moves them nowhere.
COMPARISONS = {"rework"}
