"""doc_blocks.py - the generated parts of the docs' Markdown pages, shared by the scripts that
print them (bench_tables.py, test_counts.py).

A generated block sits between two comment lines, the first naming the script and the
arguments it prints the block from:

    <!-- generated: bench_tables.py techniques h100-2026-11-26-clear msaa=1 -->
    ...what `bench_tables.py` prints for those arguments...
    <!-- end generated -->

A script checks that every block of its own is what it prints today (--check), or writes
them again (--write); the text around the blocks is left as it is.
"""
import difflib
import re
import sys
import textwrap

START = re.compile(r"^<!-- generated: (\S+)((?: \S+)*) -->$")
END = "<!-- end generated -->"


class Block:
    """One generated block of a page: its arguments and where its text lies (line numbers,
    the marker lines excluded)."""

    def __init__(self, script, args, first, last):
        self.script, self.args, self.first, self.last = script, args, first, last

    def marker(self):
        return f"<!-- generated: {self.script} {' '.join(self.args)} -->"


def wrap(text, width=95):
    """The text with its prose lines wrapped as the pages are (table rows left whole, list
    items indented under their dash)."""
    out = []
    for line in text.split("\n"):
        if len(line) <= width or line.startswith("|"):
            out.append(line)
            continue
        indent = "  " if line.startswith("- ") else ""
        out += textwrap.wrap(line, width, subsequent_indent=indent, break_long_words=False,
                             break_on_hyphens=False)
    return "\n".join(out)


def blocks(lines, script, path):
    """The blocks of `script` in a page's lines; a start without its end stops the script."""
    found = []
    for i, line in enumerate(lines):
        m = START.match(line)
        if not m or m.group(1) != script:
            continue
        try:
            end = lines.index(END, i + 1)
        except ValueError:
            sys.exit(f"{path}:{i + 1}: generated block without '{END}'")
        found.append(Block(script, m.group(2).split(), i + 1, end))
    return found


def refresh(path, script, render, write, retarget=None):
    """Prints every block of `script` in the page at `path` again with render(args) (a
    string ending in a newline). With write, the page is saved with the new text; without,
    the differences are printed. retarget(args) may give a block new arguments first (None:
    keep them). Returns how many blocks differed."""
    with open(path) as f:
        lines = f.read().split("\n")
    changed = 0
    # From the last block up, so that earlier line numbers stay valid while text changes.
    for block in reversed(blocks(lines, script, path)):
        if retarget:
            args = retarget(block.args)
            if args is not None and args != block.args:
                block.args = args
                lines[block.first - 1] = block.marker()
                changed += 1
        want = render(block.args).rstrip("\n").split("\n")
        have = lines[block.first:block.last]
        if have == want:
            continue
        changed += 1
        if not write:
            where = f"{path}:{block.first} ({' '.join(block.args)})"
            print(f"{where} differs from what {script} prints:")
            sys.stdout.writelines(
                line + "\n" for line in difflib.unified_diff(have, want, "page", script, n=1,
                                                            lineterm=""))
        lines[block.first:block.last] = want
    if write and changed:
        with open(path, "w") as f:
            f.write("\n".join(lines))
    return changed
