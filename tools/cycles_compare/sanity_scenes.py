"""Small generated glTF files whose Cycles and woven renders should agree closely.

Each is a self-contained .gltf (the buffer is a base64 data URI) with one material:
baseColor 0.8, metallic 0, roughness 1 unless stated. Under a uniform environment these test
the harness itself (camera, units, bounce counts), not woven's glTF material support.

    sphere_lambert   a UV sphere of radius 1: convex, so only direct light (no interreflection)
    sphere_on_floor  the sphere resting on a 6 x 6 floor: light bounces between the two, so
                     a wrong bounce-count mapping shows up at --max-depth 1 and 2
    mirror_sphere    metallic 1, roughness 0, baseColor 1: reflects the environment
    mirror_on_mirror the mirror sphere on a mirror floor: at --max-depth 1 (direct light only)
                     the sphere's reflection of the floor is black in both renderers, at 2
                     it shows the environment; this checks the bounce-count mapping, which
                     the Lambert scenes cannot (woven's and Cycles' diffuse models differ)

LIGHT_SCENES are for a black environment (compare.py --env-color 0 0 0):

    point_light_floor  a 4 x 4 white floor at y = 0 lit by a KHR_lights_punctual point light of
                       683 cd at (0, 1, 0): shows how each renderer converts light units
                       (Blender's importer: 683 cd -> 4 pi W -> 1 W/sr; woven: 683 W/sr)

Run as a script to write them all: /usr/bin/python3 sanity_scenes.py OUT_FOLDER
"""

import base64
import json
import math
import os

import numpy as np

SCENES = ("sphere_lambert", "sphere_on_floor", "mirror_sphere", "mirror_on_mirror")
LIGHT_SCENES = ("point_light_floor",)

# glTF constants
_FLOAT, _UINT32 = 5126, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963


def uv_sphere(radius=1.0, rings=48, segments=96):
    """Positions, normals and triangle indices of a UV sphere centred at the origin."""
    positions, normals = [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2.0 * math.pi * j / segments
            n = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            normals.append(n)
            positions.append(tuple(radius * c for c in n))
    indices = []
    row = segments + 1
    for i in range(rings):
        for j in range(segments):
            a, b = i * row + j, (i + 1) * row + j
            # Counter-clockwise seen from outside (glTF's front face).
            if i != 0:
                indices += [a, b, a + 1]
            if i != rings - 1:
                indices += [a + 1, b, b + 1]
    return (np.array(positions, np.float32), np.array(normals, np.float32),
            np.array(indices, np.uint32))


def floor_quad(half_size, height):
    positions = np.array([[-half_size, height, -half_size], [-half_size, height, half_size],
                          [half_size, height, half_size], [half_size, height, -half_size]], np.float32)
    normals = np.tile(np.array([0.0, 1.0, 0.0], np.float32), (4, 1))
    indices = np.array([0, 1, 2, 0, 2, 3], np.uint32)
    return positions, normals, indices


class GltfBuilder:
    """Collects meshes into one glTF document with a single embedded buffer."""

    def __init__(self):
        self.blob = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "woven cycles_compare"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [],
                    "materials": [], "accessors": [], "bufferViews": [], "buffers": []}

    def material(self, name, base_color, metallic, roughness):
        self.doc["materials"].append({"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": list(base_color) + [1.0],
            "metallicFactor": metallic, "roughnessFactor": roughness}})
        return len(self.doc["materials"]) - 1

    def _accessor(self, array, target, component_type, kind):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.blob),
                                        "byteLength": array.nbytes, "target": target})
        self.blob += array.tobytes()
        accessor = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component_type,
                    "count": int(array.shape[0]) if kind != "SCALAR" else int(array.size), "type": kind}
        if kind == "VEC3" and target == _ARRAY_BUFFER:
            accessor["min"] = array.min(axis=0).tolist()
            accessor["max"] = array.max(axis=0).tolist()
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, positions, normals, indices, material):
        primitive = {"attributes": {
            "POSITION": self._accessor(positions, _ARRAY_BUFFER, _FLOAT, "VEC3"),
            "NORMAL": self._accessor(normals, _ARRAY_BUFFER, _FLOAT, "VEC3")},
            "indices": self._accessor(indices, _ELEMENT_ARRAY_BUFFER, _UINT32, "SCALAR"),
            "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        self.doc["nodes"].append({"name": name, "mesh": len(self.doc["meshes"]) - 1})
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def point_light(self, name, position, intensity):
        self.doc.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
        lights = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        lights.append({"name": name, "type": "point", "color": [1.0, 1.0, 1.0], "intensity": intensity})
        self.doc["nodes"].append({"name": name, "translation": list(position),
                                  "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}})
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def write(self, path):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()
        self.doc["buffers"] = [{"byteLength": len(self.blob), "uri": uri}]
        with open(path, "w") as f:
            json.dump(self.doc, f)


def build(name):
    g = GltfBuilder()
    if name == "point_light_floor":
        g.mesh("Floor", *floor_quad(2.0, 0.0), g.material("White", (0.8, 0.8, 0.8), 0.0, 1.0))
        g.point_light("Point", (0.0, 1.0, 0.0), 683.0)
        return g
    if name.startswith("mirror"):
        material = g.material("Mirror", (1.0, 1.0, 1.0), 1.0, 0.0)
    else:
        material = g.material("White", (0.8, 0.8, 0.8), 0.0, 1.0)
    g.mesh("Sphere", *uv_sphere(), material)
    if name in ("sphere_on_floor", "mirror_on_mirror"):
        g.mesh("Floor", *floor_quad(3.0, -1.0), material)
    return g


def write_scene(name, folder):
    """Writes NAME.gltf into folder and returns its path."""
    if name not in SCENES + LIGHT_SCENES:
        raise ValueError(f"unknown sanity scene '{name}' (known: {', '.join(SCENES + LIGHT_SCENES)})")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, name + ".gltf")
    build(name).write(path)
    return path


if __name__ == "__main__":
    import sys
    if len(sys.argv) != 2:
        sys.exit("usage: sanity_scenes.py OUT_FOLDER")
    for scene in SCENES + LIGHT_SCENES:
        print(write_scene(scene, sys.argv[1]))
