"""bench_runs.py - reading the benchmark runs under docs/benchmarks/ for bench_tables.py: a
run's rows, the idview command that made a run (rebuilt from what its JSON records), and the
runs scripts/gpu-runs.sh makes.
"""
import json
import os
import re
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH = os.path.join(ROOT, "docs", "benchmarks")
H100_RUNS = os.path.join(ROOT, "scripts", "gpu-runs.sh")

# The registry's order (idview --list-renderers): what `--renderer all` and `--mode all` mean,
# and how `--culling` lists its modes.
TECHNIQUES = ["per-draw", "tri-fs", "tri-gs", "search-fs", "search-gs", "bsearch-fs",
              "nsearch-fs", "nsearch-gs", "vertex-fs", "mesh-fs", "mesh-vertex-fs", "visbuffer",
              "visbuffer-compute"]
# Added to the registry after runs were made that named no renderer: for those, every renderer
# meant the registry without these (the command as it was given).
ADDED_LATER = ["visbuffer", "visbuffer-compute"]
FLOORS = ["no-id", "no-id-mesh"]
MODES = ["push", "mdi-baseinstance", "mdi-attribute"]
CULLING = ["off", "frustum", "occlusion"]
# The --benchmark defaults (idview --help), left out of a command; --msaa and --frames are
# always written, as their benchmark defaults differ from the program's.
DEFAULTS = {"--size": "2560x1440", "--copies": "3", "--model": "default.glb",
            "--clear": "auto", "--search-batch": "16", "--visible": "1", "--edge-width": "1",
            "--camera-path": "none", "--raster-pixels": "32"}
# The order a command's flags are written in, here and in gpu-runs.sh.
ORDER = ["--size", "--msaa", "--model", "--copies", "--frames", "--camera-path", "--renderer",
         "--mode", "--culling", "--lod-levels", "--lod-error", "--raster-pixels", "--raster-all",
         "--search-batch", "--visible",
         "--no-sort-draws", "--gs-ordinary", "--edges", "--edge-width", "--visible-parts",
         "--hide", "--isolate", "--clear"]
# The parts hidden or isolated by the hiding runs, as the page writes them and as
# gpu-runs.sh spells them: every third unique part ID below 3,000.
THIRDS = "0,3,6,...,2997"
THIRDS_COUNT = 1000


def path_of(folder, stem):
    return os.path.join(BENCH, folder, stem + ".json")


def load(folder, stem):
    path = path_of(folder, stem)
    if not os.path.exists(path):
        sys.exit(f"{os.path.relpath(path, ROOT)}: no such run")
    with open(path) as f:
        return json.load(f)


def culling(row):
    return row.get("culling", "off")  # runs from before culling drew everything


def lod(row):
    return row.get("lod_error", 0.0)


def rows(run, renderer=None, mode=None, cull=None, lod_error=None):
    """The run's rows that match every criterion given."""
    return [r for r in run["results"]
            if (renderer is None or r["renderer"] == renderer)
            and (mode is None or r["mode"] == mode)
            and (cull is None or culling(r) == cull)
            and (lod_error is None or abs(lod(r) - lod_error) < 1e-6)]


def row(run, renderer, mode, cull="off", lod_error=0.0, where=""):
    found = rows(run, renderer, mode, cull, lod_error)
    if len(found) != 1:
        sys.exit(f"{where}: {len(found)} rows of {renderer} + {mode}, culling {cull}, "
                 f"LOD error {lod_error:g}")
    return found[0]


def find(run, renderer, mode, cull="off", lod_error=0.0):
    """The row, or None where the run has none."""
    found = rows(run, renderer, mode, cull, lod_error)
    return found[0] if len(found) == 1 else None


def names(run, floors=True):
    """The run's renderers in the order of its rows."""
    seen = []
    for r in run["results"]:
        if r["renderer"] not in seen and (floors or r["renderer"] not in FLOORS):
            seen.append(r["renderer"])
    return seen


def listed(values, everything, later=()):
    """A comma list, or None where it names everything (the flag's default), or everything
    but `later`, what the default named before those were added."""
    ordered = sorted(values, key=everything.index)
    if ordered in (everything, [v for v in everything if v not in later]):
        return None
    return ",".join(values)


def flags_of(run, extra=()):
    """The flags of the command that made `run`, as far as its JSON records them, with the
    `extra` flags it cannot record (--gs-ordinary, --visible-parts, ...) added."""
    s, results = run["settings"], run["results"]
    unique = []
    for key in (lambda r: r["mode"], culling, lod):
        values = []
        for r in results:
            if key(r) not in values:
                values.append(key(r))
        unique.append(values)
    modes, cullings, errors = unique
    errors = sorted(errors)
    flags = {"--size": s["size"], "--msaa": str(s["msaa"]),
             "--model": os.path.basename(s["scene"]), "--copies": str(s["copies"]),
             "--frames": str(s["frames"]), "--camera-path": s.get("camera_path", "none"),
             "--renderer": listed(names(run, floors=False), TECHNIQUES, ADDED_LATER),
             "--mode": listed(modes, MODES),
             # Runs from before culling or the compute clear path drew as these flags do now.
             "--culling": listed(cullings, CULLING) if "culling" in results[0] else "off",
             "--lod-error": None if errors == [0.0] else ",".join(f"{e:g}" for e in errors),
             "--search-batch": str(s.get("search_batch", 16)),
             "--visible": f"{s.get('visible', 1.0):g}",
             "--no-sort-draws": None if s.get("sort_draws", True) else True,
             "--edges": True if s.get("edges") else None,
             "--edge-width": str(s.get("edge_width", 1)), "--clear": run.get("clear", "pass"),
             # Runs from before the compute rasterizer did not record its settings.
             "--raster-pixels": f"{s['raster_pixels']:g}" if "raster_pixels" in s else None,
             "--raster-all": True if s.get("raster_all") else None}
    levels = s.get("lod_levels", 1)
    if levels != (4 if flags["--lod-error"] else 1):
        flags["--lod-levels"] = str(levels)
    # The JSON counts the hidden parts: the thirds hidden, or every other part (isolated).
    hidden = s.get("hidden_parts", 0)
    if hidden:
        flags["--hide" if hidden == THIRDS_COUNT else "--isolate"] = THIRDS
    for flag in extra:
        flags[flag] = extra[flag] if isinstance(extra, dict) else True
    return {k: v for k, v in flags.items() if v is not None and DEFAULTS.get(k) != v}


def command(flags):
    """The command line of `flags`, in ORDER (unknown flags last, sorted)."""
    words = ["idview", "--headless", "--benchmark"]
    for flag in sorted(flags, key=lambda f: (ORDER.index(f) if f in ORDER else len(ORDER), f)):
        words.append(flag if flags[flag] is True else f"{flag} {flags[flag]}")
    return " ".join(words)


def parse(args):
    """A command's flags from its words (after idview --headless --benchmark), as flags_of
    gives them: gpu-runs.sh's $thirds as the page writes it, a model by its file name, and
    the defaults left out."""
    flags, words = {}, shlex.split(args.replace("$thirds", THIRDS))
    i = 0
    while i < len(words):
        flag = words[i]
        if i + 1 < len(words) and not words[i + 1].startswith("--"):
            flags[flag] = words[i + 1]
            i += 2
        else:
            flags[flag] = True
            i += 1
    if "--model" in flags:
        flags["--model"] = os.path.basename(flags["--model"])
    return {k: v for k, v in flags.items() if DEFAULTS.get(k) != v}


def script_runs(path=H100_RUNS):
    """gpu-runs.sh's runs, as its --list prints them: {name: (part, flags)}."""
    listed = subprocess.run(["bash", path, "--list", "idview", "out"], capture_output=True,
                            text=True, check=True).stdout
    runs = {}
    for line in listed.splitlines():
        m = re.match(r"^part (\d+) (\S+): idview --headless --benchmark (.*)$", line)
        if not m:
            sys.exit(f"gpu-runs.sh --list: not a run: {line}")
        if m.group(2) in runs:
            sys.exit(f"gpu-runs.sh: two runs named {m.group(2)}")
        runs[m.group(2)] = (int(m.group(1)), parse(m.group(3)))
    return runs


# --- What every kind of table writes alike (bench_kinds*.py) ---------------------------------

MDI = "mdi-baseinstance"


def f3(x):
    return f"{x:.3f}"


def span(values, fmt):
    """'lo-hi' of the values as formatted, or the one value where they print alike."""
    lo, hi = fmt(min(values)), fmt(max(values))
    return lo if lo == hi else f"{lo}-{hi}"


def triangles(n):
    """A triangle count as the tables write it: M from a million up, else k."""
    if n >= 1e6:
        return f"{n / 1e6:.2f} M"
    return "0" if n == 0 else f"{n / 1e3:.0f} k"
