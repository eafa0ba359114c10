#!/usr/bin/python3
"""Compare woven with Blender Cycles on glTF assets under one uniform environment.

For every asset: Blender imports the glTF and reports its bounds, a camera is framed from
them, Cycles renders a reference EXR (cycles_render.py), woven renders the same view from a
scene file, and the two are compared over the pixels the object covers. See
docs/CYCLES_COMPARISON.md.

    /usr/bin/python3 tools/cycles_compare/compare.py --woven build/app/woven \
        --samples /work/samples --out /tmp/cycles_compare

Needs Debian's python3-numpy and python3-openimageio (EXR and PNG I/O) and blender.
"""

import argparse
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ inside the source tree
import sanity_scenes  # noqa: E402  (after the path is set)

try:
    import OpenImageIO as oiio
except ImportError:
    sys.exit("compare.py: OpenImageIO's Python module is missing: apt-get install python3-openimageio "
             "(and run this script with Debian's /usr/bin/python3)")

CYCLES_SCRIPT = os.path.join(HERE, "cycles_render.py")
BOUNDS_TAG = "CYCLES_BOUNDS "

# Khronos sample assets (glTF-Sample-Assets / glTF-Sample-Models layout: NAME/glTF-Binary/NAME.glb
# or NAME/glTF/NAME.gltf) and what each exercises.
DEFAULT_ASSETS = {
    "Avocado": "base colour, metallicRoughness and normal textures",
    "DamagedHelmet": "textures, normal map, emissive, occlusion",
    "WaterBottle": "metal, ORM texture, normal map, emissive",
    "MetalRoughSpheresNoTextures": "metallic x roughness sweep, no textures",
    "NormalTangentMirrorTest": "normal maps with mirrored UVs / tangents",
    "TextureTransformTest": "KHR_texture_transform",
    "AlphaBlendModeTest": "alphaMode OPAQUE / MASK / BLEND",
    "VertexColorTest": "COLOR_0 vertex colours",
    "SheenChair": "KHR_materials_sheen, textures",
    "GlamVelvetSofa": "sheen, specular",
    "ClearCoatTest": "KHR_materials_clearcoat",
    "TransmissionTest": "KHR_materials_transmission",
    "ToyCar": "transmission, clearcoat, sheen, texture transform",
    "CesiumMan": "skin (static pose), base colour texture",
}
QUICK_ASSETS = ["Avocado", "DamagedHelmet", "MetalRoughSpheresNoTextures", "VertexColorTest"]

COVERED_ALPHA = 0.99  # Cycles alpha above which a pixel is taken as covered by the object


class StepError(Exception):
    """One step of one asset failed; the message says which and why."""


# --- coordinates -------------------------------------------------------------------------------
# glTF is +Y up; Blender's importer makes it +Z up: blender (x, y, z) = gltf (x, -z, y).

def gltf_to_blender(v):
    return [v[0], -v[2], v[1]]


def blender_to_gltf(v):
    return [v[0], v[2], -v[1]]


def bounds_to_gltf(bounds):
    """An axis-aligned box in Blender coordinates -> the same box in glTF coordinates."""
    a, b = blender_to_gltf(bounds["min"]), blender_to_gltf(bounds["max"])
    return [min(x, y) for x, y in zip(a, b)], [max(x, y) for x, y in zip(a, b)]


def framing_camera(lo, hi, yfov_degrees, pitch_degrees, margin):
    """A camera in glTF coordinates that sees the whole object.

    As woven's own framing (core/scene/scene_camera.cpp): from the front (+Z, the side glTF
    models face), pitched down by pitch_degrees, aimed at the box centre, at the distance where
    the bounding sphere (radius = half the box diagonal) just fills the vertical field of view,
    times margin: distance = margin * radius / sin(yfov / 2).
    """
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    centre = 0.5 * (lo + hi)
    radius = max(0.5 * float(np.linalg.norm(hi - lo)), 1e-3)
    distance = margin * radius / math.sin(0.5 * math.radians(yfov_degrees))
    pitch = math.radians(pitch_degrees)
    forward = np.array([0.0, -math.sin(pitch), -math.cos(pitch)])
    return {"position": (centre - distance * forward).tolist(), "target": centre.tolist(),
            "up": [0.0, 1.0, 0.0], "yfov_degrees": yfov_degrees}


def camera_to_blender(camera):
    return {"position": gltf_to_blender(camera["position"]), "target": gltf_to_blender(camera["target"]),
            "up": gltf_to_blender(camera["up"]), "yfov_degrees": camera["yfov_degrees"]}


# --- running the renderers ---------------------------------------------------------------------

def run_logged(cmd, log_path, timeout, what):
    """Runs cmd, keeps stdout+stderr in log_path, raises StepError (with the log's tail) on failure."""
    start = time.time()
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        raise StepError(f"{what}: timed out after {timeout} s") from None
    except OSError as e:
        raise StepError(f"{what}: cannot run {cmd[0]}: {e}") from None
    with open(log_path, "w") as f:
        f.write(" ".join(cmd) + "\n\n" + proc.stdout)
    if proc.returncode != 0:
        # Progress bars end their lines with \r; keep only what reads as messages.
        lines = [line.strip() for line in proc.stdout.replace("\r", "\n").splitlines() if line.strip()]
        cause = next((line for line in reversed(lines) if "error" in line.lower()), lines[-1] if lines else "")
        tail = "\n".join(lines[-15:])
        raise StepError(f"{what} failed (exit {proc.returncode}): {cause}\nlog: {log_path}\n{tail}")
    return proc.stdout, time.time() - start


def blender_command(args, script_args):
    # --python-exit-code makes an uncaught Python error fail the process; Blender exits 0 otherwise.
    return [args.blender, "-b", "--factory-startup", "--python-exit-code", "1",
            "--python", CYCLES_SCRIPT, "--"] + script_args


def blender_bounds(args, gltf, folder):
    out, _ = run_logged(blender_command(args, ["--gltf", gltf, "--bounds-only"]),
                        os.path.join(folder, "bounds.log"), args.timeout, "Blender import")
    for line in out.splitlines():
        if line.startswith(BOUNDS_TAG):
            return json.loads(line[len(BOUNDS_TAG):])
    raise StepError(f"Blender import printed no bounds (log {os.path.join(folder, 'bounds.log')})")


def render_cycles(args, gltf, camera, folder):
    exr = os.path.join(folder, "cycles.exr")
    script_args = ["--gltf", gltf, "--out", exr, "--camera", json.dumps(camera_to_blender(camera)),
                   "--width", str(args.width), "--height", str(args.height),
                   "--samples", str(args.spp), "--seed", str(args.seed),
                   "--max-depth", str(args.max_depth), "--threads", str(args.threads),
                   "--world-color", *map(str, args.env_color)]
    if args.env_image:
        script_args += ["--world-image", args.env_image, "--world-rotation", str(args.env_rotation)]
    _, seconds = run_logged(blender_command(args, script_args), os.path.join(folder, "cycles.log"),
                            args.timeout, "Cycles render")
    return exr, seconds


def woven_scene(args, gltf, camera):
    environment = {"color": list(args.env_color)}
    if args.env_image:
        environment["image"] = os.path.abspath(args.env_image)
        environment["rotation"] = args.env_rotation
    return {"gltf": gltf, "camera": camera, "environment": environment,
            "render": {"width": args.width, "height": args.height, "spp": args.spp, "integrator": "path"}}


def render_woven(args, gltf, camera, folder):
    scene_path = os.path.join(folder, "woven_scene.json")
    with open(scene_path, "w") as f:
        json.dump(woven_scene(args, gltf, camera), f, indent=2)
    exr = os.path.join(folder, "woven.exr")
    cmd = [args.woven, "render", scene_path, "--spp", str(args.spp), "--integrator", "path",
           "--max-depth", str(args.max_depth), "--seed", str(args.seed), "--width", str(args.width),
           "--height", str(args.height), "--threads", str(args.threads), "-o", exr]
    log, seconds = run_logged(cmd, os.path.join(folder, "woven.log"), args.timeout, "woven render")
    return exr, seconds, woven_ignored_extensions(log)


def woven_ignored_extensions(log):
    """Extensions woven's loader warned it ignores ("ignores the optional extension X")."""
    marker = "ignores the optional extension "
    found = [line.split(marker, 1)[1].split()[0] for line in log.replace("\r", "\n").splitlines() if marker in line]
    return sorted(set(found))


# --- images ------------------------------------------------------------------------------------

def read_exr(path):
    """(height, width, channels) float32 array and the channel names, top row first."""
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        raise StepError(f"{path}: {buf.geterror()}")
    pixels = buf.get_pixels(oiio.FLOAT)
    if pixels is None or buf.has_error:
        raise StepError(f"{path}: cannot read pixels: {buf.geterror()}")
    names = list(buf.spec().channelnames)
    return np.asarray(pixels, np.float32).reshape(buf.spec().height, buf.spec().width, -1), names


def channels(image, names, wanted, path):
    missing = [c for c in wanted if c not in names]
    if missing:
        raise StepError(f"{path}: no channel(s) {missing} (has {names})")
    return np.stack([image[..., names.index(c)] for c in wanted], axis=-1)


def load_pair(cycles_exr, woven_exr):
    c_img, c_names = read_exr(cycles_exr)
    w_img, w_names = read_exr(woven_exr)
    if c_img.shape[:2] != w_img.shape[:2]:
        raise StepError(f"image sizes differ: Cycles {c_img.shape[1]}x{c_img.shape[0]}, "
                        f"woven {w_img.shape[1]}x{w_img.shape[0]}")
    rgba = channels(c_img, c_names, "RGBA", cycles_exr)
    return rgba[..., :3], rgba[..., 3], channels(w_img, w_names, "RGB", woven_exr)


def composite_over(rgb, alpha, background):
    """Cycles' premultiplied film over the uniform background woven sees behind the object."""
    return rgb + (1.0 - alpha)[..., None] * np.asarray(background, np.float32)


def woven_coverage(woven, background, uniform):
    """Pixels where woven shows something other than the (uniform) environment, or None.

    None with an image (the background varies) or a black environment (unlit surfaces are
    black too, so they would read as background).
    """
    bg = np.asarray(background, np.float32)
    if not uniform or not bg.max() > 0.0:
        return None
    return np.any(np.abs(woven - bg) > 1e-4 * float(bg.max()), axis=-1)


def compare_images(cycles_rgb, alpha, woven, args):
    """Ratios and errors over covered pixels; the Cycles image composited as woven sees it."""
    uniform = not args.env_image
    reference = composite_over(cycles_rgb, alpha, args.env_color) if uniform else cycles_rgb
    covered = alpha > COVERED_ALPHA
    n = int(covered.sum())
    if n == 0:
        raise StepError("the object covers no pixel in the Cycles image (camera or import problem)")
    ref, test = reference[covered].astype(np.float64), woven[covered].astype(np.float64)
    ref_mean, test_mean = ref.mean(axis=0), test.mean(axis=0)
    ratio = [float(t / r) if r > 0 else float("nan") for t, r in zip(test_mean, ref_mean)]
    rel_rmse = float(math.sqrt(((test - ref) ** 2).sum() / max((ref ** 2).sum(), 1e-30)))
    result = {"covered_pixels": n, "ratio_rgb": ratio, "cycles_mean_rgb": ref_mean.tolist(),
              "woven_mean_rgb": test_mean.tolist(), "rel_rmse": rel_rmse, "iou": None}
    woven_mask = woven_coverage(woven, args.env_color, uniform)
    if woven_mask is not None:
        # "Any coverage" on both sides: Cycles alpha > 0, woven differs from the background.
        cycles_mask = alpha > 0.0
        union = np.logical_or(cycles_mask, woven_mask).sum()
        result["iou"] = float(np.logical_and(cycles_mask, woven_mask).sum() / union) if union else None
    return result, reference


def to_srgb8(linear, exposure):
    v = np.clip(linear * (2.0 ** exposure), 0.0, 1.0)
    v = np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1.0 / 2.4) - 0.055)
    return (np.clip(v, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)


def ratio_map(reference, woven, covered):
    """log2(woven / Cycles) luminance, red = woven brighter, blue = darker, +-1 stop full scale."""
    weights = np.array([0.2126, 0.7152, 0.0722], np.float32)
    lr, lw = reference @ weights, woven @ weights
    stops = np.clip(np.log2(np.maximum(lw, 1e-6) / np.maximum(lr, 1e-6)), -1.0, 1.0)
    out = np.full(reference.shape, 0.5, np.float32)
    out[..., 0] = np.where(stops > 0, 1.0, 1.0 + stops)
    out[..., 1] = 1.0 - np.abs(stops)
    out[..., 2] = np.where(stops < 0, 1.0, 1.0 - stops)
    out[~covered] = 0.15
    return (out * 255.0 + 0.5).astype(np.uint8)


def write_png(path, pixels):
    spec = oiio.ImageSpec(pixels.shape[1], pixels.shape[0], pixels.shape[2], oiio.UINT8)
    out = oiio.ImageOutput.create(path)
    if out is None or not out.open(path, spec) or not out.write_image(np.ascontiguousarray(pixels)):
        raise StepError(f"{path}: cannot write PNG: {oiio.geterror()}")
    out.close()


def write_side_by_side(path, reference, woven, alpha, exposure):
    """Cycles | woven | log2 ratio, both renders tone-mapped the same way (exposure, clamp, sRGB)."""
    gap = np.full((reference.shape[0], 4, 3), 255, np.uint8)
    panels = [to_srgb8(reference, exposure), gap, to_srgb8(woven, exposure), gap,
              ratio_map(reference, woven, alpha > COVERED_ALPHA)]
    write_png(path, np.concatenate(panels, axis=1))


# --- glTF facts for the report -----------------------------------------------------------------

def read_gltf_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        length, kind = struct.unpack_from("<II", data, 12)
        if kind != 0x4E4F534A:
            raise StepError(f"{path}: the first .glb chunk is not JSON")
        return json.loads(data[20:20 + length])
    return json.loads(data)


def gltf_features(path):
    """Short list of what the asset uses: extensions, textures, alpha modes, skins, colours."""
    doc = read_gltf_json(path)
    features = list(doc.get("extensionsUsed", []))
    materials = doc.get("materials", [])
    alpha_modes = sorted({m.get("alphaMode", "OPAQUE") for m in materials} - {"OPAQUE"})
    features += [f"alpha {m}" for m in alpha_modes]
    slots = [("baseColor", lambda m: m.get("pbrMetallicRoughness", {}).get("baseColorTexture")),
             ("metalRough", lambda m: m.get("pbrMetallicRoughness", {}).get("metallicRoughnessTexture")),
             ("normal", lambda m: m.get("normalTexture")), ("occlusion", lambda m: m.get("occlusionTexture")),
             ("emissive", lambda m: m.get("emissiveTexture"))]
    textures = [name for name, get in slots if any(get(m) for m in materials)]
    if textures:
        features.append("tex: " + "/".join(textures))
    if doc.get("skins"):
        features.append("skin")
    if any("COLOR_0" in p.get("attributes", {}) for mesh in doc.get("meshes", []) for p in mesh["primitives"]):
        features.append("COLOR_0")
    if any(m.get("doubleSided") for m in materials):
        features.append("doubleSided")
    return features


# --- one asset ---------------------------------------------------------------------------------

def find_asset(samples, name):
    for candidate in (os.path.join(samples, name, "glTF-Binary", name + ".glb"),
                      os.path.join(samples, name, "glTF", name + ".gltf")):
        if os.path.isfile(candidate):
            return candidate
    raise StepError(f"{name}: neither {name}/glTF-Binary/{name}.glb nor {name}/glTF/{name}.gltf "
                    f"under {samples}")


def run_asset(args, name, gltf, note):
    folder = os.path.join(args.out, name)
    os.makedirs(folder, exist_ok=True)
    row = {"asset": name, "gltf": gltf, "note": note}
    try:
        row["features"] = gltf_features(gltf)
        lo, hi = bounds_to_gltf(blender_bounds(args, gltf, folder))
        camera = framing_camera(lo, hi, args.yfov, args.pitch, args.margin)
        row["bounds_gltf"], row["camera"] = [lo, hi], camera
        cycles_exr, row["cycles_seconds"] = render_cycles(args, gltf, camera, folder)
        woven_exr, row["woven_seconds"], row["woven_ignores"] = render_woven(args, gltf, camera, folder)
        cycles_rgb, alpha, woven = load_pair(cycles_exr, woven_exr)
        metrics, reference = compare_images(cycles_rgb, alpha, woven, args)
        row.update(metrics)
        png = os.path.join(folder, "side_by_side.png")
        write_side_by_side(png, reference, woven, alpha, args.exposure)
        row["png"] = os.path.relpath(png, args.out)
    except StepError as e:
        row["error"] = str(e)
    return row


# --- report ------------------------------------------------------------------------------------

def fmt(v, digits=3):
    return "n/a" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.{digits}f}"


def cell(text):
    return str(text).replace("|", "\\|")


def markdown_report(rows, args):
    lines = [
        "# woven vs Blender Cycles",
        "",
        f"{args.width}x{args.height}, {args.spp} spp, --max-depth {args.max_depth} "
        f"(Cycles bounces {args.max_depth - 1}), seed {args.seed}, environment "
        + (f"image {args.env_image} x {args.env_color}" if args.env_image else f"uniform {args.env_color}")
        + f", woven `{args.woven}`.",
        "",
        "Ratio = mean woven / mean Cycles per channel over pixels with Cycles alpha > "
        f"{COVERED_ALPHA}; rel RMSE = sqrt(sum (w - c)^2 / sum c^2) there; IoU of the "
        "coverage masks (Cycles alpha > 0, woven != background).",
        "",
        "| asset | ratio R | ratio G | ratio B | rel RMSE | IoU | pixels | Cycles s | woven s | uses | woven ignores | image |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        uses = cell(", ".join(r.get("features", [])) or r.get("note", ""))
        if "error" in r:
            first = cell(r["error"].splitlines()[0])
            lines.append(f"| {r['asset']} | FAILED: {first} | | | | | | | | {uses} | | |")
            continue
        ratio = r["ratio_rgb"]
        lines.append(f"| {r['asset']} | {fmt(ratio[0])} | {fmt(ratio[1])} | {fmt(ratio[2])} | "
                     f"{fmt(r['rel_rmse'])} | {fmt(r['iou'])} | {r['covered_pixels']} | "
                     f"{r['cycles_seconds']:.0f} | {r['woven_seconds']:.0f} | {uses} | "
                     f"{', '.join(r['woven_ignores'])} | [png]({r['png']}) |")
    failures = [r for r in rows if "error" in r]
    if failures:
        lines += ["", "## Failures", ""]
        for r in failures:
            lines += [f"### {r['asset']}", "", "```", r["error"], "```", ""]
    return "\n".join(lines) + "\n"


# --- command line ------------------------------------------------------------------------------

def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--woven", required=True, help="the woven executable")
    p.add_argument("--samples", help="folder of Khronos sample assets (NAME/glTF-Binary/NAME.glb ...)")
    p.add_argument("--out", required=True, help="output folder (report.md, results.json, one folder per asset)")
    p.add_argument("--assets", help="comma-separated asset names under --samples "
                   f"(default: all of {', '.join(DEFAULT_ASSETS)}; 'quick' = {', '.join(QUICK_ASSETS)})")
    p.add_argument("--gltf", action="append", default=[], help="an extra glTF file to compare (repeatable)")
    p.add_argument("--sanity", action="store_true",
                   help=f"also generate and compare the sanity scenes ({', '.join(sanity_scenes.SCENES)})")
    p.add_argument("--blender", default="blender")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=240)
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--max-depth", type=int, default=8, help="woven's --max-depth (Cycles gets one bounce less)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=int, default=2, help="threads for each renderer (they run one at a time)")
    p.add_argument("--env-color", type=float, nargs=3, default=[1.0, 1.0, 1.0], metavar=("R", "G", "B"),
                   help="uniform environment radiance, linear (default 1 1 1)")
    p.add_argument("--env-image", help="equirectangular .hdr/.exr environment (times --env-color)")
    p.add_argument("--env-rotation", type=float, default=0.0, help="degrees about +Y (glTF up)")
    p.add_argument("--yfov", type=float, default=39.6, help="vertical field of view, degrees")
    p.add_argument("--pitch", type=float, default=math.degrees(0.5),
                   help="camera looks down by this many degrees (default: woven's 0.5 rad)")
    p.add_argument("--margin", type=float, default=1.05, help="distance factor beyond the bounding sphere")
    p.add_argument("--exposure", type=float, default=0.0, help="PNG exposure in stops")
    p.add_argument("--timeout", type=int, default=3600, help="seconds allowed for each render")
    args = p.parse_args()
    if args.max_depth < 1:
        p.error("--max-depth must be at least 1")
    if not (args.assets or args.gltf or args.sanity) and not args.samples:
        p.error("give --samples (with or without --assets), --gltf or --sanity")
    return args


def check_tools(args):
    woven = shutil.which(args.woven) if os.sep not in args.woven else args.woven
    if not woven or not os.access(woven, os.X_OK):
        sys.exit(f"compare.py: woven executable not found: {args.woven}")
    args.woven = os.path.abspath(woven)
    if not shutil.which(args.blender):
        sys.exit(f"compare.py: Blender not found: {args.blender} (apt-get install blender)")
    if args.env_image and not os.path.isfile(args.env_image):
        sys.exit(f"compare.py: environment image not found: {args.env_image}")


def asset_list(args):
    """(name, glTF path or None, note, error) for everything to compare."""
    items = []
    if args.samples or args.assets:
        if not args.samples:
            sys.exit("compare.py: --assets needs --samples")
        if not os.path.isdir(args.samples):
            sys.exit(f"compare.py: samples folder not found: {args.samples}")
        names = (QUICK_ASSETS if args.assets == "quick" else
                 [n.strip() for n in args.assets.split(",") if n.strip()] if args.assets else list(DEFAULT_ASSETS))
        for name in names:
            try:
                items.append((name, os.path.abspath(find_asset(args.samples, name)), DEFAULT_ASSETS.get(name, ""), None))
            except StepError as e:
                items.append((name, None, DEFAULT_ASSETS.get(name, ""), str(e)))
    for path in args.gltf:
        name = os.path.splitext(os.path.basename(path))[0]
        error = None if os.path.isfile(path) else f"{path}: no such file"
        items.append((name, os.path.abspath(path), "", error))
    if args.sanity:
        folder = os.path.join(args.out, "sanity_gltf")
        for name in sanity_scenes.SCENES:
            items.append(("sanity_" + name, sanity_scenes.write_scene(name, folder), "generated", None))
    return items


def main():
    args = parse_args()
    check_tools(args)
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for name, gltf, note, error in asset_list(args):
        print(f"== {name}", flush=True)
        row = {"asset": name, "gltf": gltf, "note": note, "error": error} if error else run_asset(args, name, gltf, note)
        if "error" in row:
            print(f"   FAILED: {row['error']}", flush=True)
        else:
            print("   ratio " + " ".join(fmt(v) for v in row["ratio_rgb"]) + f"  rel RMSE {fmt(row['rel_rmse'])}"
                  f"  IoU {fmt(row['iou'])}  (Cycles {row['cycles_seconds']:.0f} s, woven {row['woven_seconds']:.0f} s)",
                  flush=True)
        rows.append(row)
        # Rewritten after every asset, so a long run can be read while it goes on.
        with open(os.path.join(args.out, "results.json"), "w") as f:
            json.dump({"settings": {k: v for k, v in vars(args).items()}, "assets": rows}, f, indent=2)
        with open(os.path.join(args.out, "report.md"), "w") as f:
            f.write(markdown_report(rows, args))
    print(f"report: {os.path.join(args.out, 'report.md')}")
    return 1 if any("error" in r for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
