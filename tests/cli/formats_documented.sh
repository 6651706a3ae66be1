#!/usr/bin/env bash
# The documents name the image formats glint writes, no more and no fewer:
# the extensions `glint --help` lists (from the library's registry,
# src/image/image_formats.c) are those of the README's -o row, the scene
# format's `output` row, library.md's glint_image_write row and
# robustness.md's check before rendering.
# Usage: formats_documented.sh PATH/TO/glint
set -u
GLINT=$1
cd "$(dirname "$0")/../.." || exit 1
passed=0
failed=0

# The extensions on a format's line of the help: the words before its name.
registry=$("$GLINT" --help | sed -n '/^Image formats/,/^$/p' |
           awk '{ for (i = 1; i <= NF && $i ~ /^\./; i++) print $i }' | sort -u | tr '\n' ' ')
if [ -z "$registry" ]; then
    echo "FAIL: glint --help lists no image formats"
    exit 1
fi

# documented FILE WHAT TEXT: the backquoted extensions in TEXT are the registry's.
documented() {
    local named
    named=$(grep -o '`\.[A-Za-z0-9]*`' <<<"$3" | tr -d '`' | sort -u | tr '\n' ' ')
    if [ "$named" = "$registry" ]; then
        passed=$((passed + 1))
    else
        echo "FAIL: $1, $2, names $named; glint writes $registry"
        failed=$((failed + 1))
    fi
}

documented README.md "the -o row" "$(grep '^| `-o`, `--output FILE`' README.md)"
documented docs/scene-format.md "the output row" "$(grep '^| `output` |' docs/scene-format.md)"
documented docs/library.md "the glint_image_write row" "$(grep '^| `glint_image_write(&img, path, &err)`' docs/library.md)"
documented docs/robustness.md "the check before rendering" \
    "$(awk '/^- Before rendering, glint checks/ { on = 1 } on && /^$|^- / && !/Before rendering/ { on = 0 } on' docs/robustness.md)"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
