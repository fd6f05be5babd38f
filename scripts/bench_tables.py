#!/usr/bin/python3
"""bench_tables.py - every table of docs/benchmarks.md, printed from the run folder under
docs/benchmarks/ that the table cites, so that the page repeats the runs and nothing else.

    scripts/bench_tables.py print KIND FOLDER [KEY=VALUE...]
        one table (KINDS below), with the line that names its files and their commands
    scripts/bench_tables.py --check [PAGE]    (default docs/benchmarks.md)
        every generated block of the page (<!-- generated: bench_tables.py ... -->) is what
        this script prints for its arguments, and every run a block reads is one that
        scripts/gpu-runs.sh makes (under the same name); exit 1 otherwise
    scripts/bench_tables.py --write [PAGE] [--from FOLDER]
        prints the blocks into the page again; with --from, every block whose files are all
        in FOLDER (a folder of docs/benchmarks/, as gpu-runs.sh writes one) cites FOLDER
        from then on, its old folder's layout and commit arguments dropped
    scripts/bench_tables.py status [PAGE]
        per block: its folder, commit, and whether each file's command (as its JSON records
        it) is the one gpu-runs.sh runs today; those that are not are made by older commands

A block's arguments: KIND FOLDER [commit=HASH] [KEY=VALUE...]. The commit is the build the
folder's runs were made with (the JSON does not record it; gpu-runs.sh writes it into the
folder's runs*.txt, read where no commit= is given). A comparison of two builds (the kinds in
bench_kinds.COMPARISONS) names the earlier build's folder too (before=FOLDER); --from leaves
it where it is, as it compares those two builds and no others.
"""
import glob
import os
import sys

import bench_kinds
import bench_runs as runs
import doc_blocks

SCRIPT = "bench_tables.py"
PAGE = os.path.join(runs.ROOT, "docs", "benchmarks.md")
# Arguments that describe an old folder's layout or build: dropped when a block moves to a
# folder gpu-runs.sh wrote.
LAYOUT = ("commit", "dir", "prefix")


def split(args):
    kind, folder = args[0], args[1]
    params = dict(a.split("=", 1) for a in args[2:])
    return kind, folder, params


def commit_of(folder, params):
    if "commit" in params:
        return params["commit"]
    for log in sorted(glob.glob(os.path.join(runs.BENCH, folder, "runs*.txt"))):
        with open(log) as f:
            for line in f:
                if line.startswith("commit: "):
                    return line.split()[1]
    return "not recorded"


def entries(args, params=None):
    """The runs a block reads, as (folder, stem, extra flags): a kind's files are in the
    block's folder unless they name another (a comparison's earlier build)."""
    kind, folder, own = split(args)
    found = bench_kinds.KINDS[kind][0](own if params is None else params)
    return [(entry[2] if len(entry) > 2 else folder, entry[0], entry[1]) for entry in found]


def source(args, used):
    """The paragraph under a table: its folders, builds, files and their commands."""
    kind, folder, params = split(args)
    folders = []
    for where, _, _ in used:
        if where not in folders:
            folders.append(where)
    where = " and ".join(
        f"[`{f}/`](benchmarks/{f}/) (commit {commit_of(f, params if f == folder else {})})"
        for f in folders)
    printed = f"printed by `scripts/bench_tables.py {' '.join(args)}`"
    cited = [(f"{f + '/' if len(folders) > 1 else ''}{stem}.json",
              runs.command(runs.flags_of(runs.load(f, stem), extra))) for f, stem, extra in used]
    if len(cited) == 1:
        name, line = cited[0]
        return f"Source: {where}, `{name}`: `{line}`; {printed}.\n"
    text = f"Source: {where}; {printed}, from:\n\n"
    return text + "".join(f"- `{name}`: `{line}`\n" for name, line in cited)


def render(args):
    kind, folder, params = split(args)
    if kind not in bench_kinds.KINDS:
        sys.exit(f"unknown table kind '{kind}' (kinds: {', '.join(bench_kinds.KINDS)})")
    used = entries(args)
    # By stem; a run of another folder (a comparison's earlier build) as FOLDER/STEM.
    loaded = {(stem if f == folder else f"{f}/{stem}"): runs.load(f, stem)
              for f, stem, _ in used}
    return doc_blocks.wrap(bench_kinds.KINDS[kind][1](loaded, params) + "\n" +
                           source(args, used))


def check_runs(page):
    """Every run a block would read from a folder gpu-runs.sh wrote (its layout arguments
    dropped) is one gpu-runs.sh makes, and gpu-runs.sh names no --benchmark-out of its own
    (it writes NAME.json). Blocks of experiments (kinds gpu-runs.sh cannot run) are left
    out."""
    made = runs.script_runs()
    bad = 0
    for name, (_, flags) in made.items():
        if "--benchmark-out" in flags:
            print(f"gpu-runs.sh: {name} names its own --benchmark-out")
            bad += 1
    with open(page) as f:
        lines = f.read().split("\n")
    for block in doc_blocks.blocks(lines, SCRIPT, page):
        kind, folder, params = split(block.args)
        if kind in bench_kinds.EXPERIMENTS:
            continue
        kept = {k: v for k, v in params.items() if k not in LAYOUT}
        for _, stem, _ in entries(block.args, kept):
            if stem not in made:
                print(f"{page}:{block.first}: gpu-runs.sh makes no run '{stem}'")
                bad += 1
    return bad


def status(page):
    made = runs.script_runs()
    with open(page) as f:
        lines = f.read().split("\n")
    for block in doc_blocks.blocks(lines, SCRIPT, page):
        kind, folder, params = split(block.args)
        print(f"{kind} {folder} (commit {commit_of(folder, params)}), line {block.first}:")
        # The same run under the name gpu-runs.sh gives it (an old folder's layout dropped).
        kept = {k: v for k, v in params.items() if k not in LAYOUT}
        for (where, stem, extra), (_, name, _) in zip(entries(block.args),
                                                      entries(block.args, kept)):
            have = runs.flags_of(runs.load(where, stem), extra)
            stem = stem if where == folder else f"{where}/{stem}"
            if name not in made:
                print(f"  {stem}: no run of gpu-runs.sh")
            elif made[name][1] == have:
                print(f"  {stem}: gpu-runs.sh part {made[name][0]}, the same command")
            else:
                print(f"  {stem}: gpu-runs.sh part {made[name][0]} runs another command:"
                      f"\n    had:  {runs.command(have)}\n    runs: {runs.command(made[name][1])}")


def retarget_to(folder):
    """A block's arguments moved to `folder` where it holds every run the block reads (None
    where not), saying which moved and which stay."""
    def retarget(args):
        kind, old, params = split(args)
        if kind in bench_kinds.COMPARISONS:
            print(f"{kind} stays at {old}: it compares two named builds")
            return None
        kept = [f"{k}={v}" for k, v in params.items() if k not in LAYOUT]
        moved = [kind, folder] + kept
        missing = [s for f, s, _ in entries(moved) if not os.path.exists(runs.path_of(f, s))]
        if missing:
            print(f"{kind} stays at {old}: {folder} has no {', '.join(missing)}")
            return None
        print(f"{kind}: {old} -> {folder}")
        return moved
    return retarget


def main(argv):
    if len(argv) >= 3 and argv[0] == "print":
        sys.stdout.write(render(argv[1:]))
        return 0
    if argv and argv[0] == "status":
        status(argv[1] if len(argv) > 1 else PAGE)
        return 0
    if argv and argv[0] in ("--check", "--write"):
        rest = argv[1:]
        folder = None
        if "--from" in rest:
            i = rest.index("--from")
            folder = rest[i + 1].rstrip("/")
            rest = rest[:i] + rest[i + 2:]
        page = rest[0] if rest else PAGE
        retarget = retarget_to(folder) if folder else None
        differ = doc_blocks.refresh(page, SCRIPT, render, argv[0] == "--write", retarget)
        bad = check_runs(page) if argv[0] == "--check" else 0
        if argv[0] == "--check" and differ:
            print(f"{differ} table(s) differ: scripts/bench_tables.py --write {page}")
        return 1 if (differ or bad) and argv[0] == "--check" else 0
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
