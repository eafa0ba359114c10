#!/usr/bin/env python3
"""Writes the backlit scenes of docs/RESULTS.md's "Light through the yarns" (issue 25) into assets/:

  curtain_window.gltf  a sheer curtain hanging in folds before a bright window, a floor
  lampshade.gltf       an open cylinder (a lampshade) on a table, to be lit from inside
  coloured_shadow.gltf three sheets over a floor under a lamp, for their shadows: a voile, the same
                       cloth opaque, and a leaf with KHR_materials_diffuse_transmission

Each glTF holds only geometry and plain materials; the scene files beside them
(curtain_window*.json, lampshade*.json) make the cloth woven and add the lights. Meshes carry
UVs in metres along the cloth (u across, v down the curtain; u around, v up the shade), so a
fabric's ends_per_cm and picks_per_cm give its real thread count.

Usage: tools/transmission_scenes.py [ASSETS_DIR]   (default: assets/ beside tools/)
"""
import base64
import json
import math
import os
import struct
import sys


def gltf(meshes, materials):
    """A glTF 2.0 document with one node per mesh; `meshes`: (name, material, positions,
    normals, uvs, triangles)."""
    blob = bytearray()
    views, accessors, gl_meshes, nodes = [], [], [], []

    def add(data, fmt, count, kind, target, minmax=None):
        while len(blob) % 4:
            blob.append(0)
        offset = len(blob)
        blob.extend(struct.pack("<" + fmt * count, *data))
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset, "target": target})
        acc = {"bufferView": len(views) - 1, "componentType": 5126 if fmt == "f" else 5125,
               "count": count // {"VEC3": 3, "VEC2": 2, "SCALAR": 1}[kind], "type": kind}
        if minmax:
            acc["min"], acc["max"] = minmax
        accessors.append(acc)
        return len(accessors) - 1

    for name, material, positions, normals, uvs, triangles in meshes:
        flat = [c for p in positions for c in p]
        lo = [min(p[i] for p in positions) for i in range(3)]
        hi = [max(p[i] for p in positions) for i in range(3)]
        attributes = {
            "POSITION": add(flat, "f", len(flat), "VEC3", 34962, (lo, hi)),
            "NORMAL": add([c for n in normals for c in n], "f", 3 * len(normals), "VEC3", 34962),
            "TEXCOORD_0": add([c for t in uvs for c in t], "f", 2 * len(uvs), "VEC2", 34962),
        }
        indices = add([i for t in triangles for i in t], "I", 3 * len(triangles), "SCALAR", 34963)
        gl_meshes.append({"name": name, "primitives": [{"attributes": attributes, "indices": indices, "material": material}]})
        nodes.append({"name": name, "mesh": len(gl_meshes) - 1})
    doc = {
        "asset": {"version": "2.0", "generator": "woven tools/transmission_scenes.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": gl_meshes,
        "materials": materials,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    # Every extension a material uses is declared, as the specification requires.
    used = sorted({name for m in materials for name in m.get("extensions", {})})
    if used:
        doc["extensionsUsed"] = used
    return doc


def grid(nu, nv, point, normal, uv):
    """A (nu + 1) x (nv + 1) vertex grid over s, t in [0, 1]; triangles counter-clockwise seen
    from the side `normal` points to (glTF's front face)."""
    positions, normals, uvs, triangles = [], [], [], []
    for j in range(nv + 1):
        for i in range(nu + 1):
            s, t = i / nu, j / nv
            positions.append(point(s, t))
            normals.append(normal(s, t))
            uvs.append(uv(s, t))
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i
            b, c, d = a + 1, a + nu + 2, a + nu + 1
            e1 = [positions[b][k] - positions[a][k] for k in range(3)]
            e2 = [positions[c][k] - positions[a][k] for k in range(3)]
            n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
            if sum(n[k] * normals[a][k] for k in range(3)) < 0.0:
                b, d = d, b
            triangles += [(a, b, c), (a, c, d)]
    return positions, normals, uvs, triangles


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def plain(name, color, emission=None):
    m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0], "metallicFactor": 0.0, "roughnessFactor": 0.8}}
    if emission:
        m["emissiveFactor"] = [1.0, 1.0, 1.0]
        m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": emission}}
    return m


def curtain_window():
    # The curtain: 1.6 m wide, 2.2 m tall at z ~ 0, in 6 soft folds of 4 cm depth, facing +z (the room).
    width, height, depth, folds = 1.6, 2.2, 0.04, 6
    k = 2.0 * math.pi * folds / width

    def point(s, t):
        x = (s - 0.5) * width
        return (x, height * (1.0 - t) + 0.05, depth * math.sin(k * x))

    def normal(s, t):
        x = (s - 0.5) * width
        return normalized((-depth * k * math.cos(k * x), 0.0, 1.0))

    curtain = grid(96, 8, point, normal, lambda s, t: (s * width, t * height))
    # The window: a bright pane 0.4 m behind the curtain, facing it (+z), wider than the curtain
    # so that both the bare pane and the pane through the cloth are in view.
    window = grid(1, 1, lambda s, t: ((s - 0.5) * 2.4, 0.3 + (1.0 - t) * 1.8, -0.4), lambda s, t: (0.0, 0.0, 1.0), lambda s, t: (s, t))
    floor = grid(1, 1, lambda s, t: ((s - 0.5) * 6.0, 0.0, -1.0 + t * 5.0), lambda s, t: (0.0, 1.0, 0.0), lambda s, t: (s, t))
    meshes = [("Curtain", 0, *curtain), ("Window", 1, *window), ("Floor", 2, *floor)]
    materials = [plain("Curtain", (0.8, 0.8, 0.8)), plain("Window", (0.0, 0.0, 0.0), emission=1.2), plain("Floor", (0.35, 0.3, 0.25))]
    return gltf(meshes, materials)


def lampshade():
    # The shade: an open cylinder of radius 0.15 m and height 0.24 m on a table, normals outwards.
    radius, height, base = 0.15, 0.24, 0.1

    def point(s, t):
        a = 2.0 * math.pi * s
        return (radius * math.cos(a), base + height * (1.0 - t), -radius * math.sin(a))

    def normal(s, t):
        a = 2.0 * math.pi * s
        return (math.cos(a), 0.0, -math.sin(a))

    shade = grid(96, 4, point, normal, lambda s, t: (s * 2.0 * math.pi * radius, t * height))
    table = grid(1, 1, lambda s, t: ((s - 0.5) * 3.0, 0.0, (t - 0.5) * 3.0), lambda s, t: (0.0, 1.0, 0.0), lambda s, t: (s, t))
    wall = grid(1, 1, lambda s, t: ((s - 0.5) * 3.0, (1.0 - t) * 2.0, -0.6), lambda s, t: (0.0, 0.0, 1.0), lambda s, t: (s, t))
    meshes = [("Shade", 0, *shade), ("Table", 1, *table), ("Wall", 1, *wall)]
    materials = [plain("Shade", (0.8, 0.8, 0.8)), plain("Room", (0.45, 0.42, 0.38))]
    return gltf(meshes, materials)


def coloured_shadow():
    # Three 0.5 m squares 0.35 m over the floor, side by side along x, normals up; the scene file
    # makes the first two woven (UVs in metres) and lights them from above.
    size, height = 0.5, 0.35

    def sheet(x0):
        return grid(1, 1, lambda s, t: (x0 + (s - 0.5) * size, height, (t - 0.5) * size), lambda s, t: (0.0, 1.0, 0.0),
                    lambda s, t: (s * size, t * size))

    floor = grid(1, 1, lambda s, t: ((s - 0.5) * 4.0, 0.0, (t - 0.5) * 3.0), lambda s, t: (0.0, 1.0, 0.0), lambda s, t: (s, t))
    meshes = [("Voile", 0, *sheet(-0.65)), ("Opaque", 1, *sheet(0.0)), ("Leaf", 2, *sheet(0.65)), ("Floor", 3, *floor)]
    leaf = plain("Leaf", (0.3, 0.5, 0.2))
    leaf["extensions"] = {"KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": 0.7,
                                                                 "diffuseTransmissionColorFactor": [0.2, 0.8, 0.3]}}
    materials = [plain("Voile", (0.8, 0.8, 0.8)), plain("Opaque", (0.8, 0.8, 0.8)), leaf, plain("Floor", (0.6, 0.6, 0.6))]
    return gltf(meshes, materials)


def main():
    assets = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets")
    for name, doc in (("curtain_window.gltf", curtain_window()), ("lampshade.gltf", lampshade()),
                      ("coloured_shadow.gltf", coloured_shadow())):
        with open(os.path.join(assets, name), "w") as f:
            json.dump(doc, f, separators=(",", ":"))
            f.write("\n")


if __name__ == "__main__":
    main()
