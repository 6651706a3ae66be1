#!/usr/bin/env bash
# Every example scene in scenes/ passes --check and renders; the seed room
# file renders exactly the bytes of the built-in default; a scene's output
# setting is honoured and -o overrides it.
# Usage: scenes.sh PATH/TO/glint
set -u
GLINT=$1
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
check() { # check DESCRIPTION COMMAND...
    local what=$1
    shift
    if "$@" >"$work/out" 2>&1; then
        passed=$((passed + 1))
    else
        echo "FAIL: $what"
        sed 's/^/  /' "$work/out"
        failed=$((failed + 1))
    fi
}

count=0
for scene in "$here"/scenes/*.yaml; do
    name=$(basename "$scene" .yaml)
    count=$((count + 1))
    check "$name: --check" "$GLINT" --check "$scene"
    # One frame of an animated scene (a still ignores --frame).
    check "$name: renders" "$GLINT" "$scene" -w 64 -h 48 --spp 1 --frame 12 -q -o "$work/$name.png"
done
if [ "$count" -lt 6 ]; then
    echo "FAIL: expected the seed room and at least five example scenes, found $count"
    failed=$((failed + 1))
fi

# The model scenes need ../shared/data beside the repository; skipped without it.
if [ -d "$here/../shared/data" ]; then
    for scene in "$here"/scenes/models/*.yaml; do
        name=models-$(basename "$scene" .yaml)
        check "$name: --check" "$GLINT" --check "$scene"
        # One frame of an animated scene (a still ignores --frame).
    check "$name: renders" "$GLINT" "$scene" -w 64 -h 48 --spp 1 --frame 12 -q -o "$work/$name.png"
    done
else
    echo "skipped scenes/models/: ../shared/data is absent"
fi

# The seed room from its file and the built-in default: the same bytes.
check "seed room file renders" "$GLINT" "$here/scenes/seed-room.yaml" -q -o "$work/file.png"
check "built-in seed room renders" "$GLINT" -q -o "$work/builtin.png"
check "seed room file = built-in default, byte for byte" cmp "$work/file.png" "$work/builtin.png"

# A scene's output setting is used, relative to the current directory; -o wins.
cat >"$work/out.yaml" <<'YAML'
settings: {width: 8, height: 6, output: from-scene.ppm}
objects:
  - {type: sphere, center: [0, 0, -3], radius: 1, material: {color: [1, 1, 1]}}
YAML
check "output setting" bash -c "cd '$work' && '$GLINT' out.yaml -q && test -s from-scene.ppm"
check "-o overrides output" bash -c "cd '$work' && rm -f from-scene.ppm && '$GLINT' out.yaml -q -o flag.png && test -s flag.png && test ! -e from-scene.ppm"

# The broken file in docs/scene-format.md's Errors section gives exactly the
# problems the document shows.
awk -v dir="$work" '
    /^## Errors/ { in_errors = 1 }
    in_errors && /^```yaml/ && !yaml_done { in_yaml = 1; next }
    in_yaml && /^```/ { in_yaml = 0; yaml_done = 1; next }
    in_yaml { print > (dir "/bad.yaml") }
    yaml_done && /^\$ glint --check bad.yaml/ { in_out = 1; next }
    in_out && /^```/ { exit }
    in_out { print > (dir "/expected") }
' "$here/docs/scene-format.md"
check "docs error example matches the loader" bash -c "cd '$work' && ! '$GLINT' --check bad.yaml 2>actual && diff expected actual"

# Samples that shade to NaN: left out of their pixels, counted in a warning
# that --quiet does not hide, and the image is still written (exit 0).
nan_check() {
    local err
    err=$("$GLINT" "$here/tests/cli/nan-sphere.yaml" -q -o "$work/nan.png" 2>&1 >/dev/null) || return 1
    [ "$err" = "glint: warning: 896 samples came out NaN (not a number) and were left out of their pixels" ] &&
        [ -s "$work/nan.png" ] || { echo "got: $err"; return 1; }
}
check "NaN samples: warned about and left out" nan_check

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
