#!/usr/bin/env bash
# stl_cli_test.sh IDVIEW LAVAPIPE_ICD - STL files as a user opens them, and files that are not
# what their name says: each refused in exactly one line naming the file, exit 1, none of a
# reader library's own words (tinygltf's JSON errors, Open CASCADE's messages).
source "$(dirname "$0")/cli_lib.sh"

spider=/usr/share/assimp/models/STL/Spider_binary.stl
two=/usr/share/assimp/models/STL/triangle_with_two_solids.stl

# The unit is said once, "none": STL stores none.
out=$("$idview" --model "$two" --stats 2>&1)
if [[ $? -eq 0 && $(grep -o '"unit":"[a-z]*"' <<<"$out" | sort -u) == '"unit":"none"' &&
    $out == *'"objects":2,'* && $out == *'"parts":2,'* ]]; then
    echo "ok   stl-stats-unit-none"
else
    fail "stl-stats-unit-none: $out"
fi
out=$("$idview" --headless --validation --frames 1 --size 64x48 --model "$spider" 2>&1)
[[ $? -eq 0 ]] && echo "ok   stl-headless" || fail "stl-headless: $out"

# refused NAME FILE REASON: exactly one line "idview: error: FILE: REASON...", exit 1.
refused() {
    local name=$1 file=$2 reason=$3 out rc
    out=$("$idview" --headless --model "$file" --stats 2>&1)
    rc=$?
    if [[ $rc -ne 1 || $(wc -l <<<"$out") -ne 1 || $out != "idview: error: $file: $reason"* ]]; then
        fail "$name: exit $rc, output:"; echo "$out" | head -5
    elif grep -qE 'json\.|parse[_ ]error|exception|tinygltf|Error:' <<<"${out#idview: error: }"; then
        fail "$name: a library's words: $out"
    else
        echo "ok   $name"
    fi
}
echo "hello, no model here" >"$work/notreally.stl"
refused text-as-stl "$work/notreally.stl" "not an STL file"
printf '\x89PNG\r\n\x1a\n%0200d' 0 >"$work/picture.glb"
refused png-as-glb "$work/picture.glb" "not a glTF file"
printf '{"asset": ' >"$work/broken.gltf"
refused broken-json "$work/broken.gltf" "not valid JSON text: it breaks off or is malformed at line 1"
: >"$work/empty.stl"
refused empty-stl "$work/empty.stl" "the file is empty"
mkdir "$work/folder.stl"
refused folder-stl "$work/folder.stl" "a folder, not a file"
refused missing-stl "$work/missing.stl" "file not found"
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex a b c\n' >"$work/facet.stl"
refused broken-facet "$work/facet.stl" "not a readable ASCII STL file"
head -c 1000 "$spider" >"$work/cut.stl"
refused cut-binary "$work/cut.stl" "not an STL file"
head -c 3000 /dev/urandom >"$work/noise.step"
refused noise-step "$work/noise.step" "not a STEP file"
echo "CASCADE" >"$work/short.brep"
refused text-brep "$work/short.brep" "not a BREP file"
echo "text" >"$work/model.obj"
refused unknown-name "$work/model.obj" "not a file idview reads by its name; it reads glTF"

[[ $failures -eq 0 ]] && echo "all STL command-line checks passed"
exit $((failures > 0))
