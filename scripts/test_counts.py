#!/usr/bin/python3
"""test_counts.py - the counts of tests that docs/testing.md and docs/reliability.md give,
printed from a build folder's ctest lists, so the pages stay true as tests come and go.

    scripts/test_counts.py print KIND BUILD         one block (labels, files or passes)
    scripts/test_counts.py --check BUILD [PAGE...]  every block of the pages (default:
                                                    docs/testing.md, docs/reliability.md) is
                                                    what BUILD's tests give; exit 1 otherwise
    scripts/test_counts.py --write BUILD [PAGE...]  prints the blocks into the pages again

A block is <!-- generated: test_counts.py KIND --> ... <!-- end generated -->. The tests come
from `ctest --show-only=json-v1` in BUILD: their names, labels and commands. A gtest case is
counted under the tests/*.cpp file that defines its suite (TEST, TEST_F, TEST_P), a script
test under its script. A build that has not built every test binary (build-asan/, which
leaves the culling tests out) lists a placeholder for it; --check then says so and checks
nothing.
"""
import glob
import json
import os
import re
import subprocess
import sys

import doc_blocks

SCRIPT = "test_counts.py"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGES = [os.path.join(ROOT, "docs", "testing.md"), os.path.join(ROOT, "docs", "reliability.md")]
SANITIZE = os.path.join(ROOT, "scripts", "sanitize-tests.sh")
# What each label holds, for the labels table (tests/CMakeLists.txt gives them).
LABELS = {
    "unit": "no GPU: the scene model, loaders, command line, chart and table scripts",
    "lavapipe": "Vulkan on lavapipe with validation: renders, picks, passes, switches, the "
                "command-line scripts",
    "culling": "lavapipe: culling, levels of detail and the clear paths against culling off, "
               "image for image",
    "viewer": "the viewer under Xvfb on lavapipe, driven by scripts",
    "fuzz": "the glTF and CAD loaders under libFuzzer",
    "far": "models far from the origin, against the same models at the origin",
    "memory": "running out of memory under an address-space limit: one line, exit 1",
    "install": "cmake --install moved to another folder, the Debian package (cpack, lintian, unpacked and run), the launcher opening a model",
}


def tests(build):
    """[(name, labels, command)] of every test ctest lists in the build folder."""
    listed = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True,
                            text=True, check=True).stdout
    found = []
    for test in json.loads(listed)["tests"]:
        labels = []
        for prop in test.get("properties", []):
            if prop["name"] == "LABELS":
                labels = prop["value"]
        found.append((test["name"], labels, test.get("command", [])))
    return found


def not_built(found):
    return [name for name, _, _ in found if name.endswith("_NOT_BUILT")]


def source_dir(build):
    """The checkout the build folder was configured from."""
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            if line.startswith("CMAKE_HOME_DIRECTORY:"):
                return line.split("=", 1)[1].strip()
    sys.exit(f"{build}: no CMAKE_HOME_DIRECTORY in CMakeCache.txt")


def cases(source):
    """{(suite, test): file} of every gtest case the checkout's tests/*.cpp define."""
    where = {}
    for path in sorted(glob.glob(os.path.join(source, "tests", "*.cpp"))):
        with open(path) as f:
            for case in re.findall(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)", f.read()):
                where[case] = os.path.relpath(path, source)
    return where


def file_of(name, command, where, source):
    """The test's file: the script it runs, else the file that defines its gtest case
    (Prefix/Suite.Case/param for parameterized cases)."""
    for word in command:
        if word.endswith((".sh", ".py")):
            return os.path.relpath(word, source)
    suite, _, case = name.partition(".")
    key = (suite.split("/")[-1], case.split("/")[0])
    if key not in where:
        sys.exit(f"{name}: no tests/*.cpp defines {key[0]}.{key[1]}")
    return where[key]


def sanitizer_filter():
    """The labels and exclusions of the sanitizer pass's ctest line."""
    with open(SANITIZE) as f:
        text = f.read()
    labels = re.search(r"ctest [^\n]*-L '([^']+)'", text).group(1)
    excluded = re.search(r"-E '([^']+)'", text).group(1)
    return labels, excluded


def labels_table(found):
    counts = {}
    for _, labels, _ in found:
        for label in labels:
            counts[label] = counts.get(label, 0) + 1
    out = ["| label | tests | what |", "|---|---:|---|"]
    for label in sorted(counts, key=lambda l: (l not in LABELS, list(LABELS).index(l)
                                                  if l in LABELS else 0, l)):
        out.append(f"| `{label}` | {counts[label]} | {LABELS.get(label, '(not described)')} |")
    out.append(f"| all | {len(found)} | `ctest -N` in `build/` |")
    return "\n".join(out) + "\n"


def files_table(found, source):
    where = cases(source)
    rows = {}
    for name, labels, command in found:
        path = file_of(name, command, where, source)
        label, count = rows.get(path, (", ".join(labels), 0))
        rows[path] = (label, count + 1)
    out = ["| file | label | tests |", "|---|---|---:|"]
    for path in sorted(rows, key=lambda p: (rows[p][0], p)):
        out.append(f"| `{path}` | {rows[path][0]} | {rows[path][1]} |")
    return "\n".join(out) + "\n"


def cell(text):
    """Text for a table cell: a | would end the cell."""
    return text.replace("|", "\\|")


def passes_table(found):
    labels, excluded = sanitizer_filter()
    chosen = [n for n, ls, _ in found if any(re.fullmatch(labels, l) for l in ls)]
    kept = [n for n in chosen if not re.search(excluded, n)]
    out = ["| pass | what runs | tests |", "|---|---|---:|",
           f"| main | `ctest` in `build/`: every label | {len(found)} |",
           f"| sanitizers | `scripts/sanitize-tests.sh`: labels `{cell(labels)}` in "
           f"`build-asan/`, less those it leaves out | {len(kept)} |",
           f"| left out of the sanitizer pass | its `-E '{cell(excluded)}'` | "
           f"{len(chosen) - len(kept)} |"]
    return "\n".join(out) + "\n"


def render(kind, build, found):
    if kind == "files":
        return files_table(found, source_dir(build))
    return {"labels": labels_table, "passes": passes_table}[kind](found)


def main(argv):
    if len(argv) == 3 and argv[0] == "print":
        sys.stdout.write(render(argv[1], argv[2], tests(argv[2])))
        return 0
    if len(argv) >= 2 and argv[0] in ("--check", "--write"):
        found = tests(argv[1])
        missing = not_built(found)
        if missing and argv[0] == "--check":
            print(f"test_counts: {argv[1]} has not built every test ({', '.join(missing)}): "
                  "counts not checked here")
            return 0
        differ = 0
        for page in argv[2:] or PAGES:
            differ += doc_blocks.refresh(page, SCRIPT,
                                         lambda args: render(args[0], argv[1], found),
                                         argv[0] == "--write")
        if differ and argv[0] == "--check":
            print(f"{differ} block(s) differ: scripts/test_counts.py --write {argv[1]}")
            return 1
        return 0
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
