#!/usr/bin/env bash
# Command-line errors that need files around them: a missing scene, an output
# path that cannot be written, missing and unreadable textures, an existing
# file left alone; then good runs (PNG, PPM, OpenEXR), --help and the
# progress line. Each error gives its message on stderr, its exit code, and
# leaves no file behind. The errors of flags alone are in the catalogue,
# tests/bad/flags/expected.txt.
# Usage: errors.sh PATH/TO/glint
set -u
GLINT=$1
work=$(mktemp -d)
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
cd "$work"
passed=0
failed=0

# expect CODE MESSAGE -- ARGS...: runs glint ARGS, checks exit code and stderr.
expect() {
    local code=$1 message=$2
    shift 3
    local out err status
    err=$("$GLINT" "$@" 2>&1 >/dev/null)
    status=$?
    if [ "$status" -ne "$code" ] || [ "$err" != "$message" ]; then
        echo "FAIL: glint $*"
        echo "  expected exit $code: $message"
        echo "  got      exit $status: $err"
        failed=$((failed + 1))
    else
        passed=$((passed + 1))
    fi
    if [ -n "$(ls -A "$work" | grep -v '^ro$' | grep -v '^old.png$' | grep -v '^not-an-image.jpg$' | grep -v '^huge.obj$' | grep -v '^huge.png$')" ]; then
        echo "FAIL: glint $* left files: $(ls -A "$work")"
        failed=$((failed + 1))
    fi
}

small=(-w 8 -h 8 --spp 1 --quiet)
expect 1 $'cannot read scene \'missing.yaml\': No such file or directory\nglint: missing.yaml: 1 problem; nothing rendered' -- missing.yaml
expect 3 "glint: cannot write 'missing/dir/a.png': No such file or directory" -- "${small[@]}" -o missing/dir/a.png
expect 3 "glint: cannot write 'missing/dir/a.exr': No such file or directory" -- "${small[@]}" -o missing/dir/a.exr
mkdir ro && chmod a-w ro
if [ "$(id -u)" -ne 0 ]; then
    expect 3 "glint: cannot write 'ro/a.png': Permission denied" -- "${small[@]}" -o ro/a.png
    expect 3 "glint: cannot write 'ro/a.exr': Permission denied" -- "${small[@]}" -o ro/a.exr
fi
expect 1 "glint: cannot open texture 'nope.jpg': No such file or directory" -- "${small[@]}" --texture moon=nope.jpg -o a.png
echo "this is not an image" > not-an-image.jpg
expect 1 "glint: texture 'not-an-image.jpg' is not a PNG, JPEG or OpenEXR file" -- "${small[@]}" --texture moon=not-an-image.jpg -o a.png
expect 1 "glint: no image texture named 'sun'" -- "${small[@]}" --texture sun=not-an-image.jpg -o a.png

# A model file larger than half the machine's memory is refused before it
# is read (a sparse file: no disk space is used).
mem=$(($(awk '/^MemTotal:/ {print $2}' /proc/meminfo) * 1024))
if truncate -s "$mem" huge.obj 2>/dev/null; then
    expect 1 "glint: huge.obj: too large to import: $mem bytes, more than half of this machine's memory ($mem bytes)" -- "${small[@]}" huge.obj -o a.png
fi
rm -f huge.obj
# So is a texture file larger than 2 GiB.
if truncate -s 3G huge.png 2>/dev/null; then
    expect 1 "glint: texture 'huge.png' is too large: 3221225472 bytes (limit 2147483648)" -- "${small[@]}" --texture moon=huge.png -o a.png
fi
rm -f huge.png

# A failed run never touches an existing file.
printf 'precious' > old.png
expect 1 "glint: cannot open texture 'nope.jpg': No such file or directory" -- "${small[@]}" --texture moon=nope.jpg -o old.png
if [ "$(cat old.png)" != "precious" ]; then echo "FAIL: old.png was changed"; failed=$((failed + 1)); fi
rm -f old.png not-an-image.jpg

# --help and --version succeed and say what they should.
if "$GLINT" --help | grep -q -- "--spp N" && "$GLINT" --version | grep -Eq '^glint [0-9]+\.[0-9]+\.[0-9]+$'; then
    passed=$((passed + 1))
else
    echo "FAIL: --help or --version"; failed=$((failed + 1))
fi

# A good run writes exactly the named file, PNG or PPM, and a summary line.
summary=$("$GLINT" -w 16 -h 12 --spp 1 --threads 2 -o ok.ppm 2>&1 >/dev/null)
if [ "$(head -c 2 ok.ppm)" = "P6" ] && [ "$(head -2 ok.ppm | tail -1)" = "16 12" ] &&
   [[ "$summary" =~ ^glint:\ 16x12,\ 1\ spp,\ 2\ threads:\ .*\ s,\ 192\ samples,\ [0-9]+\ rays,\ .*Mrays/s\ -\>\ ok.ppm$ ]]; then
    passed=$((passed + 1))
else
    echo "FAIL: good PPM run: $summary"; failed=$((failed + 1))
fi
"$GLINT" -w 16 -h 12 --spp 1 --quiet -o ok.png 2>quiet.err
if [ "$(head -c 8 ok.png | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] && [ ! -s quiet.err ]; then
    passed=$((passed + 1))
else
    echo "FAIL: good PNG run"; failed=$((failed + 1))
fi

# An OpenEXR render, named by -o or by the scene's output setting, in half
# floats or, with --exr-pixel float, in 32-bit ones: OpenEXR's exrheader
# reads R, G and B of that type, the size and ZIP compression.
exr_header_ok() { # FILE TYPE
    local header
    header=$(exrheader "$1" 2>&1) &&
    grep -q "dataWindow (type box2i): (0 0) - (31 23)" <<<"$header" &&
    grep -q "compression (type compression): zip" <<<"$header" &&
    [ "$(grep -c "^ *[RGB], $2, sampling 1 1$" <<<"$header")" -eq 3 ]
}
printf 'settings: {width: 32, height: 24, samples: 1, output: scene.EXR}\n' > exr.yaml
"$GLINT" -w 32 -h 24 --spp 1 --quiet -o x.exr && "$GLINT" -w 32 -h 24 --spp 1 --quiet --exr-pixel float -o f.exr &&
    "$GLINT" exr.yaml --quiet
if [ "$(head -c 4 x.exr | od -An -tx1 | tr -d ' \n')" != "762f3101" ] || [ ! -s f.exr ] || [ ! -s scene.EXR ]; then
    echo "FAIL: OpenEXR runs"; failed=$((failed + 1))
elif ! command -v exrheader >/dev/null; then
    echo "skipped: exrheader is not installed (Debian: openexr), so the OpenEXR headers are not read"
elif exr_header_ok x.exr "16-bit floating-point" && exr_header_ok f.exr "32-bit floating-point" &&
     exr_header_ok scene.EXR "16-bit floating-point"; then
    passed=$((passed + 1))
else
    echo "FAIL: exrheader does not read the OpenEXR files as written:"; exrheader x.exr f.exr scene.EXR
    failed=$((failed + 1))
fi
# --exr-pixel with a scene whose output is not OpenEXR is refused before rendering.
printf 'settings: {output: scene.png}\n' > png.yaml
err=$("$GLINT" png.yaml --exr-pixel float 2>&1 >/dev/null)
if [ $? -eq 2 ] && [ "$err" = "glint: --exr-pixel is for .exr output, not 'scene.png'" ] && [ ! -e scene.png ]; then
    passed=$((passed + 1))
else
    echo "FAIL: --exr-pixel with a scene's PNG output: $err"; failed=$((failed + 1))
fi

# --bit-depth 16: a PPM of maxval 65535 and 2 bytes a channel, a PNG whose
# IHDR says 16 bits. Each 16-bit code is within half an 8-bit step of the
# 8-bit image's byte, and some are between 8-bit steps (finer, not scaled).
"$GLINT" -w 32 -h 24 --spp 1 --quiet -o d8.ppm && "$GLINT" -w 32 -h 24 --spp 1 --quiet --bit-depth 16 -o d16.ppm &&
    "$GLINT" -w 32 -h 24 --spp 1 --quiet --bit-depth=16 -o d16.png
if [ "$(head -c 15 d16.ppm | tr '\n' ' ')" = "P6 32 24 65535 " ] && [ "$(stat -c %s d16.ppm)" -eq $((15 + 32 * 24 * 6)) ] &&
   [ "$(od -An -tu1 -j 24 -N 1 d16.png | tr -d ' ')" = 16 ] &&
   paste <(tail -c $((32 * 24 * 3)) d8.ppm | od -An -v -tu1 -w1) \
         <(tail -c $((32 * 24 * 6)) d16.ppm | od -An -v -tu2 --endian=big -w2) |
       awk '{ d = $2 * 255 / 65535 - $1; if (d > 0.501 || d < -0.501) bad++; if ($2 % 257) finer++ }
            END { exit !(NR == 32 * 24 * 3 && bad == 0 && finer > 0) }'; then
    passed=$((passed + 1))
else
    echo "FAIL: --bit-depth 16 output"; failed=$((failed + 1))
fi

# GNU habits: -h alone is the help, --name=value is --name value (the same
# bytes), and --threads 0 is one thread per core (the same bytes again).
help=$("$GLINT" -h 2>/dev/null)
if [ $? -eq 0 ] && [[ "$help" == usage:* ]] && grep -q -- "--width=320" <<<"$help"; then
    passed=$((passed + 1))
else
    echo "FAIL: glint -h alone: $help"; failed=$((failed + 1))
fi
"$GLINT" -w 24 -h 16 --spp 4 --quiet -o spaced.ppm &&
    "$GLINT" --width=24 --height=16 --spp=4 --quiet --output=equals.ppm &&
    "$GLINT" -w 24 -h 16 --spp 4 --threads 0 --quiet -o cores.ppm
if [ $? -eq 0 ] && cmp -s spaced.ppm equals.ppm && cmp -s spaced.ppm cores.ppm; then
    passed=$((passed + 1))
else
    echo "FAIL: --name=value or --threads 0 rendered differently"; failed=$((failed + 1))
fi
rm -f spaced.ppm equals.ppm cores.ppm

# On a terminal, a progress line (percent, elapsed, remaining) comes before
# the summary; off a terminal there is none.
if command -v script >/dev/null; then
    tty_out=$(script -qec "'$GLINT' -w 200 -h 200 --spp 16 --threads 1 -o tty.png" /dev/null | tr '\r' '\n')
    if grep -Eq '^ *[0-9]+%  [0-9.]+ s elapsed, [0-9.]+ s left' <<<"$tty_out" && grep -q 'glint: 200x200, 16 spp, 1 thread:' <<<"$tty_out" &&
       ! grep -q 'elapsed' <<<"$summary"; then
        passed=$((passed + 1))
    else
        echo "FAIL: progress line on a terminal: $tty_out"; failed=$((failed + 1))
    fi
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
