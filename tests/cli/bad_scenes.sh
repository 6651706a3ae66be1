#!/usr/bin/env bash
# The catalogue of broken scenes in tests/bad/scenes: each gives its exact
# first message and exit code and writes no image (expected.txt lists
# FILE, EXIT and the first line of stderr, tab-separated).
# Usage: bad_scenes.sh PATH/TO/glint
set -u
GLINT=$1
cd "$(dirname "$0")/../.." || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
while IFS=$'\t' read -r file code first; do
    "$GLINT" "$file" -q -o "$work/out.png" 2>"$work/err" >/dev/null
    status=$?
    actual=$(head -n 1 "$work/err")
    if [ "$status" -eq "$code" ] && [ "$actual" = "$first" ] && [ ! -e "$work/out.png" ] &&
       tail -n 1 "$work/err" | grep -q "^glint: $file: .*nothing rendered$"; then
        passed=$((passed + 1))
    else
        echo "FAIL: $file"
        echo "  expected exit $code: $first"
        echo "  got      exit $status: $actual"
        failed=$((failed + 1))
    fi
done < tests/bad/scenes/expected.txt
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
