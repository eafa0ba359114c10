#!/usr/bin/env bash
# docs/RESULTS.md's "Light through the yarns" section (issue 25, docs/MODEL_TRANSMISSION.md): the
# backlit scenes of assets/ (a sheer curtain against a bright window, a satin lampshade lit from
# inside, the default drape lit from behind), each rendered with its yarns' transmission and with
# it set to 0 by --woven, at the scene file's size, samples and integrator, and woven's own render
# times. Prints the section's markdown; writes the PNGs into docs/results/. About 6 minutes on 2 cores.
# Usage: tools/transmission_pictures.sh [WOVEN]   (default build/app/woven)
set -euo pipefail
cd "$(dirname "$0")/.."
woven=${1:-build/app/woven}
out=docs/results
mkdir -p "$out"
python3 tools/transmission_scenes.py
log=$(mktemp)
trap 'rm -f "$log"' EXIT

# Renders assets/$1.json to $out/$2.png with the remaining options; prints woven's render time.
render() {
  local scene=$1 name=$2
  shift 2
  "$woven" render "assets/$scene.json" --seed 1 -o "$out/$name.png" "$@" >"$log" 2>&1
  # woven's summary line: "integrator path, 64 spp at most (... average, noise ...), 320x240, 14.6 s, ..."
  awk -F', ' '/^integrator/ { t = $5 } END { print t }' "$log"
}

echo "| scene | with transmission | without (\`transmission\` 0) |"
echo "|---|---|---|"
for entry in "curtain_window Curtain" "lampshade Shade" "default_scene_backlit Cloth"; do
  read -r scene material <<<"$entry"
  with=$(render "$scene" "${scene}_transmission")
  without=$(render "$scene" "${scene}_opaque" --woven "$material={\"transmission\": 0}")
  echo "| \`assets/$scene.json\` | ![$scene with transmission](results/${scene}_transmission.png) $with | ![$scene without](results/${scene}_opaque.png) $without |"
done
echo
echo '```'
echo "tools/transmission_pictures.sh $woven"
echo '```'
