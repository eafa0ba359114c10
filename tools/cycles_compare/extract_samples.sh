#!/usr/bin/env bash
# Extract Khronos sample assets from a bare git copy of glTF-Sample-Assets (or
# glTF-Sample-Models, or a fork) into the layout compare.py reads: OUT/NAME/glTF[-Binary]/...
#
#   tools/cycles_compare/extract_samples.sh GIT_DIR OUT [NAME...]
#
# A copy may lack large blobs (a partial or size-limited clone): a glTF or glTF-Binary folder
# is extracted only when every file in it is present, and a model with no complete folder is
# reported and skipped. Without NAMEs, the assets compare.py uses by default (and a few more).
set -euo pipefail

if [ $# -lt 2 ]; then
    echo "usage: $0 GIT_DIR OUT [NAME...]" >&2
    exit 2
fi
git_dir=$1
out=$2
shift 2
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
    names=(Avocado DamagedHelmet WaterBottle MetalRoughSpheresNoTextures NormalTangentMirrorTest
           TextureTransformTest AlphaBlendModeTest VertexColorTest SheenChair GlamVelvetSofa
           ClearCoatTest TransmissionTest ToyCar CesiumMan SheenCloth Fox Suzanne SpecularTest
           EmissiveStrengthTest LightsPunctualLamp ClearcoatWicker IridescenceSuzanne BoxVertexColors)
fi

git() { command git --git-dir="$git_dir" "$@"; }
git rev-parse --verify -q HEAD >/dev/null || { echo "$git_dir: not a git directory with a HEAD" >&2; exit 1; }

# glTF-Sample-Assets keeps models under Models/, glTF-Sample-Models under 2.0/.
root=""
for candidate in Models 2.0; do
    if [ -n "$(git ls-tree HEAD "$candidate/")" ]; then root=$candidate; break; fi
done
[ -n "$root" ] || { echo "$git_dir: neither Models/ nor 2.0/ at HEAD" >&2; exit 1; }

# True when every blob under the folder is present in the object store.
complete() {
    local sha
    for sha in $(git ls-tree -r HEAD "$1/" | awk '{print $3}'); do
        git cat-file -e "$sha" 2>/dev/null || return 1
    done
    [ -n "$(git ls-tree HEAD "$1/")" ]
}

mkdir -p "$out"
status=0
for name in "${names[@]}"; do
    variants=()
    for variant in glTF-Binary glTF; do
        if complete "$root/$name/$variant"; then variants+=("$variant"); fi
    done
    if [ ${#variants[@]} -eq 0 ]; then
        echo "skipped $name: no complete glTF or glTF-Binary folder in this copy" >&2
        status=1
        continue
    fi
    # Each folder from its own tree: git archive reads (and complains about) every missing
    # blob under the tree it is given, even outside the paths asked for.
    for variant in "${variants[@]}"; do
        mkdir -p "$out/$name/$variant"
        git archive "HEAD:$root/$name/$variant" | tar -x -C "$out/$name/$variant"
    done
    for f in LICENSE.md README.md; do
        if git cat-file -e "HEAD:$root/$name/$f" 2>/dev/null; then git show "HEAD:$root/$name/$f" > "$out/$name/$f"; fi
    done
    echo "extracted $name: ${variants[*]}"
done
exit $status
