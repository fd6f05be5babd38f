#!/usr/bin/env bash
# manual_test.sh IDVIEW_DOCS IDVIEW SOURCE_DIR - the committed manual page and bash completion
# (data/) are what idview-docs writes now from the flag table, byte for byte, so they cannot
# go stale; the page lints clean under man and groff, lists every flag --help lists and has
# the sections a manual page has.
set -uo pipefail
docs=$1 idview=$2 source=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

for pair in man:idview.1 bash:idview.bash-completion; do
    kind=${pair%%:*} file=$source/data/${pair#*:}
    "$docs" "$kind" >"$work/$kind" || fail "idview-docs $kind: exit code $?"
    if diff -u "$file" "$work/$kind" >"$work/$kind.diff"; then
        ok "data/${pair#*:} is what idview-docs $kind writes"
    else
        head -40 "$work/$kind.diff"
        fail "data/${pair#*:} is stale: cmake --build build --target docs-data rewrites it"
    fi
done

page=$source/data/idview.1
# man's own check (it runs groff with -ww and the preprocessors man pages get), then groff's.
LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -E UTF-8 -l "$page" >"$work/man.txt" 2>"$work/man.err"
[[ $? -eq 0 && ! -s $work/man.err ]] && ok "man --warnings: no warning" ||
    fail "man --warnings: $(head -5 "$work/man.err")"
groff -man -ww -z "$page" 2>"$work/groff.err"
[[ $? -eq 0 && ! -s $work/groff.err ]] && ok "groff -man -ww: no warning" ||
    fail "groff -man -ww: $(head -5 "$work/groff.err")"

for section in NAME SYNOPSIS DESCRIPTION OPTIONS FILES ENVIRONMENT "EXIT STATUS" "SEE ALSO"; do
    grep -qx "\.SH $section\|\.SH \"$section\"" "$page" || fail "no section $section"
done
# Every flag --help lists, counted from the help's own lines, has its entry in the page.
help_flags=$("$idview" --help | grep -o '^  --[a-z-]*' | sed 's/^  //')
count=$(wc -l <<<"$help_flags")
missing=0
for flag in $help_flags; do
    grep -q "^  *${flag}\b" "$work/man.txt" || { missing=$((missing + 1)); echo "  $flag"; }
done
[[ $count -ge 50 && $missing -eq 0 ]] && ok "the page lists all $count flags of --help" ||
    fail "$missing of $count flags of --help are not in the page"
grep -q "^ *3 *validation messages" "$work/man.txt" && ok "EXIT STATUS lists code 3" ||
    fail "EXIT STATUS lacks code 3"

[[ $failures -eq 0 ]] || { echo "$failures failures"; exit 1; }
