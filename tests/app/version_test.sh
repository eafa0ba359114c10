#!/usr/bin/env bash
# version_test.sh WOVEN VERSION SOURCE_DIR: `woven --version` prints the project's version and the
# commit the source tree is at ("unknown" outside a git checkout), and exits 0.
set -euo pipefail
woven=$1 version=$2 source_dir=$3
commit=$(git -C "$source_dir" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
expected="woven $version (commit $commit)"
actual=$("$woven" --version)
if [[ $actual != "$expected" ]]; then
    echo "woven --version printed '$actual', expected '$expected'"
    exit 1
fi
echo "$actual"
