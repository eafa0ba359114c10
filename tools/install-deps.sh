#!/usr/bin/env bash
# Installs the Debian 12 packages woven needs, only those missing. Safe to run repeatedly.
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libglm-dev nlohmann-json3-dev libcli11-dev libtbb-dev libstb-dev
  libembree-dev libtinygltf-dev libopenimageio-dev
  libglfw3-dev libimgui-dev libepoxy-dev libegl-dev libgl-dev libgles-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  libgtest-dev libbenchmark-dev xvfb xauth xdotool gnuplot-nox
  clang libclang-rt-14-dev  # the fuzz and asan presets (docs/FUZZING.md): libFuzzer, ASan, UBSan
  slurm-wlm munge
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm (for the glTF validator below) may come from Node's own packages, which conflict with Debian's.
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
# Khronos's glTF validator (through gltf-transform) checks woven export's files in the tests.
# It is not a Debian package; without it those tests are skipped, saying so, so a failed npm
# install (no network) is a warning, not a failed build.
if [ ! -x "$HOME/node_modules/.bin/gltf-transform" ]; then
  echo "installing: @gltf-transform/cli (npm, into ~/node_modules)" >&2
  npm install --prefix "$HOME" --no-audit --no-fund @gltf-transform/cli >&2 \
    || echo "warning: npm could not install @gltf-transform/cli; the glTF validator tests will be skipped" >&2
fi
