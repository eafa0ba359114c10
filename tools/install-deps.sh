#!/usr/bin/env bash
# Installs the Debian 12 packages woven needs, only those missing. Safe to run repeatedly.
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libglm-dev nlohmann-json3-dev libcli11-dev libtbb-dev libstb-dev
  libembree-dev libtinygltf-dev libopenimageio-dev
  libglfw3-dev libimgui-dev libepoxy-dev libegl-dev libgl-dev libgles-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
  libgtest-dev libbenchmark-dev xvfb xauth gnuplot-nox
  slurm-wlm munge
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -q
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
