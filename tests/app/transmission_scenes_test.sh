#!/usr/bin/env bash
# The backlit scenes in assets/ are what tools/transmission_scenes.py writes, byte for byte: the
# project makes them, and an edit of the tool that is not re-run (or of a file by hand) fails here.
# Usage: transmission_scenes_test.sh SOURCE_DIR
set -euo pipefail
src=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 "$src/tools/transmission_scenes.py" "$out"
for f in curtain_window.gltf lampshade.gltf coloured_shadow.gltf; do
  cmp "$out/$f" "$src/assets/$f" || { echo "assets/$f differs from what tools/transmission_scenes.py writes" >&2; exit 1; }
done
echo "assets/curtain_window.gltf, lampshade.gltf and coloured_shadow.gltf are the tool's"
