#!/usr/bin/env python3
"""far_building.py OUT.gltf X,Y,Z - writes a small building (metres, glTF's y up) whose root
node is translated by X,Y,Z: the georeferenced export of issue 35 (a BIM model at its UTM
coordinates) and, with 0,0,0, the same building at the origin. One mesh node per building
element, each one primitive, so each is a part of its own (--parts primitives).

The elements never share a visible plane: where two touch (a wall on the floor slab, the roof
on the walls) the touching faces lie inside the building, and the roof overhangs the walls, so
every visible pixel has one nearest surface and no tie in depth at the origin."""
import base64
import json
import struct
import sys


def box(lo, hi):
    """24 vertices (4 per face, flat normals) and 12 triangles of an axis-aligned box."""
    faces = []
    for axis in range(3):
        for side, sign in ((lo, -1.0), (hi, 1.0)):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            corners = []
            for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis] = side[axis]
                p[u] = (lo, hi)[a][u]
                p[v] = (lo, hi)[b][v]
                corners.append(p)
            if sign < 0:
                corners.reverse()  # counter-clockwise seen from outside
            normal = [0.0, 0.0, 0.0]
            normal[axis] = sign
            faces.append((corners, normal))
    return faces


def prism(base, top_y):
    """A vertical prism (y up) over a convex counter-clockwise (seen from above) polygon of
    (x, z) points from y=0 to top_y: walls, a cap and a floor."""
    faces = []
    n = len(base)
    for i in range(n):
        (x0, z0), (x1, z1) = base[i], base[(i + 1) % n]
        nx, nz = z1 - z0, -(x1 - x0)  # outward for a counter-clockwise outline seen from +y
        length = (nx * nx + nz * nz) ** 0.5
        faces.append(([[x0, 0, z0], [x1, 0, z1], [x1, top_y, z1], [x0, top_y, z0]],
                      [nx / length, 0.0, nz / length]))
    faces.append(([[x, top_y, z] for x, z in reversed(base)], [0.0, 1.0, 0.0]))
    faces.append(([[x, 0.0, z] for x, z in base], [0.0, -1.0, 0.0]))
    return faces


def pitched_roof(x0, x1, z0, z1, eave_y, ridge_y):
    """A gable roof over x0..x1 (ridge along x) from z0 to z1: two slopes, two gables and the
    flat underside, all planar."""
    zm = 0.5 * (z0 + z1)
    a, b, c, d = [x0, eave_y, z0], [x1, eave_y, z0], [x1, eave_y, z1], [x0, eave_y, z1]
    r0, r1 = [x0, ridge_y, zm], [x1, ridge_y, zm]
    rise, run = ridge_y - eave_y, zm - z0
    length = (rise * rise + run * run) ** 0.5
    return [([a, r0, r1, b], [0.0, run / length, -rise / length]),
            ([c, r1, r0, d], [0.0, run / length, rise / length]),
            ([a, d, r0], [-1.0, 0.0, 0.0]),
            ([b, r1, c], [1.0, 0.0, 0.0]),
            ([a, b, c, d], [0.0, -1.0, 0.0])]


def elements():
    """(name, faces, local translation) of each building element; about 24 x 14 x 18 m."""
    height = 9.0
    walls = [  # outer walls 0.3 m thick on a 20 x 12 m footprint
        ("south wall", box((0.0, 0.0, 0.0), (20.0, height, 0.3))),
        ("north wall", box((0.0, 0.0, 11.7), (20.0, height, 12.0))),
        ("west wall", box((0.0, 0.0, 0.3), (0.3, height, 11.7))),
        ("east wall", box((19.7, 0.0, 0.3), (20.0, height, 11.7))),
    ]
    out = [("floor slab", box((-1.0, -0.4, -1.0), (21.0, 0.0, 13.0)), (0.0, 0.0, 0.0))]
    out += [(name, faces, (0.0, 0.0, 0.0)) for name, faces in walls]
    out.append(("roof", pitched_roof(-0.8, 20.8, -0.8, 12.8, height, 13.5), (0.0, 0.0, 0.0)))
    out.append(("chimney", box((0.0, 0.0, 0.0), (1.0, 3.5, 1.0)), (14.0, 11.0, 3.0)))
    # A stair tower beside the building and an octagonal tank in front of it.
    out.append(("tower", box((0.0, 0.0, 0.0), (3.0, 17.5, 3.0)), (21.5, 0.0, 4.0)))
    octagon = [(2.0 * c, 2.0 * s) for c, s in (
        (1, 0), (0.7071, -0.7071), (0, -1), (-0.7071, -0.7071),
        (-1, 0), (-0.7071, 0.7071), (0, 1), (0.7071, 0.7071))]
    out.append(("tank", prism(octagon, 4.0), (5.0, 0.0, 15.5)))
    out.append(("door canopy", box((0.0, 0.0, 0.0), (3.0, 0.2, 1.2)), (8.0, 3.0, 12.0)))
    return out


def triangles(faces):
    positions, normals, indices = [], [], []
    for corners, normal in faces:
        first = len(positions)
        positions += corners
        normals += [normal] * len(corners)
        for i in range(1, len(corners) - 1):
            indices += [first, first + i, first + i + 1]
    return positions, normals, indices


def write(path, offset):
    blob = bytearray()
    views, accessors, meshes, nodes = [], [], [], []

    def add_view(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                      "target": target})
        blob.extend(data)
        return len(views) - 1

    for name, faces, translation in elements():
        positions, normals, indices = triangles(faces)
        flat = [c for p in positions for c in p]
        pos_view = add_view(struct.pack("<%df" % len(flat), *flat), 34962)
        nflat = [c for n in normals for c in n]
        nrm_view = add_view(struct.pack("<%df" % len(nflat), *nflat), 34962)
        idx_view = add_view(struct.pack("<%dH" % len(indices), *indices), 34963)
        # accessor min/max as float32 rounds them, so the validator's check of them holds.
        f32 = [[struct.unpack("<f", struct.pack("<f", p[k]))[0] for p in positions]
               for k in range(3)]
        accessors.append({"bufferView": pos_view, "componentType": 5126, "count": len(positions),
                          "type": "VEC3", "min": [min(a) for a in f32],
                          "max": [max(a) for a in f32]})
        accessors.append({"bufferView": nrm_view, "componentType": 5126, "count": len(normals),
                          "type": "VEC3"})
        accessors.append({"bufferView": idx_view, "componentType": 5123, "count": len(indices),
                          "type": "SCALAR"})
        meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": len(accessors) - 3, "NORMAL": len(accessors) - 2},
            "indices": len(accessors) - 1}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1, "translation": list(translation)})

    # The same node at the origin (0, 0, 0) and far, so only the numbers differ.
    root = {"name": "site", "children": list(range(len(nodes))), "translation": list(offset)}
    nodes.append(root)
    doc = {
        "asset": {"version": "2.0", "generator": "idview tests/far_building.py"},
        "scene": 0,
        "scenes": [{"nodes": [len(nodes) - 1]}],
        "nodes": nodes,
        "meshes": meshes,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(blob)).decode("ascii")}],
    }
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: far_building.py OUT.gltf X,Y,Z")
    write(sys.argv[1], [float(v) for v in sys.argv[2].split(",")])
