#!/usr/bin/env bash
# docs/results/fidelity/<subject>.png and scene_<scene>.png: the pictures of the tables of the
# preview against core (docs/results/fidelity/README.md). The harnesses (test_preview's
# Shipped/PreviewFidelity, Shipped/SceneFidelity and Shipped/DrapeFidelity cases) write each
# case's preview beside core's image; this puts a subject's near, mid and far side by side (on the
# flat cloth the cloth alone, not the black above it; drape_<subject>.png on the drape) and keeps
# each scene's pair as it is, in 64 colours (ImageMagick, tools/install-deps.sh
# --tests), about 10 KB a row. About four minutes on 2 cores.
# Usage: tools/preview_fidelity_pictures.sh [test_preview-binary] [out-folder]
set -euo pipefail
cd "$(dirname "$0")/.."
test_preview=${1:-build/tests/preview/test_preview}
out=${2:-docs/results/fidelity}
command -v convert >/dev/null || { echo "preview_fidelity_pictures.sh: ImageMagick's convert is missing (tools/install-deps.sh --tests installs it)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
WOVEN_FIDELITY_PICTURES=$tmp "$test_preview" --gtest_filter='Shipped/PreviewFidelity.*:Shipped/SceneFidelity.*:Shipped/DrapeFidelity.*' >"$tmp/log" ||
    { cat "$tmp/log" >&2; echo "preview_fidelity_pictures.sh: the harness failed (its output above)" >&2; exit 1; }
mkdir -p "$out"
for near in "$tmp"/*_near.png; do
    subject=$(basename "$near" _near.png)
    # The flat cloth's pictures show the cloth, not the black above it; the drape's are whole.
    crop=(-crop 160x45+0+15 +repage)
    [[ $subject == drape_* ]] && crop=()
    convert "$near" "$tmp/${subject}_mid.png" "$tmp/${subject}_far.png" "${crop[@]}" -bordercolor white -border 1x0 +append \
        -colors 64 "PNG8:$out/$subject.png"
done
for scene in "$tmp"/scene_*.png; do
    convert "$scene" -colors 64 "PNG8:$out/$(basename "$scene")"
done
grep '^fidelity' "$tmp/log"
ls "$out"
