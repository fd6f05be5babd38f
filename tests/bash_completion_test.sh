#!/usr/bin/env bash
# bash_completion_test.sh COMPLETION IDVIEW - the bash completion (data/idview.bash-completion)
# as bash calls it: COMP_WORDS and COMP_CWORD set, _idview called, COMPREPLY checked against
# what idview itself lists (--help's flags, --list-renderers' names) and files on disk.
set -uo pipefail
completion=$1 idview=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

# shellcheck source=/dev/null
source "$completion"
complete -p idview | grep -q -- "-F _idview" || fail "complete -F _idview idview not set"
# complete WORD...: the command line up to the cursor, the last word the one completed; the
# replies sorted, one a line.
complete_words() {
    COMP_WORDS=(idview "$@")
    COMP_CWORD=$#
    COMPREPLY=()
    _idview
    printf '%s\n' "${COMPREPLY[@]}" | sed '/^$/d' | sort
}
expect() { # NAME WANT GOT
    [[ $2 == "$3" ]] && ok "$1" || fail "$1: want '$(echo $2)', got '$(echo $3)'"
}

expect "--ren completes to --renderer" "--renderer" "$(complete_words --ren)"
flags=$("$idview" --help | grep -o '^  --[a-z-]*' | sed 's/^  //' | sort)
expect "-- offers every flag of --help" "$flags" "$(complete_words --)"

# --list-renderers' sections: renderers, per-draw modes, the reference floors, culling modes.
section() { "$idview" --list-renderers | awk -v s="$1" '/^[a-z]/ { on = index($0, s) == 1; next }
    on && /^  [a-z]/ { print $1 }'; }
renderers=$( (section renderers; section reference; echo all) | sort)
expect "--renderer offers the renderers" "$renderers" "$(complete_words --renderer '')"
expect "--renderer= offers them too" "$renderers" "$(complete_words --renderer = '')"
modes=$( (section per-draw; echo all) | sort)
expect "--mode offers the per-draw modes" "$modes" "$(complete_words --mode '')"
expect "--mode mdi offers the mdi modes" "$(grep '^mdi' <<<"$modes")" "$(complete_words --mode mdi)"
expect "--culling offers the culling modes" "$( (section culling; echo all) | sort)" \
    "$(complete_words --culling '')"
expect "--nsearch-guess offers on and off" "$(printf 'off\non')" "$(complete_words --nsearch-guess '')"
expect "--size offers nothing to type over" "" "$(complete_words --size '')"

# Files: --model offers folders and the model files idview reads, in any case; --screenshot
# every file; --shader-dir folders.
mkdir -p "$work/sub"
touch "$work/a.step" "$work/b.STP" "$work/c.glb" "$work/d.txt" "$work/e.iges"
cd "$work" || exit 1
expect "--model offers folders and model files" "$(printf 'a.step\nb.STP\nc.glb\ne.iges\nsub')" \
    "$(complete_words --model '')"
expect "a bare word offers model files" "$(printf 'a.step\nb.STP\nc.glb\ne.iges\nsub')" \
    "$(complete_words '')"
expect "--screenshot offers every file" "$(printf 'a.step\nb.STP\nc.glb\nd.txt\ne.iges\nsub')" \
    "$(complete_words --screenshot '')"
expect "--shader-dir offers folders" "sub" "$(complete_words --shader-dir '')"

[[ $failures -eq 0 ]] || { echo "$failures failures"; exit 1; }
