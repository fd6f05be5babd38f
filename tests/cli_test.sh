#!/usr/bin/env bash
# cli_test.sh IDVIEW LAVAPIPE_ICD - idview as a user runs it: exit codes, one-line errors,
# and the files the headless path writes. Every check names itself when it fails.
source "$(dirname "$0")/cli_lib.sh"

# expect NAME CODE PATTERN -- COMMAND...: runs COMMAND, checks its exit code and that its
# stdout+stderr match the extended regex PATTERN.
expect() {
    local name=$1 code=$2 pattern=$3
    shift 4
    local out rc
    out=$("$@" 2>&1)
    rc=$?
    if [[ $rc -ne $code ]]; then
        echo "FAIL $name: exit $rc, expected $code"; echo "$out" | head -20; failures=$((failures + 1))
    elif ! grep -qE -- "$pattern" <<<"$out"; then
        echo "FAIL $name: output lacks /$pattern/"; echo "$out" | head -20; failures=$((failures + 1))
    else
        echo "ok   $name"
    fi
}

expect unknown-flag 2 "unknown option '--bogus'" -- "$idview" --bogus
# The error and where to look, not the usage that would scroll it away.
out=$("$idview" --bogus 2>&1)
rc=$?
if [[ $rc -eq 2 && $out == "idview: unknown option '--bogus'"$'\n'"see idview --help" ]]; then
    echo "ok   error-points-to-help"
else
    echo "FAIL error-points-to-help: exit $rc, expected 2 and two lines:"; echo "$out" | head -5
    failures=$((failures + 1))
fi
expect missing-value 2 '--size needs a value' -- "$idview" --headless --size
expect bad-number 2 '--frames expects a whole number' -- "$idview" --frames lots
expect help 0 '--id-image FILE' -- "$idview" --help
expect list-renderers 0 'per-draw' -- "$idview" --list-renderers
expect list-devices 0 '^0: llvmpipe.* \| CPU \| driver .* \| Vulkan 1\.[0-9]+\.[0-9]+ \| usable$' -- "$idview" --list-devices
expect no-such-index 1 '^idview: error: --device 7: there are only 1 Vulkan devices' -- "$idview" --headless --device 7
expect no-such-name 1 'no Vulkan device name contains it' -- "$idview" --headless --device radeon
expect clear-unknown 2 '^idview: --clear expects auto, pass or compute, not bogus$' -- \
    "$idview" --headless --clear bogus
expect msaa-not-power 2 '--msaa expects 1, 2, 4 or 8, not 3' -- "$idview" --headless --msaa 3
expect msaa-unsupported 1 'MSAA 8x is not supported by llvmpipe.*\(it offers 1, 4\)' -- \
    "$idview" --headless --frames 1 --size 64x48 --msaa 8
expect msaa-4 0 '64x48' -- "$idview" --headless --validation --frames 1 --size 64x48 --msaa 4
expect unwritable 1 "cannot write PNG '/nonexistent/x.png'" -- "$idview" --headless --frames 1 --size 64x48 --screenshot /nonexistent/x.png

# --view: every name idview lists (read from its own refusal, which names them all) renders
# a view of its own; --ortho changes the image; an unknown name is refused in one line.
view_names=$("$idview" --view sideways 2>&1 | sed -n "s/^idview: --view expects \(.*\), not 'sideways'$/\1/p" | tr -d ',')
expect view-unknown 2 "^idview: --view expects front, .*isometric, not 'sideways'$" -- "$idview" --view sideways
[[ $(wc -w <<<"$view_names") -ge 7 ]] || { echo "FAIL view-names: '$view_names'"; failures=$((failures + 1)); }
for v in $view_names; do
    expect "view-$v" 0 '64x48' -- "$idview" --headless --validation --scene procedural:preset=small \
        --size 64x48 --frames 1 --view "$v" --id-image "$work/view-$v.ids"
done
expect view-ortho 0 '64x48' -- "$idview" --headless --validation --scene procedural:preset=small \
    --size 64x48 --frames 1 --view front --ortho --id-image "$work/view-front-ortho.ids"
sums=$(for v in $view_names front-ortho; do md5sum <"$work/view-$v.ids"; done | sort -u | wc -l)
if [[ $sums -eq $(($(wc -w <<<"$view_names") + 1)) ]]; then
    echo "ok   views-differ ($sums distinct ID images)"
else
    echo "FAIL views-differ: $sums distinct ID images of $(($(wc -w <<<"$view_names") + 1))"
    failures=$((failures + 1))
fi

# No driver at all: exactly one line, exit 1.
out=$(VK_DRIVER_FILES=$work/none.json VK_ICD_FILENAMES=$work/none.json "$idview" --headless 2>&1)
rc=$?
if [[ $rc -eq 1 && $(wc -l <<<"$out") -eq 1 && $out == "idview: error: no Vulkan device found"* ]]; then
    echo "ok   no-driver"
else
    echo "FAIL no-driver: exit $rc, output:"; echo "$out"; failures=$((failures + 1))
fi

# Headless files: a PNG, and W*H little-endian uint32 IDs holding the tiles' 25 parts and
# the background (the in-process tests check every pixel; this checks the file format).
expect headless-files 0 '25 draws' -- "$idview" --headless --validation --scene tiles --size 160x100 \
    --frames 2 --screenshot "$work/t.png" --id-image "$work/t.ids"
if [[ $(head -c 8 "$work/t.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; then
    echo "ok   png-signature"
else
    echo "FAIL png-signature"; failures=$((failures + 1))
fi
size=$(stat -c %s "$work/t.ids" 2>/dev/null || echo 0)
values=$(od -An -v -tx4 -w4 "$work/t.ids" | sort -u | tr -d ' ' | tr '\n' ' ')
if [[ $size -eq $((160 * 100 * 4)) && $(wc -w <<<"$values") -eq 26 && $values == *ffffffff* &&
    $values == "00000000 00000001 "* ]]; then
    echo "ok   id-image-format"
else
    echo "FAIL id-image-format: size $size, values $values"; failures=$((failures + 1))
fi
# Top-left pixel is background, first row first: the first four bytes are ff ff ff ff.
[[ $(head -c 4 "$work/t.ids" | od -An -tx1 | tr -d ' \n') == ffffffff ]] &&
    echo "ok   id-image-top-left" || { echo "FAIL id-image-top-left"; failures=$((failures + 1)); }

# --pick: one JSON line per point on stdout, naming the part the ID image holds there (in
# the right format, with its object's name and path) and null on background.
picks=$("$idview" --headless --validation --scene tiles --size 160x100 --frames 1 \
    --pick 80,50 --pick 0,0 --pick 40,30 --id-image "$work/p.ids" 2>/dev/null)
pick_ok=1
[[ $(wc -l <<<"$picks") -eq 3 ]] || pick_ok=0
while read -r line; do
    x=$(sed -E 's/.*"x":([0-9]+).*/\1/' <<<"$line")
    y=$(sed -E 's/.*"y":([0-9]+).*/\1/' <<<"$line")
    id=$(od -An -tu4 -j $(((y * 160 + x) * 4)) -N4 "$work/p.ids" | tr -d ' ')
    if [[ $id == 4294967295 ]]; then
        [[ $line == "{\"x\":$x,\"y\":$y,\"part\":null,\"object\":null,\"local_part\":null,\"name\":null,\"path\":null,\"depth\":null}" ]] ||
            pick_ok=0
    else
        # tiles: 12 parts a tile sheet, objects "tile sheet #1", "tile sheet #2", "back plate".
        names=("tile sheet #1" "tile sheet #2" "back plate")
        object=$((id / 12))
        name=${names[$object]}
        [[ $line =~ ^\{\"x\":$x,\"y\":$y,\"part\":$id,\"object\":$object,\"local_part\":[0-9]+,\"name\":\"$name\",\"path\":\"tiles/$name\",\"depth\":0\.[0-9]+\}$ ]] ||
            pick_ok=0
    fi
done <<<"$picks"
[[ $pick_ok -eq 1 && $picks == *'"part":null'* && $picks == *'"part":'[0-9]* ]] && echo "ok   pick-json" ||
    { echo "FAIL pick-json:"; echo "$picks"; failures=$((failures + 1)); }
expect pick-outside 2 'pixel 200,10 is outside the 160x100 image' -- "$idview" --headless --size 160x100 --pick 200,10

# --select-rect and --visible-parts: one JSON line each, the parts the ID image holds in the
# rectangle (corners given in any order, both included) or in the whole image, sorted.
ids_in() { # ids_in X0 Y0 X1 Y1: the sorted unique IDs of $work/r.ids (160 wide) in the box
    od -An -tu4 -v -w640 "$work/r.ids" | awk -v x0="$1" -v y0="$2" -v x1="$3" -v y1="$4" \
        '{ for (x = x0; x <= x1; ++x) if (NR - 1 >= y0 && NR - 1 <= y1 && $(x + 1) != 4294967295) print $(x + 1) }' |
        sort -nu | paste -sd, -
}
sets=$("$idview" --headless --validation --scene tiles --size 160x100 --frames 1 \
    --select-rect 70,50,40,30 --visible-parts --id-image "$work/r.ids" 2>/dev/null)
rect_parts=$(ids_in 40 30 70 50)
all_parts=$(ids_in 0 0 159 99)
rect_count=$(tr ',' '\n' <<<"$rect_parts" | grep -c .)
all_count=$(tr ',' '\n' <<<"$all_parts" | grep -c .)
want=$(printf '{"rect":[40,30,70,50],"parts":[%s],"count":%s}\n{"count":%s,"parts":[%s]}' \
    "$rect_parts" "$rect_count" "$all_count" "$all_parts")
[[ $sets == "$want" && $rect_count -gt 3 && $all_count -gt $rect_count ]] && echo "ok   part-set-json" ||
    { echo "FAIL part-set-json: got"; echo "$sets"; echo "want"; echo "$want"; failures=$((failures + 1)); }
# Hiding what the rectangle showed: none of it is visible any more.
hidden=$("$idview" --headless --validation --scene tiles --size 160x100 --frames 1 --hide "$rect_parts" \
    --visible-parts 2>/dev/null)
left=$(sed -n 's/.*"parts":\[\([0-9,]*\)\].*/\1/p' <<<"$hidden" | tr ',' '\n')
if [[ -n $left ]] && ! grep -qxF -f <(tr ',' '\n' <<<"$rect_parts") <<<"$left"; then
    echo "ok   hide-visible-parts"
else
    echo "FAIL hide-visible-parts: hid $rect_parts, visible: $hidden"; failures=$((failures + 1))
fi
expect hide-unknown-part 1 '^idview: error: --hide: part 99999 is not in the scene \(its parts are 0 to 24\)' -- \
    "$idview" --headless --scene tiles --size 16x16 --frames 1 --hide 99999
expect hide-and-isolate 2 'cannot be combined' -- "$idview" --headless --hide 1 --isolate 2
expect rect-outside 2 'pixel 160,10 is outside the 160x100 image' -- "$idview" --headless --size 160x100 --select-rect 0,0,160,10
expect edge-colour 2 '--edge-color expects a colour as RRGGBB' -- "$idview" --headless --edge-color red

# Without --headless idview opens a window; with no display it says so in one line, exit 1.
out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$idview" 2>&1)
rc=$?
if [[ $rc -eq 1 && $(wc -l <<<"$out") -eq 1 && $out == "idview: error: "*"cannot open a window"* ]]; then
    echo "ok   no-display"
else
    echo "FAIL no-display: exit $rc, output:"; echo "$out"; failures=$((failures + 1))
fi

# Mesh-shader techniques say what they need; on Debian's own lavapipe (Mesa 22, no
# VK_EXT_mesh_shader) they are refused in one line, skipped by the benchmark with the reason,
# and nothing else changes.
expect list-needs-mesh 0 'mesh-fs .*\[needs VK_EXT_mesh_shader\]' -- "$idview" --list-renderers
mesa22=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -1)
if [[ -z $mesa22 ]]; then
    echo "FAIL no-mesh-device: Debian's lavapipe ICD is missing (mesa-vulkan-drivers)"
    failures=$((failures + 1))
else
    # As on a Debian 12 machine: Mesa 22 with its own libraries (not the tests' newer libdrm).
    on22() { env -u LD_LIBRARY_PATH VK_DRIVER_FILES=$mesa22 VK_ICD_FILENAMES=$mesa22 "$@"; }
    expect no-mesh-refused 1 '^idview: error: mesh-fs is unavailable here: needs VK_EXT_mesh_shader.*llvmpipe.* does not offer' -- \
        on22 "$idview" --headless --validation --renderer mesh-fs --frames 1 --size 64x48
    expect no-mesh-others-run 0 'vertex-fs \+ push' -- \
        on22 "$idview" --headless --validation --renderer vertex-fs --frames 1 --size 64x48
    expect no-mesh-benchmark 0 'mesh-fs: skipped, needs VK_EXT_mesh_shader' -- \
        on22 "$idview" --benchmark --validation --renderer vertex-fs,mesh-fs --mode push \
        --size 64x48 --frames 2 --copies 1 --scene tiles --benchmark-out "$work/no-mesh.json"
    if grep -q '"skipped":\[{"renderer":"mesh-fs","reason":"needs VK_EXT_mesh_shader' "$work/no-mesh.json" &&
        ! grep -q '"renderer":"mesh-fs"\|"renderer":"no-id-mesh"' <(grep -v skipped "$work/no-mesh.json") &&
        grep -q '"renderer":"vertex-fs","mode":"push"' "$work/no-mesh.json"; then
        echo "ok   no-mesh-benchmark-json"
    else
        echo "FAIL no-mesh-benchmark-json:"; cat "$work/no-mesh.json"; failures=$((failures + 1))
    fi
fi

# --stats: one JSON object with the scene's counts; --export writes a .glb that loads back.
expect stats-json 0 '^\{"source":"assembly".*"objects":32,.*"parts":312,.*"triangles":2360,.*"load_ms":' -- \
    "$idview" --scene assembly --stats
expect stats-vertex-fs 0 '"renderer":"vertex-fs".*"geometry_bytes":[1-9][0-9]*,"added_vertices":0,"added_vertex_bytes":0,"meshlets":0' -- \
    "$idview" --scene assembly --renderer vertex-fs --stats
expect stats-mesh-fs 0 '"renderer":"mesh-fs".*"geometry_bytes":[1-9][0-9]*,.*"meshlets":[1-9]' -- \
    "$idview" --scene assembly --renderer mesh-fs --stats
expect stats-copies 0 '"objects":96,.*"parts":936,' -- "$idview" --scene assembly --copies 3 --stats
expect export 0 '"parts":312' -- "$idview" --scene assembly --export "$work/a.glb" --stats
expect export-loads 0 '"source":".*a.glb".*"objects":32,.*"parts":312,.*"triangles":2360' -- \
    "$idview" --model "$work/a.glb" --stats
expect missing-model 1 "^idview: error: $work/none.glb: " -- "$idview" --model "$work/none.glb" --stats
# Another glTF version, or a buffer outside the model's folder: exactly one line, exit 1.
mkdir -p "$work/old" "$work/escape"
printf '{"asset":{"version":"1.0"},"buffers":{"b":{"uri":"b.bin"}},"scenes":{"s":{"nodes":[]}}}' >"$work/old/v1.gltf"
out=$("$idview" --headless --model "$work/old/v1.gltf" 2>&1)
rc=$?
if [[ $rc -eq 1 && $(wc -l <<<"$out") -eq 1 &&
    $out == "idview: error: $work/old/v1.gltf: glTF 1.0 is not supported (idview reads glTF 2.0; convert it, e.g. with Cesium's gltf-pipeline)" ]]; then
    echo "ok   gltf-1.0-refused"
else
    echo "FAIL gltf-1.0-refused: exit $rc, output:"; echo "$out"; failures=$((failures + 1))
fi
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"../v1.bin"}]}' >"$work/escape/up.gltf"
expect uri-outside-refused 1 "^idview: error: $work/escape/up.gltf: uri '../v1.bin' points outside the model's folder" -- \
    "$idview" --headless --model "$work/escape/up.gltf"
expect bad-scene 2 "--scene: unknown procedural preset 'huge'" -- "$idview" --scene procedural:preset=huge

# CAD files (samples from Debian's occt-misc): counts are checked against OCCT in the unit tests.
screw=/usr/share/opencascade/data/step/screw.step
if [[ -f $screw ]]; then
    expect cad-stats 0 '"part_mode":"faces".*"objects":1,.*"tessellation_ms":[0-9.]+,"faces_failed":0,"unit":"mm","deflection":0\.048' -- \
        "$idview" --model "$screw" --stats
    expect cad-parts-ignored 0 '"warnings":\["--parts is ignored for CAD files' -- \
        "$idview" --model "$screw" --parts components --stats
    expect cad-deflection 0 '"deflection":0\.5,' -- "$idview" --model "$screw" --deflection 0.5 --stats
    expect cad-pick 0 '"part":[0-9]+,"object":0,.*"name":"the product name"' -- \
        "$idview" --headless --validation --frames 1 --model "$screw" --size 160x100 --pick 80,50
    # Exact inspection, printed without rendering (the values are checked in test_inspect).
    num='-?[0-9][-+.e0-9]*'
    vec="\\[$num,$num,$num\\]"
    expect cad-properties 0 "^\\{\"object\":0,\"volume\":$num,\"area\":$num,\"center\":$vec,\"bbox\":\\{\"min\":$vec,\"max\":$vec,\"size\":$vec\\},\"closed\":true,\"unit\":\"mm\"\\}$" -- \
        "$idview" --model "$screw" --properties 0
    expect cad-properties-all 0 "^\\{\"object\":\"all\",\"objects\":1,\"volume\":$num," -- \
        "$idview" --model "$screw" --properties all
    expect cad-distance 0 "^\\{\"distance\":$num,\"p0\":$vec,\"p1\":$vec,\"source\":\"brep\".*\"unit\":\"mm\"\\}$" -- \
        "$idview" --model "$screw" --distance 0,3
    # With --headless, after the rendered run's lines.
    expect cad-properties-headless 0 '^\{"object":0,"volume":' -- \
        "$idview" --headless --frames 1 --size 64x48 --model "$screw" --pick 32,24 --properties 0
    expect cad-distance-range 1 '^idview: error: --distance: part 99999 is not in the scene \(its parts are 0 to [0-9]+\)$' -- \
        "$idview" --model "$screw" --distance 0,99999
    expect cad-properties-range 1 '^idview: error: --properties: object 1 is not in the scene \(its objects are 0 to 0\)$' -- \
        "$idview" --model "$screw" --properties 1
    expect cad-export 0 '"source":".*screw.glb".*"objects":1,' -- \
        bash -c '"$1" --model "$2" --export "$3" && "$1" --model "$3" --stats' _ "$idview" "$screw" "$work/screw.glb"
fi
head -c 4000 /dev/urandom >"$work/junk.STEP"
expect cad-junk 1 "^idview: error: $work/junk.STEP: not a STEP file \\(no 'ISO-10303-21' header\\)$" -- "$idview" --model "$work/junk.STEP" --stats
: >"$work/empty.igs"
expect cad-empty 1 "^idview: error: $work/empty.igs: the file is empty" -- "$idview" --model "$work/empty.igs" --stats
expect distance-one-id 2 "--distance expects A,B \\(two unique part IDs\\), not '4'" -- "$idview" --distance 4
expect cad-bad-deflection 2 '--deflection expects a length' -- "$idview" --deflection -2

# The tessellation cache in a folder of this run: a miss, then a hit; --no-cache neither.
motor=/usr/share/opencascade/data/occ/Motor-c.brep
bearing=/usr/share/opencascade/data/iges/bearing.iges
if [[ -f $motor && -f $bearing ]]; then
    cache=$work/xdg-cache
    in_cache() { XDG_CACHE_HOME=$cache "$@"; }
    expect cad-no-cache 0 '"cache":"off","cache_note":"--no-cache"' -- in_cache "$idview" --model "$motor" --stats --no-cache
    [[ -e $cache ]] && { echo "FAIL cad-no-cache wrote $cache"; failures=$((failures + 1)); }
    expect cad-cache-miss 0 '"cache":"miss","cache_note":"no entry"' -- in_cache "$idview" --model "$motor" --stats
    expect cad-cache-hit 0 '"objects":17,.*"cache":"hit"' -- in_cache "$idview" --model "$motor" --stats
    # Past --max-triangles: one line naming the file and a deflection, exit 1, headless or not.
    for f in "$motor" "$bearing"; do
        name=max-triangles-$(basename "$f")
        out=$("$idview" --headless --no-cache --model "$f" --max-triangles 1000 2>&1)
        rc=$?
        line="^idview: error: $f: the tessellation passes --max-triangles 1000 \\(about [0-9]+ triangles at deflection [0-9.e+-]+\\); try --deflection [0-9.e+-]+$"
        if [[ $rc -eq 1 && $(wc -l <<<"$out") -eq 1 ]] && grep -qE "$line" <<<"$out"; then
            echo "ok   $name"
        else
            echo "FAIL $name: exit $rc, output:"; echo "$out" | head -5; failures=$((failures + 1))
        fi
    done
    # Progress lines: into a pipe (or a file) only with --progress, then every stage of the
    # load from its start. That no line comes without it however long the load takes, on a
    # clock the test moves: tests/test_progress_lines.cpp.
    load=("$idview" --headless --no-cache --frames 1 --size 64x48 --model "$motor")
    out=$("${load[@]}" 2>&1 >/dev/null)
    if [[ $? -eq 0 && $out != *"idview: loading "* ]]; then
        echo "ok   no-progress-into-a-pipe"
    else
        echo "FAIL no-progress-into-a-pipe:"; echo "$out" | head -5; failures=$((failures + 1))
    fi
    "${load[@]}" --progress >/dev/null 2>"$work/progress.err"
    stages=$(sed -n "s|^idview: loading $motor: \([a-z ]*\) [0-9]*%$|\1|p" "$work/progress.err" |
        uniq | paste -sd, -)
    if [[ $stages == reading,tessellating,building && $(grep -c "^idview: loading $motor: building" \
        "$work/progress.err") -gt 1 ]]; then
        echo "ok   progress-with-flag: $stages"
    else
        echo "FAIL progress-with-flag: stages '$stages'"; head -5 "$work/progress.err"
        failures=$((failures + 1))
    fi
fi
expect progress-in-help 0 '--progress +print progress on stderr' -- "$idview" --help

echo "cli_test: $failures failed"
exit $((failures > 0))
