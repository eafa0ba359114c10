#!/usr/bin/env bash
# Installs the Debian 12 packages woven needs, only those missing. Safe to run repeatedly.
# docs/BUILDING.md lists what each package brings with it.
#   tools/install-deps.sh          what building woven and rendering need (README's first command)
#   tools/install-deps.sh --share  also Google's <model-viewer>, which woven share copies into its
#                                  pages: Debian's npm (about 370 packages) and the script from npm
#   tools/install-deps.sh --tests  also what the test suite needs (README's second command):
#                                  --share's, GoogleTest, Google Benchmark, Python 3, Xvfb and
#                                  xdotool (the window is tested through a real display), gnuplot
#                                  (converge's plots), clang and its sanitizer runtime (the fuzz and
#                                  asan presets), slurm-wlm and munge (a real one-node cluster),
#                                  Khronos's glTF validator (npm), Chromium and puppeteer-core
#                                  (npm), which open woven share's pages
#   tools/install-deps.sh --compare also what the comparisons with Blender Cycles need
#                                  (tools/cycles_compare, docs/CYCLES_COMPARISON.md; the tests that
#                                  open frames in Blender run where it is installed): Blender,
#                                  Python's numpy and OpenImageIO
# Options may be combined.
set -euo pipefail
share=false
tests=false
compare=false
for option in "$@"; do
  case "$option" in
    --share) share=true ;;
    --tests) tests=true share=true ;;
    --compare) compare=true ;;
    *) echo "install-deps.sh: unknown option '$option' (--share adds woven share's model-viewer, --tests what the test suite needs, --compare what the Cycles comparisons need)" >&2; exit 2 ;;
  esac
done
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libglm-dev nlohmann-json3-dev libcli11-dev libtbb-dev libstb-dev
  libembree-dev libtinygltf-dev libdraco-dev libmeshoptimizer-dev libxxhash-dev
  libpng-dev libjpeg62-turbo-dev libwebp-dev libopenexr-dev  # images: each format's own library (docs/BUILDING.md)
  libfftw3-dev libnlopt-cxx-dev  # woven fit's spectra and optimiser
  zlib1g-dev  # the U3MA archive of woven export (deflate, CRC-32)
  libglfw3-dev libimgui-dev libepoxy-dev libegl-dev libgl-dev libgles-dev libosmesa6-dev libgl1-mesa-dri libegl-mesa0
)
test_packages=(
  libgtest-dev libbenchmark-dev xvfb xauth xdotool gnuplot-nox
  python3  # the structure tests and the reference pages' check (tests/product_*.py, tools/cli_reference.py)
  clang libclang-rt-14-dev  # the fuzz and asan presets (docs/FUZZING.md): libFuzzer, ASan, UBSan
  slurm-wlm munge
  imagemagick  # tools/fabric_sheet.sh stitches docs/RESULTS.md's sheet of the fabric library
  chromium     # a real browser for woven share's page (tests/export/share_page_test.cpp)
)
compare_packages=(blender python3-numpy python3-openimageio)
if $tests; then packages+=("${test_packages[@]}"); fi
if $compare; then packages+=("${compare_packages[@]}"); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm (for model-viewer and the glTF validator below) may come from Node's own packages, which
# conflict with Debian's.
if $share; then command -v npm >/dev/null || missing+=(npm); fi
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
if $tests && [ ! -x "$HOME/node_modules/.bin/gltf-transform" ]; then
  echo "installing: @gltf-transform/cli (npm, into ~/node_modules)" >&2
  npm install --prefix "$HOME" --no-audit --no-fund @gltf-transform/cli >&2 \
    || echo "warning: npm could not install @gltf-transform/cli; the glTF validator tests will be skipped" >&2
fi
# Google's <model-viewer>, which woven share copies into its pages (docs/EXPORT.md). Not a Debian
# package; without it woven share says how to get it, so a failed install is a warning.
if $share && [ ! -f "$HOME/node_modules/@google/model-viewer/dist/model-viewer-umd.min.js" ]; then
  echo "installing: @google/model-viewer (npm, into ~/node_modules)" >&2
  npm install --prefix "$HOME" --no-audit --no-fund @google/model-viewer >&2 \
    || echo "warning: npm could not install @google/model-viewer; woven share will not work" >&2
fi
# puppeteer-core drives Debian's chromium in the share page's test (no browser download).
if $tests && [ ! -d "$HOME/node_modules/puppeteer-core" ]; then
  echo "installing: puppeteer-core (npm, into ~/node_modules)" >&2
  npm install --prefix "$HOME" --no-audit --no-fund puppeteer-core >&2 \
    || echo "warning: npm could not install puppeteer-core; the share page test will be skipped" >&2
fi
