#!/usr/bin/env python3
"""viewer_layers.py SRC_DIR - checks that src/app/viewer's folders are layers: a file includes
only files of its own folder or of a folder below it, and nothing of the headless runs.

Bottom to top: state/ (what is shown and what the person did), commands/ (the command table
that changes it), panel/ and window/ (what shows it and feeds it; neither includes the other),
then the viewer itself, in the folder's top. Prints one line per include that breaks this
and exits 1; a file in a folder this table does not name is a break too, so a new folder
gets its place here on purpose."""
import pathlib
import re
import sys

LAYERS = {"state": 0, "commands": 1, "panel": 2, "window": 2, "": 3}
# What the viewer must not include: headless runs and the benchmark are one-shot queries.
FORBIDDEN = ("app/headless.h", "app/benchmark.h")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def folder_of(viewer, path):
    rel = path.relative_to(viewer)
    return rel.parts[0] if len(rel.parts) > 1 else ""


def main():
    src = pathlib.Path(sys.argv[1])
    viewer = src / "app" / "viewer"
    breaks, files = [], 0
    for path in sorted(viewer.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        files += 1
        own = folder_of(viewer, path)
        name = path.relative_to(src)
        if own not in LAYERS:
            breaks.append(f"{name}: folder '{own}' has no layer in viewer_layers.py")
            continue
        for target in INCLUDE.findall(path.read_text()):
            if target in FORBIDDEN:
                breaks.append(f"{name} includes {target}, which is headless")
            if not target.startswith("app/viewer/"):
                continue
            theirs = folder_of(viewer, src / target)
            if theirs not in LAYERS:
                breaks.append(f"{name} includes {target}, in no layer")
            elif theirs != own and LAYERS[theirs] >= LAYERS[own]:
                breaks.append(f"{name} ({own or 'top'}) includes {target} ({theirs or 'top'})")
    for line in breaks:
        print(line)
    print(f"viewer_layers: {files} files, {len(breaks)} includes out of their layer")
    return 1 if breaks or files == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
