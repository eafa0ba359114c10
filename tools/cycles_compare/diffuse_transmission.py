"""KHR_materials_diffuse_transmission: woven against Blender Cycles, region by region (issue 25).

Generates a glTF file of two thin sheets (a leaf and a curtain) side by side, each a dielectric
with KHR_materials_diffuse_transmission and KHR_materials_specular's specularFactor 0 (so the
material is the extension's diffuse mix alone), lit from behind by a point light and a little from
the front by a weaker one, seen from the front. woven renders the file as it is; Cycles
(cycles_render.py --diffuse-transmission) imports it and replaces each material by the
extension's definition in its own nodes, Mix(Diffuse, Translucent) by the factor. The driver
prints, per region (each sheet in 2 x 2 quarters, a margin off the edges), the mean of each and
their ratio, and fails (exit 1) when any region differs by more than --tolerance (5 %).

Run with Debian's python3 (numpy and OpenImageIO, as compare.py):

    /usr/bin/python3 tools/cycles_compare/diffuse_transmission.py --woven build/app/woven --out /tmp/dt
"""

import argparse
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare  # noqa: E402  (after the path is set)
import sanity_scenes  # noqa: E402

# The sheets: name, x range, base colour, diffuseTransmissionFactor, diffuseTransmissionColorFactor.
SHEETS = (
    ("Leaf", (-1.05, -0.05), (0.25, 0.55, 0.10), 0.5, (0.8, 0.9, 0.2)),
    ("Curtain", (0.05, 1.05), (0.80, 0.75, 0.70), 0.8, (1.0, 0.7, 0.4)),
)
HALF_HEIGHT = 0.5
CAMERA = {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "up": [0.0, 1.0, 0.0], "yfov_degrees": 30.0}
BACK_LIGHT = ((0.0, 0.2, -1.2), 3.0 * 683.0)   # cd: 3 W/sr in both renderers
FRONT_LIGHT = ((1.5, 1.2, 2.5), 0.6 * 683.0)


def build_scene(path):
    g = sanity_scenes.GltfBuilder()
    for name, (x0, x1), base, factor, color in SHEETS:
        material = g.material(name, base, 0.0, 1.0)
        m = g.doc["materials"][material]
        m["doubleSided"] = True
        m["extensions"] = {"KHR_materials_specular": {"specularFactor": 0.0},
                           "KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": factor,
                                                                  "diffuseTransmissionColorFactor": list(color)}}
        positions = np.array([[x0, -HALF_HEIGHT, 0], [x1, -HALF_HEIGHT, 0], [x1, HALF_HEIGHT, 0], [x0, HALF_HEIGHT, 0]], np.float32)
        normals = np.tile(np.array([0.0, 0.0, 1.0], np.float32), (4, 1))
        g.mesh(name, positions, normals, np.array([0, 1, 2, 0, 2, 3], np.uint32), material)
    for extension in ("KHR_materials_specular", "KHR_materials_diffuse_transmission"):
        g.doc.setdefault("extensionsUsed", []).append(extension)
    g.point_light("Behind", *BACK_LIGHT)
    g.point_light("Front", *FRONT_LIGHT)
    # The camera at CAMERA's position looking down -z, as glTF cameras do.
    g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": math.radians(CAMERA["yfov_degrees"]), "znear": 0.01}}]
    g.doc["nodes"].append({"name": "Camera", "camera": 0, "translation": CAMERA["position"]})
    g.doc["scenes"][0]["nodes"].append(len(g.doc["nodes"]) - 1)
    g.write(path)


def regions(width, height):
    """Per region (sheet quarter) its name and pixel mask: pixel centres' rays hit z = 0 inside it."""
    tan_half = math.tan(0.5 * math.radians(CAMERA["yfov_degrees"]))
    aspect = width / height
    xs = ((np.arange(width) + 0.5) * 2.0 / width - 1.0) * tan_half * aspect
    ys = (1.0 - (np.arange(height) + 0.5) * 2.0 / height) * tan_half
    distance = CAMERA["position"][2]
    px, py = np.meshgrid(xs * distance, ys * distance)  # the ray through each pixel meets z = 0 there
    margin = 0.06
    out = []
    for name, (x0, x1), *_ in SHEETS:
        xm = 0.5 * (x0 + x1)
        for label, (a, b) in (("left", (x0, xm)), ("right", (xm, x1))):
            for vertical, (c, d) in (("top", (0.0, HALF_HEIGHT)), ("bottom", (-HALF_HEIGHT, 0.0))):
                mask = (px > a + margin) & (px < b - margin) & (py > c + margin) & (py < d - margin)
                out.append((f"{name} {vertical} {label}", mask))
    return out


def run(cmd, log):
    start = time.time()
    with open(log, "w") as f:
        proc = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT)
    if proc.returncode != 0:
        sys.exit(f"diffuse_transmission: {cmd[0]} failed (exit {proc.returncode}), log {log}")
    return time.time() - start


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--woven", default="build/app/woven")
    p.add_argument("--blender", default="blender")
    p.add_argument("--out", required=True, help="folder for the glTF, the renders and the logs")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=160)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--integrator", default="path", help="woven's: path or bdpt")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--tolerance", type=float, default=0.05)
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    gltf = os.path.join(args.out, "sheets.gltf")
    build_scene(gltf)

    woven_exr, cycles_exr = os.path.join(args.out, "woven.exr"), os.path.join(args.out, "cycles.exr")
    woven_seconds = run([args.woven, "render", gltf, "--spp", str(args.spp), "--integrator", args.integrator,
                         "--noise-threshold", "0", "--no-denoise", "--max-depth", "8", "--width", str(args.width), "--height",
                         str(args.height), "--threads", str(args.threads), "-o", woven_exr],
                        os.path.join(args.out, "woven.log"))
    cycles_seconds = run([args.blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                          compare.CYCLES_SCRIPT, "--", "--gltf", gltf, "--out", cycles_exr, "--camera",
                          json.dumps(compare.camera_to_blender(CAMERA)), "--width", str(args.width), "--height",
                          str(args.height), "--samples", str(args.spp), "--max-depth", "8", "--threads",
                          str(args.threads), "--world-color", "0", "0", "0", "--diffuse-transmission"],
                         os.path.join(args.out, "cycles.log"))
    cycles_rgb, _, woven = compare.load_pair(cycles_exr, woven_exr)

    print(f"woven ({args.integrator}) {woven_seconds:.1f} s, Cycles {cycles_seconds:.1f} s, "
          f"{args.width}x{args.height}, {args.spp} spp; mean linear RGB per region")
    print(f"| region | pixels | Cycles | woven | woven / Cycles (R, G, B) |")
    print(f"|---|---|---|---|---|")
    worst = 0.0
    for name, mask in regions(args.width, args.height):
        c, w = cycles_rgb[mask].mean(axis=0), woven[mask].mean(axis=0)
        ratio = w / np.maximum(c, 1e-12)
        worst = max(worst, float(np.max(np.abs(ratio - 1.0))))
        fmt = lambda v: " ".join(f"{x:.4f}" for x in v)
        print(f"| {name} | {int(mask.sum())} | {fmt(c)} | {fmt(w)} | {fmt(ratio)} |")
    print(f"largest difference {100.0 * worst:.2f} % (tolerance {100.0 * args.tolerance:.0f} %)")
    sys.exit(0 if worst <= args.tolerance else 1)


if __name__ == "__main__":
    main()
