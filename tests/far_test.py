#!/usr/bin/env python3
"""far_test.py IDVIEW STEP_WRITER [--offset-scale S] - a model far from the origin draws and
measures as it does at the origin (issue 35), through idview's headless CLI on lavapipe.

Two pairs of models, made here: a building (glTF, metres, tests/far_building.py) and the same
with its root node at (458000, 5439000, 110), as a georeferenced BIM export places it; and a
machine (STEP assembly, millimetres, idview_far_step_writer) and the same with its top-level
placement at (2e6, -3.5e6, 8e5) mm. The fitted opening camera sees each pair alike, relative
to the model. Then:
  - every renderer x per-draw mode (read from --list-renderers), culling off and occlusion:
    the far ID image equals the origin's pixel for pixel, except where two parts tie in depth,
    which must be proven: drawn alone at the origin (--isolate), both parts show at that pixel
    and their picked depths agree within 1e-6 relative;
  - two faces 0.1 mm apart, a kilometre from the camera, stay distinct in the ID image;
  - --measure between the same pixels and --face-info on the same parts: distances and areas
    equal to 1e-9 relative, points, boxes, plane offsets and centres equal the origin's plus
    the offset within 1e-6 of the model's size.
--offset-scale S (or IDVIEW_FAR_OFFSET_SCALE=S, as test_far_pick.cpp reads it) multiplies both
offsets: 0 checks this harness, both files then holding the origin's numbers. Every failure prints a line starting FAIL; the exit code is their count."""
import concurrent.futures
import json
import os
import struct
import subprocess
import sys
import tempfile

W, H = 320, 240
BACKGROUND = 0xFFFFFFFF
MAX_DIFFS_TO_PROVE = 400  # beyond this many differing pixels the test fails without proofs
TIE_RELATIVE = 1e-6
SAME_RELATIVE = 1e-9  # distances and areas
POINT_OF_SIZE = 1e-6  # points: a fraction of the model's size

failures = 0
PIXEL_LINES = 10  # pixels named one by one per model; the rest are counted


def fail(message):
    global failures
    failures += 1
    print("FAIL " + message, flush=True)


def fail_pixels(model, messages):
    """One failure per pixel, the first PIXEL_LINES of them named."""
    global failures
    for m in messages[:PIXEL_LINES]:
        fail("%s: %s" % (model.name, m))
    if len(messages) > PIXEL_LINES:
        failures += len(messages) - PIXEL_LINES
        print("FAIL %s: %d more pixels like these" % (model.name, len(messages) - PIXEL_LINES))


def run(idview, args):
    """idview --headless --validation ARGS: its stdout lines; a failure if it exits non-zero."""
    cmd = [idview, "--headless", "--validation", "--size", "%dx%d" % (W, H)] + args
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        fail("exit %d: %s\n%s" % (p.returncode, " ".join(cmd), p.stderr[-2000:]))
        return None
    return p.stdout.splitlines()


def listed(idview):
    """The renderers (those with part IDs) and per-draw modes --list-renderers prints."""
    out = subprocess.run([idview, "--list-renderers"], capture_output=True, text=True,
                         check=True).stdout
    sections, current = {}, None
    for line in out.splitlines():
        if not line.startswith(" "):
            current = line.rstrip(":").split(" (")[0]
            sections[current] = []
        elif current and line.startswith("  ") and not line.startswith("   "):
            sections[current].append(line.split()[0])
    return sections["renderers"], sections["per-draw modes"], sections["culling modes"]


def read_ids(path):
    with open(path, "rb") as f:
        data = f.read()
    if len(data) != W * H * 4:
        fail("%s holds %d bytes, not %d" % (path, len(data), W * H * 4))
        return None
    return struct.unpack("<%dI" % (W * H), data)


class Model:
    def __init__(self, name, origin, far, offset, size):
        self.name, self.origin, self.far, self.offset, self.size = name, origin, far, offset, size


def make_models(work, writer, scale):
    here = os.path.dirname(os.path.abspath(__file__))
    gltf_offset = [458000.0 * scale, 5439000.0 * scale, 110.0 * scale]
    step_offset = [2e6 * scale, -3.5e6 * scale, 8e5 * scale]
    models = []
    paths = {}
    for name, offset in (("building", [0.0, 0.0, 0.0]), ("building-far", gltf_offset)):
        paths[name] = os.path.join(work, name + ".gltf")
        subprocess.run([sys.executable, os.path.join(here, "far_building.py"), paths[name],
                        ",".join(repr(v) for v in offset)], check=True)
    for name, offset in (("machine", [0.0, 0.0, 0.0]), ("machine-far", step_offset)):
        paths[name] = os.path.join(work, name + ".step")
        # Open CASCADE's writer prints its statistics on stdout: kept out of the test's output.
        subprocess.run([writer, paths[name]] + [repr(v) for v in offset], check=True,
                       stdout=subprocess.DEVNULL)
    # Sizes: a little under each model's bounding box diagonal (about 35 m and 1000 mm), so
    # the point tolerances are, if anything, tighter than 1e-6 of the size.
    models.append(Model("building", paths["building"], paths["building-far"], gltf_offset, 30.0))
    models.append(Model("machine", paths["machine"], paths["machine-far"], step_offset, 900.0))
    return models


def render(idview, model, work, which, renderer, mode, culling):
    """The ID image of the origin's or the far model (`which`) with one combination."""
    out = os.path.join(work, "%s-%s-%s-%s-%s.ids" % (model.name, which, renderer, mode, culling))
    path = model.origin if which == "origin" else model.far
    # Occlusion culling tests the second frame against the first's ID image.
    frames = "1" if culling == "off" else "2"
    if run(idview, ["--model", path, "--frames", frames, "--renderer", renderer, "--mode", mode,
                    "--culling", culling, "--id-image", out]) is None:
        return None
    return read_ids(out)


def far_against_origin(idview, model, work, reference, combo):
    """The far model's image with `combo`, and the origin's to compare it with: `reference`
    (the origin with the first combination) where they are equal, since every combination
    draws the same image (test_techniques, test_culling), else the origin's with `combo`
    itself, so that a difference is never one between combinations."""
    far = render(idview, model, work, "far", *combo)
    if far is None or far == reference:
        return reference, far
    return render(idview, model, work, "origin", *combo), far


def compare_images(model, combo, origin, far):
    """The pixels that differ, as (x, y, origin's part, far's part); prints a line per
    combination."""
    covered = sum(1 for v in origin if v != BACKGROUND)
    parts = len(set(origin) - {BACKGROUND})
    # The origin image must show the model, or an equal pair proves nothing.
    if covered < W * H // 20 or parts < 8:
        fail("%s %s: the origin image covers %d pixels with %d parts" % (model.name, combo,
                                                                        covered, parts))
    diffs = [(i % W, i // W, a, b) for i, (a, b) in enumerate(zip(origin, far)) if a != b]
    print("%s %-40s %5d of %5d covered pixels differ" % ("ok  " if not diffs else "diff",
                                                         model.name + " " + combo, len(diffs),
                                                         covered), flush=True)
    return diffs


def prove_ties(idview, model, diffs):
    """Each differing pixel must be a tie: at the origin, each of its two parts drawn alone
    shows at that pixel, at depths equal within TIE_RELATIVE."""
    if not diffs:
        return
    if len(diffs) > MAX_DIFFS_TO_PROVE:
        fail("%s: %d differing pixels (of every combination), more than the %d ties this test "
             "proves" % (model.name, len(diffs), MAX_DIFFS_TO_PROVE))
        return
    fail_pixels(model, ["pixel %d,%d shows part %s at the origin and %s far: a part against "
                        "the background is no tie" % (x, y, a if a != BACKGROUND else "none",
                                                      b if b != BACKGROUND else "none")
                        for x, y, a, b in diffs if BACKGROUND in (a, b)])
    pairs = [d for d in diffs if BACKGROUND not in d[2:]]
    pixels_of = {}
    for x, y, a, b in pairs:
        for part in (a, b):
            pixels_of.setdefault(part, set()).add((x, y))
    depth = {}
    for part, pixels in sorted(pixels_of.items()):
        pixels = sorted(pixels)
        args = ["--model", model.origin, "--frames", "1", "--isolate", str(part)]
        for x, y in pixels:
            args += ["--pick", "%d,%d" % (x, y)]
        lines = run(idview, args)
        if lines is None:
            continue
        for line in lines:
            pick = json.loads(line)
            if pick["part"] == part:
                depth[(part, pick["x"], pick["y"])] = pick["depth"]
    untied = []
    for x, y, a, b in pairs:
        da, db = depth.get((a, x, y)), depth.get((b, x, y))
        if da is None or db is None:
            untied.append("pixel %d,%d shows part %d at the origin and %d far, but part %d "
                          "alone does not cover it: no tie" % (x, y, a, b,
                                                               a if da is None else b))
        elif abs(da - db) > TIE_RELATIVE * max(abs(da), abs(db)):
            untied.append("pixel %d,%d shows part %d at the origin and %d far, at depths %.9g "
                          "and %.9g: no tie" % (x, y, a, b, da, db))
    fail_pixels(model, untied)


def interior_pixels(ids, count):
    """One pixel deep inside each of the `count` largest parts (its 5x5 neighbourhood all the
    part): the middle one of those in scan order."""
    inside = {}
    for y in range(2, H - 2):
        for x in range(2, W - 2):
            part = ids[y * W + x]
            if part == BACKGROUND:
                continue
            if all(ids[(y + dy) * W + x + dx] == part for dy in range(-2, 3)
                   for dx in range(-2, 3)):
                inside.setdefault(part, []).append((x, y))
    largest = sorted(inside, key=lambda p: -len(inside[p]))[:count]
    return [inside[p][len(inside[p]) // 2] for p in largest]


def near(a, b, tolerance):
    return all(abs(u - v) <= tolerance for u, v in zip(a, b)) and len(a) == len(b)


def shifted(p, offset):
    return [u + o for u, o in zip(p, offset)]


def same_number(a, b):
    return abs(a - b) <= SAME_RELATIVE * max(abs(a), abs(b))


def compare_measure(model, what, o, f):
    tol = POINT_OF_SIZE * model.size
    if o["parts"] != f["parts"]:
        fail("%s %s: parts %s at the origin, %s far" % (model.name, what, o["parts"], f["parts"]))
        return
    if o["p0"] is None or o["p1"] is None:
        fail("%s %s: the origin's points are %s" % (model.name, what, o))
        return
    for key in ("p0", "p1"):
        if not near(f[key], shifted(o[key], model.offset), tol):
            fail("%s %s: %s far %s, origin's plus the offset %s (tolerance %g)" %
                 (model.name, what, key, f[key], shifted(o[key], model.offset), tol))
    if not near(f["delta"], o["delta"], tol):
        fail("%s %s: delta %s far, %s at the origin" % (model.name, what, f["delta"], o["delta"]))
    if not same_number(o["distance"], f["distance"]):
        fail("%s %s: distance %.17g far, %.17g at the origin (%.2g relative)" %
             (model.name, what, f["distance"], o["distance"],
              abs(f["distance"] - o["distance"]) / o["distance"]))
    if o["unit"] != f["unit"]:
        fail("%s %s: unit %s far, %s at the origin" % (model.name, what, f["unit"], o["unit"]))


def compare_face(model, what, o, f):
    tol = POINT_OF_SIZE * model.size
    for key in ("part", "object", "face", "surface", "unit"):
        if o.get(key) != f.get(key):
            fail("%s %s: %s %s far, %s at the origin" % (model.name, what, key, f.get(key),
                                                       o.get(key)))
            return
    for key in ("area", "radius"):
        if key in o and not same_number(o[key], f[key]):
            fail("%s %s: %s %.17g far, %.17g at the origin" % (model.name, what, key, f[key],
                                                              o[key]))
    if "normal" in o:
        if not near(f["normal"], o["normal"], SAME_RELATIVE):
            fail("%s %s: normal %s far, %s at the origin" % (model.name, what, f["normal"],
                                                            o["normal"]))
        # Planes n.p = d: moved by the offset, d grows by n.offset.
        want = o["d"] + sum(n * v for n, v in zip(o["normal"], model.offset))
        if abs(f["d"] - want) > tol:
            fail("%s %s: plane d %.17g far, want %.17g" % (model.name, what, f["d"], want))
    if "center" in o and not near(f["center"], shifted(o["center"], model.offset), tol):
        fail("%s %s: center %s far, origin's plus the offset %s" %
             (model.name, what, f["center"], shifted(o["center"], model.offset)))
    if "axis" in o:
        if not near(f["axis"]["direction"], o["axis"]["direction"], SAME_RELATIVE) or not near(
                f["axis"]["origin"], shifted(o["axis"]["origin"], model.offset), tol):
            fail("%s %s: axis %s far, %s at the origin" % (model.name, what, f["axis"],
                                                          o["axis"]))
    for key in ("min", "max"):
        if not near(f["bbox"][key], shifted(o["bbox"][key], model.offset), tol):
            fail("%s %s: bbox %s %s far, origin's plus the offset %s" %
                 (model.name, what, key, f["bbox"][key], shifted(o["bbox"][key], model.offset)))


def measure_and_faces(idview, model, reference):
    """--measure between pairs of part interiors and --face-info on those parts, at the
    origin and far."""
    pixels = interior_pixels(reference, 6)
    if len(pixels) < 6:
        fail("%s: only %d parts with an interior to measure" % (model.name, len(pixels)))
    checked = 0
    for (x0, y0), (x1, y1) in zip(pixels[0::2], pixels[1::2]):
        args = ["--frames", "1", "--measure", "%d,%d,%d,%d" % (x0, y0, x1, y1),
                "--face-info", "%d,%d" % (x0, y0), "--face-info", "%d,%d" % (x1, y1)]
        results = []
        for path in (model.origin, model.far):
            lines = run(idview, ["--model", path] + args)
            if lines is None:
                return
            results.append([json.loads(line) for line in lines])
        o, f = results
        if len(o) != 3 or len(f) != 3:
            fail("%s: expected a measure line and two face lines, got %s and %s" % (
                model.name, o, f))
            continue
        compare_measure(model, "measure %d,%d-%d,%d" % (x0, y0, x1, y1), o[0], f[0])
        compare_face(model, "face-info %d,%d" % (x0, y0), o[1], f[1])
        compare_face(model, "face-info %d,%d" % (x1, y1), o[2], f[2])
        checked += 1
        print("     %s measure %d,%d-%d,%d: distance %.9g at the origin, %.9g far" % (
            model.name, x0, y0, x1, y1, o[0]["distance"] or 0, f[0]["distance"] or 0), flush=True)
    if checked == 0:
        fail("%s: nothing measured" % model.name)


def gap_stays_distinct(idview, writer, work):
    """Two faces 0.1 mm apart, about a kilometre from the fitted camera (idview_far_step_writer
    --gap): wherever the upper face shows when drawn alone, it shows when both are drawn."""
    path = os.path.join(work, "gap.step")
    # IDVIEW_FAR_GAP_MM: a wider gap, to check this part of the harness where 0.1 mm fails.
    gap = os.environ.get("IDVIEW_FAR_GAP_MM", "0.1")
    subprocess.run([writer, "--gap", path, gap], check=True, stdout=subprocess.DEVNULL)
    both, alone = os.path.join(work, "gap.ids"), os.path.join(work, "gap-sheet.ids")
    # The sheet is the second solid: parts 6 to 11 (a box's six faces).
    if run(idview, ["--model", path, "--frames", "1", "--id-image", both]) is None or run(
            idview, ["--model", path, "--frames", "1", "--isolate", "6,7,8,9,10,11",
                     "--id-image", alone]) is None:
        return
    both, alone = read_ids(both), read_ids(alone)
    if both is None or alone is None:
        return
    shown = [v for v in alone if v != BACKGROUND]
    # The upper face is the sheet's part that covers most of its picture.
    top = max(set(shown), key=shown.count) if shown else None
    covered = [i for i, v in enumerate(alone) if v == top]
    lost = [i for i in covered if both[i] != top]
    print("%s gap: the upper face covers %d pixels, %d of them show another part" % (
        "ok  " if not lost else "diff", len(covered), len(lost)), flush=True)
    if len(covered) < W * H // 20:
        fail("gap: the upper face covers only %d pixels" % len(covered))
    fail_pixels(Model("gap", path, path, [0.0, 0.0, 0.0], 0.0),
                ["pixel %d,%d shows part %d, not the upper face %d %s mm above it" % (
                    i % W, i // W, both[i], top, gap) for i in lost])


def main():
    args = sys.argv[1:]
    scale = float(os.environ.get("IDVIEW_FAR_OFFSET_SCALE", "1"))
    if "--offset-scale" in args:
        i = args.index("--offset-scale")
        scale = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        sys.exit("usage: far_test.py IDVIEW STEP_WRITER [--offset-scale S]")
    idview, writer = args
    renderers, modes, cull_modes = listed(idview)
    # Culling off, and the one that leaves out the most (occlusion takes in frustum).
    cullings = [c for c in ("off", "occlusion") if c in cull_modes]
    if len(renderers) < 2 or not modes or len(cullings) != 2:
        fail("--list-renderers gave renderers %s, modes %s, culling %s" % (renderers, modes,
                                                                           cull_modes))
        return failures
    with tempfile.TemporaryDirectory() as work:
        # CAD tessellations and pipelines are cached in the build's folder that ctest names
        # (shared with the other tests, so pipelines compiled there are found), never in the
        # cache of the user who runs this by hand.
        os.environ.setdefault("XDG_CACHE_HOME", os.path.join(work, "xdg-cache"))
        models = make_models(work, writer, scale)
        combos = [(r, m, c) for r in renderers for m in modes for c in cullings]
        # Two runs at a time: each is a process of its own, so the order cannot matter.
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            for model in models:
                reference = render(idview, model, work, "origin", *combos[0])
                if reference is None:
                    continue
                pairs = list(pool.map(
                    lambda c: far_against_origin(idview, model, work, reference, c), combos))
                diffs, differing = set(), []
                for combo, (origin, far) in zip(combos, pairs):
                    if origin is not None and far is not None:
                        found = compare_images(model, " ".join(combo), origin, far)
                        diffs.update(found)
                        if found:
                            differing.append(len(found))
                print("     %s: %d of %d combinations differ from the origin's image, by %d to "
                      "%d pixels, %d distinct" % (model.name, len(differing), len(combos),
                                                  min(differing, default=0),
                                                  max(differing, default=0), len(diffs)))
                prove_ties(idview, model, sorted(diffs))
                measure_and_faces(idview, model, reference)
        gap_stays_distinct(idview, writer, work)
    print("%d failures" % failures)
    return failures


if __name__ == "__main__":
    sys.exit(min(main(), 125))
