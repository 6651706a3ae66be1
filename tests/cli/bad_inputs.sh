#!/usr/bin/env bash
# The catalogue of broken inputs in tests/bad/: each gives its exact first
# line on stderr and its exit code, and writes no image.
#   scenes/    scene files, rendered (glint FILE); the last line must say
#              the scene was not rendered
#   meshes/    model files, rendered as models (glint FILE)
#   textures/  images given as the seed room's texture (--texture moon=FILE)
#   flags/     command lines, run in an empty directory
# Each directory's expected.txt lists, tab-separated, the file (for flags:
# the arguments, split at spaces), the exit code and the first line.
# Usage: bad_inputs.sh PATH/TO/glint
set -u
GLINT=$1
cd "$(dirname "$0")/../.." || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

# check WHAT CODE FIRST STATUS [LAST]: compares one run's exit status and the
# first line of $work/err with the catalogue's, checks that no image was
# written and, when LAST is given, that the last line matches it (grep).
check() {
    local what=$1 code=$2 first=$3 status=$4 last=${5:-} actual
    actual=$(head -n 1 "$work/err")
    if [ "$status" -eq "$code" ] && [ "$actual" = "$first" ] && [ -z "$(ls -A "$work/out")" ] &&
       { [ -z "$last" ] || tail -n 1 "$work/err" | grep -q "$last"; }; then
        passed=$((passed + 1))
        return
    fi
    echo "FAIL: $what"
    echo "  expected exit $code: $first"
    echo "  got      exit $status: $actual"
    [ -z "$last" ] || echo "  last line: $(tail -n 1 "$work/err")"
    [ -z "$(ls -A "$work/out")" ] || echo "  and it wrote: $(ls -A "$work/out")"
    failed=$((failed + 1))
    rm -rf "${work:?}/out"/*
}

mkdir "$work/out"
small=(-w 8 -h 8 --spp 1 -q)
while IFS=$'\t' read -r file code first; do
    "$GLINT" "$file" -q -o "$work/out/out.png" 2>"$work/err" >/dev/null
    check "$file" "$code" "$first" $? "^glint: $file: .*nothing rendered$"
done <tests/bad/scenes/expected.txt
while IFS=$'\t' read -r file code first; do
    "$GLINT" "$file" "${small[@]}" -o "$work/out/out.png" 2>"$work/err" >/dev/null
    check "$file" "$code" "$first" $?
done <tests/bad/meshes/expected.txt
while IFS=$'\t' read -r file code first; do
    "$GLINT" --texture "moon=$file" "${small[@]}" -o "$work/out/out.png" 2>"$work/err" >/dev/null
    check "$file" "$code" "$first" $?
done <tests/bad/textures/expected.txt
while IFS=$'\t' read -r args code first; do
    read -ra argv <<<"$args"
    (cd "$work/out" && "$GLINT" "${argv[@]}") 2>"$work/err" >/dev/null
    check "glint $args" "$code" "$first" $?
done <tests/bad/flags/expected.txt

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
