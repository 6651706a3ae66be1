#!/usr/bin/env bash
# Standard output and input. `-o -` writes to stdout exactly the bytes -o
# FILE writes (PNG by default, PPM or OpenEXR with --format) and nothing
# else; it refuses a terminal, and a reader that goes away is exit 3.
# `glint -` reads the scene from stdin: the same image as from a file,
# relative paths from the current directory, messages naming <stdin>, an
# empty or too large stdin refused. A scene without `samples` renders 4.
# Usage: stdio.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"

# The same bytes on stdout as in the file, for every format (and OpenEXR's
# two pixel types), exit 0, and the summary on stderr names <stdout>.
small=(-w 40 -h 30 --threads 2)
same_bytes() { # EXT FLAGS...: FILE vs stdout
    local ext=$1
    shift
    "$GLINT" "${small[@]}" -q "$@" -o "file.$ext" &&
        "$GLINT" "${small[@]}" "$@" -o - --format "$ext" >"out.$ext" 2>summary.txt &&
        cmp -s "file.$ext" "out.$ext" && [ -s "out.$ext" ] &&
        grep -Eq '^glint: 40x30, 4 spp, 2 threads: .* -> <stdout>$' summary.txt
}
check "-o - --format png: the bytes of -o FILE" same_bytes png
check "-o - --format ppm: the bytes of -o FILE" same_bytes ppm
check "-o - --format exr: the bytes of -o FILE" same_bytes exr
check "-o - --format exr --exr-pixel float: the bytes of -o FILE" same_bytes exr --exr-pixel float
# PNG is the default; a matching --format with a file is allowed, and the
# default file name follows --format.
check "-o - is PNG by default" bash -c "'$GLINT' ${small[*]} -q -o - >default.out && cmp -s default.out file.png"
check "--format ppm -o x.PPM writes the file" bash -c "'$GLINT' ${small[*]} -q --format ppm -o x.PPM && cmp -s x.PPM file.ppm"
check "--format ppm alone writes glint.ppm" bash -c "'$GLINT' ${small[*]} -q --format=ppm && cmp -s glint.ppm file.ppm"
check "-o - --format png --bit-depth 16: the bytes of -o FILE" same_bytes png --bit-depth 16
check "-o - --format ppm --bit-depth 16: the bytes of -o FILE" same_bytes ppm --bit-depth 16
rm -f ./*.png ./*.ppm ./*.PPM ./*.exr default.out summary.txt

check "--help names --format and '-'" bash -c "'$GLINT' --help | grep -q -- '--format png|ppm|exr' && '$GLINT' --help | grep -q \"'-' reads it from standard input\""

# Image bytes on a terminal: refused before rendering, exit 2.
if command -v script >/dev/null; then
    tty_out=$(script -qec "'$GLINT' -o - --format exr" /dev/null | tr -d '\r'; exit "${PIPESTATUS[0]}")
    status=$?
    [ "$status" -eq 2 ] &&
        [ "$tty_out" = "glint: will not write an OpenEXR image to a terminal; redirect stdout or give -o FILE" ]
    verdict $? "-o - --format exr on a terminal: exit $status, $tty_out"
    tty_out=$(script -qec "'$GLINT' -o -" /dev/null | tr -d '\r')
    check "-o - on a terminal: $tty_out" \
        [ "$tty_out" = "glint: will not write a PNG image to a terminal; redirect stdout or give -o FILE" ]
    check "nothing written for the terminal" [ -z "$(ls)" ]
else
    echo "skipped: script (util-linux) is not installed, so no terminal is tried"
fi

# A reader that stops early: the write fails with EPIPE, exit 3. (The image,
# 360,017 bytes, is more than the pipe and head's read can hold.)
"$GLINT" -w 400 -h 300 --spp 1 -q -o - --format ppm 2>epipe.txt | head -c 1 >/dev/null
status=${PIPESTATUS[0]}
[ "$status" -eq 3 ] && [ "$(cat epipe.txt)" = "glint: cannot write '<stdout>': Broken pipe" ]
verdict $? "a closed pipe: exit $status, $(cat epipe.txt)"
rm -f epipe.txt

# A scene on stdin renders as from a file; its include, texture and output
# resolve from the current directory, not from anywhere else.
mkdir -p parts out
"$GLINT" -w 4 -h 4 --spp 1 -q -o parts/tex.png
printf 'textures:\n  inner: {type: image, file: tex.png}\n' >parts/looks.yaml
cat >scene.yaml <<'EOF'
include: parts/looks.yaml
settings: {width: 24, height: 16, output: out/stdin.ppm}
textures:
  outer: {type: image, file: parts/tex.png}
materials:
  a: {texture: inner}
  b: {texture: outer}
camera: {position: [0, 0, 5], look_at: [0, 0, 0]}
lights:
  - {type: point, position: [2, 3, 4]}
objects:
  - {type: sphere, center: [-1, 0, 0], radius: 1, material: a}
  - {type: sphere, center: [1, 0, 0], radius: 1, material: b}
EOF
"$GLINT" scene.yaml -q -o from-file.ppm
check "glint - < scene.yaml: the image of glint scene.yaml, at its output" \
    bash -c "'$GLINT' - -q <scene.yaml && cmp -s out/stdin.ppm from-file.ppm"
check "glint - -o -: a pipe through" bash -c "'$GLINT' - -q -o - --format ppm <scene.yaml | cmp -s - from-file.ppm"
# Elsewhere the same relative paths are not found: they are the directory's.
mkdir elsewhere
err=$(cd elsewhere && "$GLINT" - -q <../scene.yaml 2>&1)
check "relative paths from the current directory: $err" [ "$err" = "<stdin>:1:10: cannot include 'parts/looks.yaml': No such file or directory
<stdin>:4:30: cannot open texture 'parts/tex.png': No such file or directory
<stdin>:6:16: unknown texture 'inner'
glint: <stdin>: 3 problems; nothing rendered" ]

# Problems name <stdin> with the line and column.
err=$(printf 'settings: {width: 8}\nobjects:\n  - {type: sphere, radius: -1, material: {}}\n' | "$GLINT" - -q 2>&1)
status=$?
[ "$status" -eq 1 ] && [ "$err" = $'<stdin>:3:28: \'radius\' must be positive, got -1\nglint: <stdin>: 1 problem; nothing rendered' ]
verdict $? "a problem at <stdin>:3:28: exit $status, $err"
err=$("$GLINT" - -q </dev/null 2>&1)
status=$?
[ "$status" -eq 1 ] && [ "$err" = $'<stdin>: the file holds no scene\nglint: <stdin>: 1 problem; nothing rendered' ]
verdict $? "empty stdin: exit $status, $err"
# The 64 MiB limit of a file: exactly that many bytes are read (blanks: no
# scene), one more is refused.
err=$(head -c 67108864 /dev/zero | tr '\0' ' ' | "$GLINT" - -q 2>&1)
check "64 MiB on stdin is read: $err" [ "$(head -n 1 <<<"$err")" = "<stdin>: the file holds no scene" ]
err=$(head -c 67108865 /dev/zero | tr '\0' ' ' | "$GLINT" - -q 2>&1)
status=$?
[ "$status" -eq 1 ] && [ "$err" = $'scene \'<stdin>\' is too large: more than 67108864 bytes (the limit)\nglint: <stdin>: 1 problem; nothing rendered' ]
verdict $? "64 MiB + 1 on stdin: exit $status, $err"

# A scene file that does not say `samples` renders 4 a pixel (2 x 2).
summary=$(printf 'settings: {width: 10, height: 10}\n' | "$GLINT" - -o four.ppm 2>&1)
check "default samples: $summary" grep -Eq '^glint: 10x10, 4 spp, .* 400 samples, ' <<<"$summary"

finish
