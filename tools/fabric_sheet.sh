#!/usr/bin/env bash
# docs/results/fabric_sheet.png: every fabric of the library (`woven fabrics`) on a flat square
# swatch of 4 cm, rendered by `woven render` through {"preset": NAME}, so each shows its real
# thread count (100 pixels per cm), labelled with its name and thread counts and stitched by
# ImageMagick's montage (tools/install-deps.sh --tests). About 3 minutes on 2 cores.
# Usage: tools/fabric_sheet.sh [woven-binary] [out.png]
set -euo pipefail
cd "$(dirname "$0")/.."
woven=${1:-build/app/woven}
out=${2:-docs/results/fabric_sheet.png}
command -v montage >/dev/null || { echo "fabric_sheet.sh: ImageMagick's montage is missing (tools/install-deps.sh --tests installs it)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
side=0.04  # metres
pixels=400

# The swatch: a square of $side in the xy plane facing +z, its UVs spanning it once, so that a
# UV unit is $side and ends_per_cm x 100 x $side ends cross it.
python3 - "$tmp/swatch.gltf" "$side" <<'EOF'
import base64, json, struct, sys
path, s = sys.argv[1], float(sys.argv[2])
positions = [(0, 0, 0), (s, 0, 0), (s, s, 0), (0, s, 0)]
uvs = [(0, 0), (1, 0), (1, 1), (0, 1)]
normals = [(0, 0, 1)] * 4
data = b''.join(struct.pack('<3f', *p) for p in positions) + b''.join(struct.pack('<3f', *n) for n in normals) \
    + b''.join(struct.pack('<2f', *t) for t in uvs) + struct.pack('<6H', 0, 1, 2, 0, 2, 3)
views = [(0, 48), (48, 48), (96, 32), (128, 12)]
gltf = {
    'asset': {'version': '2.0'},
    'buffers': [{'byteLength': len(data), 'uri': 'data:application/octet-stream;base64,' + base64.b64encode(data).decode()}],
    'bufferViews': [{'buffer': 0, 'byteOffset': o, 'byteLength': n} for o, n in views],
    'accessors': [
        {'bufferView': 0, 'componentType': 5126, 'count': 4, 'type': 'VEC3', 'min': [0, 0, 0], 'max': [s, s, 0]},
        {'bufferView': 1, 'componentType': 5126, 'count': 4, 'type': 'VEC3'},
        {'bufferView': 2, 'componentType': 5126, 'count': 4, 'type': 'VEC2'},
        {'bufferView': 3, 'componentType': 5123, 'count': 6, 'type': 'SCALAR'},
    ],
    'materials': [{'name': 'Swatch'}],
    'meshes': [{'name': 'Swatch', 'primitives': [{'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2},
                                                  'indices': 3, 'material': 0}]}],
    'nodes': [{'name': 'Swatch', 'mesh': 0}],
    'scenes': [{'nodes': [0]}],
    'scene': 0,
}
json.dump(gltf, open(path, 'w'))
EOF

# Seen square on from 22.9 cm through a 10 degree lens, which spans the 4 cm exactly; a grey
# sky and a light from the upper left that catches the yarns' sheen.
labels=()
while IFS=$'\t' read -r name threads; do
  cat > "$tmp/$name.json" <<EOF
{
  "gltf": "swatch.gltf",
  "materials": {"Swatch": {"preset": "$name"}},
  "environment": {"color": 0.45},
  "lights": [{"type": "directional", "direction": [0.45, -0.55, -1], "intensity": 2.5}],
  "camera": {"position": [0.02, 0.02, 0.228601], "target": [0.02, 0.02, 0], "yfov_degrees": 10},
  "render": {"width": $pixels, "height": $pixels, "spp": 64, "integrator": "path"}
}
EOF
  echo "$name ($threads)" >&2
  "$woven" render "$tmp/$name.json" --seed 1 -o "$tmp/$name.png" >/dev/null 2>&1
  labels+=(-label "$name, $threads" "$tmp/$name.png")
done < <("$woven" fabrics --json | python3 -c '
import json, sys
for f in json.load(sys.stdin):
    print("%s\t%g x %g per cm" % (f["name"], f["ends_per_cm"], f["picks_per_cm"]))')
mkdir -p "$(dirname "$out")"
# 256 colours, Floyd-Steinberg dithered: a fifth of the full colour sheet's 6 MB, no difference to see.
montage "${labels[@]}" -tile 5x -geometry "${pixels}x${pixels}+6+6" -font DejaVu-Sans -pointsize 15 -background white \
  -dither FloydSteinberg -colors 256 "PNG8:$out"
echo "wrote $out" >&2
