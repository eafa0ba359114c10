"""Writes the many-lamp room of issue 23's light sampling item as a self-contained glTF: a closed
room 8 m x 3 m x 8 m of Lambertian walls (base colour 0.6, specularFactor 0) whose ceiling holds
an 8 x 8 grid of small square emissive lamps (10 cm) of powers spread over a factor of 1000
(log-uniform, fixed seed), seen from a camera in one corner looking across it. Most of a point's
light comes from the few lamps near it, which a light choice by power alone does not know.

    python3 bench/render/lamp_room.py OUT.gltf
"""

import json
import random
import sys

sys.dont_write_bytecode = True
from lambert_box import quads_gltf  # noqa: E402  (the same parallelogram scene writer)


def main(out):
    # (name, corner, u, v, material): each face looks into the room [-4, 4] x [0, 3] x [-4, 4].
    parts = [
        ("floor", [-4, 0, 4], [8, 0, 0], [0, 0, -8], "wall"),
        ("ceiling", [-4, 3, -4], [8, 0, 0], [0, 0, 8], "wall"),
        ("back", [-4, 0, -4], [8, 0, 0], [0, 3, 0], "wall"),
        ("front", [4, 0, 4], [-8, 0, 0], [0, 3, 0], "wall"),
        ("left", [-4, 0, 4], [0, 0, -8], [0, 3, 0], "wall"),
        ("right", [4, 0, -4], [0, 0, 8], [0, 3, 0], "wall"),
    ]
    rng = random.Random(23)
    strengths = []
    for i in range(8):
        for j in range(8):
            x, z = -3.5 + i, -3.5 + j
            # Facing down: u x v = -y.
            parts.append((f"lamp{i}{j}", [x - 0.05, 2.98, z - 0.05], [0.1, 0, 0], [0, 0, 0.1], f"lamp{len(strengths)}"))
            strengths.append(10.0 ** rng.uniform(1.0, 4.0))
    materials = [{"name": "wall", "doubleSided": True,
                  "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0,
                                           "roughnessFactor": 1},
                  "extensions": {"KHR_materials_specular": {"specularFactor": 0}}}]
    for k, strength in enumerate(strengths):
        materials.append({"name": f"lamp{k}", "doubleSided": False,
                          "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0,
                                                   "roughnessFactor": 1},
                          "emissiveFactor": [1, 1, 1],
                          "extensions": {"KHR_materials_specular": {"specularFactor": 0},
                                         "KHR_materials_emissive_strength": {"emissiveStrength": strength}}})
    index = {m["name"]: i for i, m in enumerate(materials)}
    parts = [(name, corner, u, v, index[material]) for name, corner, u, v, material in parts]
    # In the corner (3.5, 1.6, 3.5), looking towards (-1, 1.0, -1): yaw 45 deg, a little down.
    camera = {"translation": [3.5, 1.6, 3.5], "rotation": [-0.0435, 0.3823, 0.0180, 0.9229]}
    gltf = quads_gltf(parts, materials, camera, 1.0, "woven bench/render/lamp_room.py")
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1])
