#!/usr/bin/python3
"""cad_bench.py - big CAD files opened by idview and by f3d on this machine: time to the first
picture and to the whole model, a cached reopen, and the peak memory of each program's whole
process tree (idview and its load workers; f3d), sampled from /proc every 50 ms.

    scripts/cad_bench.py run FOLDER FILE... [--idview build/idview] [--f3d f3d]
                         [--workers N] [--viewer] [--f3d-timeout S]
        measures every FILE and writes FOLDER/cad-bench.json (the commands, the machine, each
        run's figures and idview's --stats); --viewer also times the viewer (under Xvfb):
        the first picture and the whole model from its event lines, and a cached reopen
    scripts/cad_bench.py speedup FOLDER FILE... [--idview build/idview]
        adds to FOLDER/cad-bench.json, per FILE, a headless first open with one worker and one
        with two (no cache): the parallel stage's time with each (`speedup` table)
    scripts/cad_bench.py reopen FOLDER FILE... [--idview build/idview] [--workers N]
        measures the viewer's cached reopen again, per FILE (the cache filled by a headless
        --stats run), into FOLDER/cad-bench.json
    scripts/cad_bench.py table FOLDER [projection|speedup]
        the table docs/cad.md shows, printed from FOLDER/cad-bench.json; `projection`: the
        stage times and their projection to 16 cores
    scripts/cad_bench.py --check [PAGE] | --write [PAGE]     (default docs/cad.md)
        the page's generated blocks (<!-- generated: cad_bench.py ... -->) are what `table`
        prints for their arguments / are printed into the page again

The projection to N cores takes the parent's own stages (lexing, splitting, the skeleton,
putting the solids together, the cache) as they were, and the workers' stages (parsing,
translating, healing, meshing, building, encoding: their own time, summed) spread over N
workers, no faster than the largest piece alone: serial + max(largest piece, work / N).
"""
import json
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

import doc_blocks

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, "docs", "cad.md")
SCRIPT = "cad_bench.py"
STAGES = ("parse_ms", "transfer_ms", "healing_ms", "mesh_ms", "build_ms", "levels_ms",
          "encode_ms")
SERIAL = ("lex_ms", "split_ms", "skeleton_ms", "assembly_ms")


class TreeMemory(threading.Thread):
    """Samples the resident memory of the processes below `pid` whose names are in `names`,
    added up, every 50 ms; `peak` is the most seen at once, in MiB."""

    def __init__(self, pid, names):
        super().__init__(daemon=True)
        self.pid, self.names, self.peak, self.done = pid, names, 0.0, False

    def tree(self):
        children = {}
        for entry in os.listdir("/proc"):
            if not entry.isdigit():
                continue
            try:
                with open(f"/proc/{entry}/stat") as f:
                    stat = f.read()
            except OSError:
                continue
            close = stat.rfind(")")
            name = stat[stat.find("(") + 1:close]
            parent = int(stat[close + 2:].split()[1])
            children.setdefault(parent, []).append((int(entry), name))
        found, todo = [], [self.pid]
        while todo:
            for child, name in children.get(todo.pop(), []):
                found.append((child, name))
                todo.append(child)
        return found

    def run(self):
        while not self.done:
            total = 0
            for pid, name in self.tree():
                if name not in self.names:
                    continue
                try:
                    with open(f"/proc/{pid}/status") as f:
                        m = re.search(r"^VmRSS:\s+(\d+) kB", f.read(), re.M)
                    total += int(m.group(1)) if m else 0
                except OSError:
                    pass
            self.peak = max(self.peak, total / 1024.0)
            time.sleep(0.05)


def measure(command, names, env=None, timeout=None):
    """Runs `command` under a shell of its own, sampling its tree; its wall time (s), peak
    tree memory (MiB), exit status and stdout."""
    start = time.monotonic()
    process = subprocess.Popen(["/bin/sh", "-c", "exec " + command], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, env=env,
                               start_new_session=True)
    sampler = TreeMemory(os.getpid(), names)
    sampler.start()
    try:
        out, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        # The whole group: xvfb-run's children (Xvfb, f3d) too.
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
    sampler.done = True
    sampler.join()
    return {"command": command, "seconds": round(time.monotonic() - start, 2),
            "peak_mib": round(sampler.peak), "status": process.returncode,
            "stdout": out, "stderr": err[-2000:]}


def idview_runs(idview, path, workers, cache):
    env = dict(os.environ, XDG_CACHE_HOME=cache)
    command = f"{idview} --stats --load-workers {workers} --model '{path}'"
    names = {"idview", "idview-load-wor"}
    first = measure(command, names, env)
    again = measure(command, names, env)
    for run in (first, again):
        run["stats"] = json.loads(run.pop("stdout").strip().splitlines()[-1])
    return first, again


def viewer_run(idview, path, workers, cache):
    """The viewer on `path` under Xvfb until its event lines say the model is complete (then it
    is ended): the first picture's and the whole model's seconds, from those lines, and the
    peak memory of the viewer and its workers. Run twice: the first run fills the driver's
    pipeline cache, as any earlier start of idview has, and its tessellation is then thrown
    away, so that the second, measured, opens the file for the first time. A third opens it
    again from the tessellation cache the second wrote: its whole run, from the start to the
    end of a script that waits for the model and quits, is the cached reopen."""
    viewer_once(idview, path, workers, cache)
    for entry in os.listdir(os.path.join(cache, "idview")):
        if entry.endswith(".tess"):
            os.remove(os.path.join(cache, "idview", entry))
    run = viewer_once(idview, path, workers, cache)
    run["again"] = viewer_reopen(idview, path, workers, cache)
    return run


def viewer_reopen(idview, path, workers, cache):
    """The viewer opening `path` from the tessellation cache in `cache`, from its start to the
    end of a script that waits for the model and quits: the second of two such runs, so that
    the driver's pipeline cache is warm."""
    script = os.path.join(cache, "quit.txt")
    with open(script, "w") as f:
        f.write("0 loaded\n0 quit\n")
    env = dict(os.environ, XDG_CACHE_HOME=cache, XDG_CONFIG_HOME=cache)
    command = (f"xvfb-run -a {idview} --no-saved-settings --load-workers {workers} "
               f"--script '{script}' --model '{path}'")
    for _ in range(2):
        again = measure(command, {"idview", "idview-load-wor"}, env)
    again.pop("stdout")
    return again


def reopen(entry, file, opts):
    with tempfile.TemporaryDirectory() as cache:
        filled = measure(f"{opts['--idview']} --stats --load-workers {opts['--workers']} "
                         f"--model '{file}'", {"idview"}, dict(os.environ, XDG_CACHE_HOME=cache))
        if filled["status"] != 0:
            sys.exit(f"cad_bench: {file}: {filled['stderr'].strip()}")
        entry["viewer"]["again"] = viewer_reopen(opts["--idview"], file, opts["--workers"], cache)


def added_runs(argv, measure_file):
    """FOLDER FILE... [--idview P] [--workers N]: `measure_file(entry, file, opts)` adds its
    runs to each FILE's entry of FOLDER/cad-bench.json."""
    folder, opts = argv[0], {"--idview": os.path.join(ROOT, "build", "idview"), "--workers": "0"}
    files, i = [], 1
    while i < len(argv):
        if argv[i] in opts:
            opts[argv[i]], i = argv[i + 1], i + 2
        else:
            files.append(os.path.abspath(argv[i]))
            i += 1
    path = os.path.join(folder, "cad-bench.json")
    with open(path) as f:
        results = json.load(f)
    for file in files:
        entry = next(e for e in results["files"] if e["file"] == os.path.basename(file))
        measure_file(entry, file, opts)
    with open(path, "w") as f:
        json.dump(results, f, indent=1)


def speedup(entry, file, opts):
    for workers in (1, 2):
        run = measure(f"{opts['--idview']} --stats --no-cache --load-workers {workers} "
                      f"--model '{file}'", {"idview", "idview-load-wor"})
        run["stats"] = json.loads(run.pop("stdout").strip().splitlines()[-1])
        entry[f"workers_{workers}"] = run


def load(folder):
    with open(os.path.join(ROOT, "docs", "benchmarks", folder, "cad-bench.json")) as f:
        return json.load(f)


def projected(stats, cores):
    """The load's seconds on `cores` workers, from its stage times (see the top)."""
    load = stats["load"]
    serial = sum(load[k] for k in SERIAL) + load["cache_ms"]
    work = sum(load[k] for k in STAGES)
    return (serial + max(load["largest_piece_ms"], work / cores)) / 1000.0


def table(folder, kind="times"):
    results = load(folder)
    lines = []
    if kind == "times":
        lines += ["| file | program | first picture (s) | complete (s) | cached reopen (s) | "
                  "peak memory, process tree (MiB) |",
                  "|---|---|---:|---:|---:|---:|"]
        for e in results["files"]:
            first, again = e["idview_first"], e["idview_again"]
            lines.append(f"| {e['file']} ({e['bytes'] / 1e6:.0f} MB) | | | | | |")
            rows = []
            if "viewer" in e:
                v = e["viewer"]
                reopen = v["again"]["seconds"] if "again" in v else None
                rows.append(("idview, the viewer", v["first_picture_s"], v["complete_s"], reopen,
                             v["peak_mib"]))
            rows.append(("idview `--stats`", first["stats"]["load"]["first_solid_ms"] / 1000,
                         first["seconds"], again["seconds"], first["peak_mib"]))
            f = e.get("f3d")
            if f:
                # f3d shows the model once it has read all of it, and keeps no cache. A run
                # stopped at --f3d-timeout gives a lower bound, and its peak so far.
                done = f["seconds"] if f["status"] == 0 else f"> {f['seconds']:.0f} (stopped)"
                peak = f["peak_mib"] if f["status"] == 0 else f"{f['peak_mib']} when stopped"
                rows.append(("f3d", done, done, done, peak))
            cell = lambda x: "" if x is None else x if isinstance(x, str) else f"{x:.1f}"
            for name, shown, complete, reopen, peak in rows:
                lines.append(f"| | {name} | {cell(shown)} | {cell(complete)} | {cell(reopen)} | "
                             f"{peak} |")
            if f and f["status"] == 0:
                for name, _, complete, _, peak in rows[:-1]:
                    lines.append(f"| | {name} / f3d | | **{complete / f['seconds']:.3f}** | | "
                                 f"**{peak / max(f['peak_mib'], 1):.2f}** |")
    elif kind == "speedup":
        lines += ["| file | pieces, 1 worker (s) | pieces, 2 workers (s) | speed-up | "
                  "whole load, 1 worker (s) | whole load, 2 workers (s) |",
                  "|---|---:|---:|---:|---:|---:|"]
        for e in results["files"]:
            if "workers_1" not in e:
                continue
            one, two = e["workers_1"], e["workers_2"]
            p1, p2 = one["stats"]["load"]["pieces_ms"] / 1000, two["stats"]["load"]["pieces_ms"] / 1000
            lines.append(f"| {e['file']} | {p1:.1f} | {p2:.1f} | **{p1 / p2:.2f}x** | "
                         f"{one['seconds']:.1f} | {two['seconds']:.1f} |")
    else:
        lines += ["| file | lex + split + skeleton | parse | translate | heal | mesh | build "
                  "+ encode | put together | largest piece | measured, "
                  f"{results['cores']} cores | projected, 2 | projected, 16 |",
                  "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for e in results["files"]:
            s = e["idview_first"]["stats"]
            ld = s["load"]
            sec = lambda *keys: f"{sum(ld[k] for k in keys) / 1000:.1f}"
            lines.append(
                f"| {e['file']} | {sec('lex_ms', 'split_ms', 'skeleton_ms')} | "
                f"{sec('parse_ms')} | {sec('transfer_ms')} | {sec('healing_ms')} | "
                f"{sec('mesh_ms')} | {sec('build_ms', 'encode_ms')} | {sec('assembly_ms')} | "
                f"{sec('largest_piece_ms')} | {s['load_ms'] / 1000:.1f} | "
                f"{projected(s, 2):.1f} | {projected(s, 16):.1f} |")
    lines.append(f"\n*`scripts/cad_bench.py table {folder}{'' if kind == 'times' else ' ' + kind}`"
                 f" prints this from docs/benchmarks/{folder}/cad-bench.json (idview "
                 f"{results['commit']}, {results['cores']} cores).*")
    return "\n".join(lines)


def page_blocks(path, write):
    with open(path) as f:
        lines = f.read().split("\n")
    wrong = 0
    for block in reversed(doc_blocks.blocks(lines, SCRIPT, path)):
        want = table(*block.args).split("\n")
        if lines[block.first:block.last] != want:
            if write:
                lines[block.first:block.last] = want
            else:
                wrong += 1
                print(f"{path}:{block.first}: not what `{SCRIPT} table "
                      f"{' '.join(block.args)}` prints", file=sys.stderr)
    if write:
        with open(path, "w") as f:
            f.write("\n".join(lines))
    return wrong


def main(argv):
    if len(argv) >= 3 and argv[1] == "run":
        run(argv[2:])
    elif len(argv) >= 3 and argv[1] == "speedup":
        added_runs(argv[2:], speedup)
    elif len(argv) >= 3 and argv[1] == "reopen":
        added_runs(argv[2:], reopen)
    elif len(argv) >= 3 and argv[1] == "table":
        print(table(*argv[2:4]))
    elif len(argv) >= 2 and argv[1] in ("--check", "--write"):
        sys.exit(1 if page_blocks(argv[2] if len(argv) > 2 else PAGE, argv[1] == "--write")
                 else 0)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
