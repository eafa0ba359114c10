"""Writes the Lambert box of issue 23 as a self-contained glTF: five walls (the front open) of
base colour 0.8 (the left one red, the right one green), roughness 1, metallic 0 and
KHR_materials_specular's specularFactor 0, so that every wall is Lambertian in woven and in
Cycles alike, lit only by a small emissive lamp below the ceiling; a camera looks in through the
open side. bench_adaptive --samplers measures the samplers on it.

    python3 bench/render/lambert_box.py OUT.gltf
"""

import base64
import json
import struct
import sys


def quad(corner, edge_u, edge_v):
    """Two triangles of the parallelogram corner, corner + u, corner + u + v, corner + v, facing u x v."""
    p = [corner, [c + u for c, u in zip(corner, edge_u)],
         [c + u + v for c, u, v in zip(corner, edge_u, edge_v)], [c + v for c, v in zip(corner, edge_v)]]
    n = [edge_u[1] * edge_v[2] - edge_u[2] * edge_v[1], edge_u[2] * edge_v[0] - edge_u[0] * edge_v[2],
         edge_u[0] * edge_v[1] - edge_u[1] * edge_v[0]]
    length = sum(c * c for c in n) ** 0.5
    return p, [[c / length for c in n]] * 4, [0, 1, 2, 0, 2, 3]


def quads_gltf(parts, materials, camera_node, yfov, generator):
    """A self-contained glTF of parallelograms, (name, corner, u, v, material index) each one mesh and
    node, with the materials, and a camera (its node's placement, its vertical field of view)."""
    blob, views, accessors, meshes, nodes = b"", [], [], [], []
    for name, corner, u, v, material in parts:
        positions, normals, indices = quad(corner, u, v)
        attributes = {}
        for key, data in (("POSITION", positions), ("NORMAL", normals)):
            flat = [c for p in data for c in p]
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 4 * len(flat), "target": 34962})
            accessor = {"bufferView": len(views) - 1, "componentType": 5126, "count": len(data), "type": "VEC3"}
            if key == "POSITION":
                accessor["min"] = [min(p[i] for p in data) for i in range(3)]
                accessor["max"] = [max(p[i] for p in data) for i in range(3)]
            accessors.append(accessor)
            attributes[key] = len(accessors) - 1
            blob += struct.pack("<%df" % len(flat), *flat)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 4 * len(indices), "target": 34963})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": len(indices), "type": "SCALAR"})
        blob += struct.pack("<%dI" % len(indices), *indices)
        meshes.append({"name": name, "primitives": [{"attributes": attributes, "indices": len(accessors) - 1,
                                                     "material": material}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})
    nodes.append(dict({"name": "camera", "camera": 0}, **camera_node))
    return {
        "asset": {"version": "2.0", "generator": generator},
        "extensionsUsed": ["KHR_materials_specular", "KHR_materials_emissive_strength"],
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
        "cameras": [{"type": "perspective", "perspective": {"yfov": yfov, "aspectRatio": 1, "znear": 0.05}}],
        "materials": materials,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(blob).decode()}],
        "bufferViews": views, "accessors": accessors,
    }


def main(out):
    # (name, corner, u, v, material): each wall faces into the box, which spans [-1, 1]^3.
    parts = [
        ("floor", [-1, -1, 1], [2, 0, 0], [0, 0, -2], 0),
        ("ceiling", [-1, 1, -1], [2, 0, 0], [0, 0, 2], 0),
        ("back", [-1, -1, -1], [2, 0, 0], [0, 2, 0], 0),
        ("left", [-1, -1, 1], [0, 0, -2], [0, 2, 0], 1),
        ("right", [1, -1, -1], [0, 0, 2], [0, 2, 0], 2),
        ("lamp", [-0.25, 0.98, -0.25], [0.5, 0, 0], [0, 0, 0.5], 3),
    ]

    def lambert(name, colour):
        return {"name": name, "doubleSided": True,
                "pbrMetallicRoughness": {"baseColorFactor": colour + [1], "metallicFactor": 0, "roughnessFactor": 1},
                "extensions": {"KHR_materials_specular": {"specularFactor": 0}}}

    lamp = lambert("lamp", [0, 0, 0])
    lamp["emissiveFactor"] = [1, 1, 1]
    lamp["extensions"]["KHR_materials_emissive_strength"] = {"emissiveStrength": 10}
    materials = [lambert("white", [0.8, 0.8, 0.8]), lambert("red", [0.8, 0.1, 0.1]),
                 lambert("green", [0.1, 0.8, 0.1]), lamp]
    gltf = quads_gltf(parts, materials, {"translation": [0, 0, 3.6]}, 0.62, "woven bench/render/lambert_box.py")
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)

if __name__ == "__main__":
    main(sys.argv[1])
