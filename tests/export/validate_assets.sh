#!/usr/bin/env bash
# Every glTF file under assets/ passes Khronos's glTF-Validator (gltf-transform validate) with no
# error and no warning: the project's own files are what it asks of others'. Exit 77 (skipped,
# saying so) where the validator is not installed (tools/install-deps.sh --tests installs it).
# Usage: validate_assets.sh SOURCE_DIR GLTF_TRANSFORM
set -euo pipefail
src=$1
validator=${GLTF_TRANSFORM:-$2}
if [[ -z $validator || ! -x $validator ]]; then
  echo "Khronos's glTF validator is not installed: assets/ not validated (tools/install-deps.sh --tests)" >&2
  exit 77
fi
failed=0
while IFS= read -r -d '' file; do
  report=$(timeout 120 "$validator" validate "$file" --format csv 2>&1) || true
  # CSV code,message,severity,pointer (the message may hold commas): severity 0 error, 1 warning.
  issues=$(printf '%s\n' "$report" | awk -F, 'NF >= 4 && ($(NF-1) == "0" || $(NF-1) == "1")')
  if [[ -n $issues ]] || grep -q "Validation detected errors" <<<"$report"; then
    echo "${file#"$src"/}: Khronos's validator finds:" >&2
    printf '%s\n' "${issues:-$report}" >&2
    failed=1
  fi
done < <(find "$src/assets" \( -name '*.gltf' -o -name '*.glb' \) -print0 | sort -z)
[[ $failed == 0 ]] && echo "every glTF file under assets/ passes Khronos's validator"
exit $failed
