#!/usr/bin/python3
"""woven's path tracer against Blender Cycles on the Lambert box of issue 23, in one run.

Writes the box (bench/render/lambert_box.py: five Lambertian walls, an emissive lamp below the
ceiling, the front open onto a black world), renders a reference of it with each renderer, then
renders it at each sample count and seed with each and prints, as a Markdown table, each render's
relMSE against its own renderer's reference, its render time and its efficiency
1 / (relMSE x render time), and woven's efficiency over Cycles'. Both render with one pixel-wide
box filter, no adaptive sampling, no denoising or clamping, the same bounces and threads.

    /usr/bin/python3 tools/cycles_compare/efficiency.py --woven build/app/woven --out /tmp/eff

Render time is what each reports for its render: woven's own figure (printed after the frame),
Cycles' the wall time of bpy.ops.render.render (scene sync, BVH, rendering, the EXR write) from
cycles_render.py. Whole process times (start-up, glTF import) are printed beside them. Each row's
renders are repeated (--repeats, the two renderers taking turns) and each renderer's least time
is kept: other work on a shared machine only ever adds time, and on the project's 2-core VMs one
render's time moves by up to 30 % from one run to the next. Both renderers are deterministic for a
seed, so the repeats' images are the same; the script checks that their relMSE agrees.

relMSE is woven converge's: the mean over pixels and channels of (x - r)^2 / (r^2 + 0.01). Each
reference's own noise adds about relMSE(reference) = relMSE(64 spp) x 64 / reference spp to every
figure; the table prints that estimate and does not take it off.

Needs Debian's python3-numpy, python3-openimageio and blender (3.4 or later).
"""

import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "bench", "render"))
sys.dont_write_bytecode = True  # no __pycache__ inside the source tree
import compare  # noqa: E402  (after the path is set)
import lambert_box  # noqa: E402

# The box's camera (bench/render/lambert_box.py) in Blender's coordinates.
CAMERA = '{"position": [0, -3.6, 0], "target": [0, 0, 0], "up": [0, 0, 1], "yfov_degrees": 35.5234}'
SECONDS_TAG = "CYCLES_RENDER_SECONDS "
WOVEN_TIME = re.compile(r"^integrator \w+, \d+ spp.*?, ([0-9.]+) (ms|s)[ ,]", re.M)


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--woven", required=True, help="the woven binary")
    p.add_argument("--blender", default="blender")
    p.add_argument("--out", required=True, help="folder for the box, the renders and the logs")
    p.add_argument("--spp", default="16,64,256", help="sample counts, comma separated")
    p.add_argument("--seeds", default="1,2", help="seeds, comma separated")
    p.add_argument("--reference-spp", type=int, default=8192)
    p.add_argument("--size", type=int, default=96, help="width and height in pixels")
    p.add_argument("--max-depth", type=int, default=12, help="woven's --max-depth (Cycles: one bounce less)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=3,
                   help="renders of each row per renderer, taking turns; the least time is kept (default 3)")
    p.add_argument("--woven-args", default="", help="more options for woven render, one string")
    p.add_argument("--reuse-references", action="store_true",
                   help="keep references already in --out (not one run: for experiments only)")
    p.add_argument("--timeout", type=float, default=3600.0)
    args = p.parse_args()
    if args.repeats < 1:
        p.error(f"--repeats {args.repeats}: at least 1")
    return args


def relative_mse(image, reference):
    return float(np.mean((image - reference) ** 2 / (reference ** 2 + 0.01)))


def seconds_of(match):
    value = float(match.group(1))
    return value / 1000.0 if match.group(2) == "ms" else value


def woven_render_options(woven):
    """Options every woven render of the box takes beyond the table's, where woven has them: no
    denoiser (Cycles' is off), as the raw estimates are what is compared, and no render passes
    (Cycles renders its Combined pass alone here)."""
    help_text = subprocess.run([woven, "render", "--help"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True).stdout
    return [option for option in ("--no-denoise", "--no-passes") if option in help_text]


def render_woven(args, gltf, spp, seed, exr):
    cmd = [args.woven, "render", gltf, "--spp", str(spp), "--integrator", "path", "--max-depth", str(args.max_depth),
           "--noise-threshold", "0", "--environment", "none", "--seed", str(seed), "--width", str(args.size),
           "--height", str(args.size), "--threads", str(args.threads), "-o", exr] + args.woven_options + \
        args.woven_args.split()
    log, process_seconds = compare.run_logged(cmd, exr + ".log", args.timeout, "woven render")
    match = WOVEN_TIME.search(log)
    if not match:
        raise compare.StepError(f"woven printed no render time (log {exr}.log)")
    image, names = compare.read_exr(exr)
    return compare.channels(image, names, "RGB", exr).astype(np.float64), seconds_of(match), process_seconds


def render_cycles(args, gltf, spp, seed, exr):
    script = ["--gltf", gltf, "--out", exr, "--camera", CAMERA, "--width", str(args.size), "--height", str(args.size),
              "--samples", str(spp), "--seed", str(seed), "--max-depth", str(args.max_depth),
              "--threads", str(args.threads), "--world-color", "0", "0", "0", "--lambert"]
    log, process_seconds = compare.run_logged(compare.blender_command(args, script), exr + ".log", args.timeout,
                                              "Cycles render")
    line = next((l for l in log.splitlines() if l.startswith(SECONDS_TAG)), None)
    if line is None:
        raise compare.StepError(f"cycles_render.py printed no render time (log {exr}.log)")
    image, names = compare.read_exr(exr)
    return compare.channels(image, names, "RGB", exr).astype(np.float64), float(line[len(SECONDS_TAG):]), \
        process_seconds


def main():
    args = parse_args()
    args.woven_options = woven_render_options(args.woven)
    os.makedirs(args.out, exist_ok=True)
    gltf = os.path.join(os.path.abspath(args.out), "lambert_box.gltf")
    lambert_box.main(gltf)
    renderers = {"woven": render_woven, "Cycles": render_cycles}
    references = {}
    for name, render in renderers.items():
        exr = os.path.join(args.out, f"{name}_reference.exr")
        if args.reuse_references and os.path.isfile(exr):
            image, names = compare.read_exr(exr)
            references[name] = compare.channels(image, names, "RGB", exr).astype(np.float64)
        else:
            print(f"{name}: reference, {args.reference_spp} spp", file=sys.stderr, flush=True)
            references[name] = render(args, gltf, args.reference_spp, 1000, exr)[0]
    means = {name: references[name].mean(axis=(0, 1)) for name in renderers}
    print(f"reference means (RGB): woven {np.round(means['woven'], 5).tolist()}, "
          f"Cycles {np.round(means['Cycles'], 5).tolist()}, woven/Cycles "
          f"{np.round(means['woven'] / means['Cycles'], 4).tolist()}")
    print()
    print("| spp | seed | woven relMSE | Cycles relMSE | woven s | Cycles s | woven process s | Cycles process s "
          "| efficiency woven / Cycles | relMSE Cycles / woven |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for spp in [int(s) for s in args.spp.split(",")]:
        for seed in [int(s) for s in args.seeds.split(",")]:
            row = {}
            for _ in range(args.repeats):
                for name, render in renderers.items():
                    exr = os.path.join(args.out, f"{name}_{spp}_{seed}.exr")
                    image, seconds, process_seconds = render(args, gltf, spp, seed, exr)
                    mse = relative_mse(image, references[name])
                    if name in row and mse != row[name][0]:
                        raise compare.StepError(f"{name} rendered {spp} spp, seed {seed} differently in two repeats "
                                                f"(relMSE {row[name][0]:.6g} and {mse:.6g})")
                    best = row.get(name, (mse, seconds, process_seconds))
                    row[name] = (mse, min(best[1], seconds), min(best[2], process_seconds))
            (w_mse, w_s, w_p), (c_mse, c_s, c_p) = row["woven"], row["Cycles"]
            ratio = (c_mse * c_s) / (w_mse * w_s)
            print(f"| {spp} | {seed} | {w_mse:.4g} | {c_mse:.4g} | {w_s:.3f} | {c_s:.3f} | {w_p:.2f} | {c_p:.2f} "
                  f"| {ratio:.2f} | {c_mse / w_mse:.2f} |", flush=True)


if __name__ == "__main__":
    try:
        main()
    except compare.StepError as e:
        sys.exit(f"efficiency.py: {e}")
