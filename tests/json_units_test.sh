#!/usr/bin/env bash
# json_units_test.sh IDVIEW LAVAPIPE_ICD - every length the headless JSON prints carries its
# unit: --measure, --face-info and --stats (and --pick, which prints no length) on a STEP
# file (millimetres, as Open CASCADE converts it), a BREP file (no unit), the default glTF
# model (metres) and a procedural scene (no unit). Each JSON line that holds a length key
# must hold "unit" with the source's unit.
source "$(dirname "$0")/cli_lib.sh"
data=/usr/share/opencascade/data

# check NAME UNIT [FLAGS...]: one headless run at 160x120 with picks across the middle row.
check() {
    local name=$1 unit=$2
    shift 2
    "$idview" --headless --validation --frames 1 --size 160x120 --measure 40,60,120,60 \
        --face-info 80,60 --pick 80,60 --stats "$@" >"$work/$name.json" 2>"$work/$name.err" || {
        echo "FAIL $name: exit code $?: $(head -c 500 "$work/$name.err")"
        failures=$((failures + 1))
        return
    }
    if python3 - "$work/$name.json" "$unit" <<'PY'; then echo "ok   $name: every length in $unit"; else failures=$((failures + 1)); fi
import json, sys
# Members that are lengths, coordinates, offsets or areas, wherever they appear.
lengths = {"distance", "delta", "p0", "p1", "area", "radius", "diameter", "d", "bbox", "center",
           "axis", "deflection", "lod_levels"}
path, unit = sys.argv[1], sys.argv[2]
seen, bad = set(), []
for line in open(path):
    line = line.strip()
    if not line.startswith("{"):
        continue
    obj = json.loads(line)
    keys = lengths & set(obj)
    if not keys:
        continue
    seen |= keys
    if obj.get("unit") != unit:
        bad.append(f"{sorted(keys)} with unit {obj.get('unit')!r}: {line[:200]}")
# The measure line, a face and the stats all came.
for wanted in ("distance", "area", "deflection"):
    if wanted not in seen:
        bad.append(f"no line held {wanted}")
for b in bad:
    print(f"FAIL {path}: {b}")
sys.exit(1 if bad else 0)
PY
}

check step mm --model "$data/step/screw.step"
check iges mm --model "$data/iges/bearing.iges"
check brep none --model "$data/occ/Ball.brep"
check gltf m
check procedural none --scene procedural:preset=small

((failures == 0)) && echo "all JSON lengths carry their unit" || exit 1
