#!/usr/bin/env bash
# Proof that a change of code structure changed no output bit: renders, frame files, denoised
# frames, a BDPT frame, the previewer's shadowed frames and a bake, made by two builds and
# compared byte for byte.
#   tools/bit_identity.sh make DIR [WOVEN]     writes the outputs of WOVEN (default build/app/woven) into DIR
#   tools/bit_identity.sh compare BEFORE AFTER cmp of every file of BEFORE against AFTER's; exit 1 on any difference
# `woven converge` renders for a time budget, so its numbers differ from run to run: of its table
# only the layout is compared (every number replaced by N). Each EXR's time of writing is set to
# one fixed time.
set -euo pipefail

usage() { sed -n '2,10p' "$0" >&2; exit 2; }

make_outputs() {
    local dir=$1 woven=${2:-build/app/woven}
    mkdir -p "$dir"
    local size=(--width 160 --height 120 --spp 8)
    "$woven" render assets/default_scene.json "${size[@]}" -o "$dir/render_denoised.exr"
    "$woven" render assets/default_scene.json "${size[@]}" --no-denoise -o "$dir/render_noisy.exr"
    "$woven" render assets/default_scene.json "${size[@]}" -o "$dir/render.png"
    "$woven" render assets/default_scene.json "${size[@]}" --integrator bdpt -o "$dir/render_bdpt.exr"
    "$woven" render assets/coloured_shadow.json "${size[@]}" --noise-threshold 0 -o "$dir/coloured_shadow.exr"
    "$woven" render assets/lampshade.json "${size[@]}" --filter -o "$dir/lampshade_filtered.exr"
    # The previewer's frames: shadow maps of opaque and transmitting casters.
    "$woven" preview assets/default_scene.json --headless --screenshot "$dir/preview.exr"
    "$woven" preview assets/coloured_shadow.json --headless --screenshot "$dir/preview_coloured_shadow.exr"
    mkdir -p "$dir/bake"
    "$woven" bake assets/default_scene.json --size 128 --mips -o "$dir/bake"
    "$woven" export assets/default_scene.json --size 64 -o "$dir/export.glb"
    "$woven" pattern --material '{"preset": "denim"}' --size 24,16 --png "$dir/pattern.png" > "$dir/pattern.txt"
    "$woven" converge assets/converge_open.json --budgets 0.05,0.1 --reference-time 0.4 --width 32 --height 24 \
        --out-dir "$dir/converge_run" > "$dir/converge_table.txt"
    # Numbers (and what depends on them: a time not reached, what auto picks, the most efficient) out, the layout kept.
    sed -E -i 's/[-+]?[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?/N/g; s/not reached \(bias\)|neither reaches it|\binf\b/N/g; s/auto \([a-z]+\)/auto (picked)/g; s/^most efficient: .*/most efficient: (timed)/' \
        "$dir/converge_table.txt"
    cut -d, -f1,7- "$dir/converge_run/converge_open_convergence.csv" | sed -E 's/,[^,]*$//' > "$dir/converge_variants.csv"
    rm -rf "$dir/converge_run"
    # OpenImageIO stamps each EXR with the time of writing (capDate): the same fixed time in all.
    find "$dir" -name '*.exr' -exec perl -0777 -pi -e \
        's/(capDate\0string\0.{4})\d{4}:\d\d:\d\d \d\d:\d\d:\d\d/${1}2000:01:01 00:00:00/s' {} +
}

compare_outputs() {
    local before=$1 after=$2 status=0 count=0
    while IFS= read -r -d '' file; do
        local rel=${file#"$before"/}
        count=$((count + 1))
        if [[ ! -f "$after/$rel" ]]; then
            echo "missing: $rel"; status=1
        elif ! cmp -s "$file" "$after/$rel"; then
            echo "differs: $rel"; status=1
        fi
    done < <(find "$before" -type f -print0 | sort -z)
    [[ $count -gt 0 ]] || { echo "no files in $before"; exit 1; }
    [[ $status -eq 0 ]] && echo "identical: all $count files"
    return $status
}

case ${1:-} in
    make) [[ $# -ge 2 ]] || usage; make_outputs "$2" "${3:-}" ;;
    compare) [[ $# -eq 3 ]] || usage; compare_outputs "$2" "$3" ;;
    *) usage ;;
esac
