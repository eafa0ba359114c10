#!/usr/bin/env bash
# product_file_lines.sh SOURCE_DIR LIMIT: fails, naming them, when any C++ file of the product
# (core/ and app/) is over LIMIT lines. A file that long holds more than one concept; split it by
# concept rather than raise the limit.
set -euo pipefail
source_dir=$1 limit=$2
over=$(cd "$source_dir" && find core app \( -name '*.cpp' -o -name '*.h' -o -name '*.in' \) -print0 |
       xargs -0 wc -l | awk -v limit="$limit" '$2 != "total" && $1 > limit { print "  " $2 ": " $1 " lines" }')
if [[ -n $over ]]; then
    echo "product files over $limit lines (split each by concept):"
    echo "$over"
    exit 1
fi
echo "no product file over $limit lines"
