#!/bin/sh
# Remakes denim_flash.png, the example shot's "photo" (docs/FIT.md, "Try it"): woven's own render of
# the library's denim (assets/fabrics/denim.json) in the rig of denim_flash.json, written as a
# phone writes a photo (sRGB, clamped, no denoiser). swatch.gltf is the capture rig's 4 cm swatch
# (core's flat_cloth and glTF writer, as tests/fit/write_capture_shot writes it).
# Run from the repository root after building: assets/fit/make_photo.sh [build/app/woven]
set -e
woven=${1:-build/app/woven}
"$woven" render assets/fit/denim_scene.json -o assets/fit/denim_flash.png --spp 64 --integrator path \
    --noise-threshold 0 --no-denoise --tone-map clamp --seed 7
