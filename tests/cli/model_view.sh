#!/usr/bin/env bash
# glint MODEL frames the model for the image size the flags give, measured
# in pixels: a red box seen from the top shows only its top face, which is
# the box's projected bounding box; it must be centred and span 85% of the
# image's width or height, whichever limits (the pixel centres inside that
# share, counted). Every --view renders. (The framing of every view in
# numbers, and rooms seen through their openings, are in
# tests/unit/test_model_view.c; the refused --view values in the flags
# catalogue, tests/bad/flags/expected.txt.)
# Usage: model_view.sh PATH/TO/glint
set -u
GLINT=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0
failed=0

# A closed box 2 wide (x), 0.5 high, 1 deep (z), pure red.
printf 'newmtl red\nKd 1 0 0\nKs 0 0 0\n' >box.mtl
{
    echo "mtllib box.mtl"
    echo "usemtl red"
    for v in "0 0 0" "2 0 0" "2 0.5 0" "0 0.5 0" "0 0 1" "2 0 1" "2 0.5 1" "0 0.5 1"; do echo "v $v"; done
    echo "f 1 4 3 2"
    echo "f 5 6 7 8"
    echo "f 1 2 6 5"
    echo "f 4 8 7 3"
    echo "f 1 5 8 4"
    echo "f 2 3 7 6"
} >box.obj

# red_span FILE.ppm ROW|COLUMN INDEX: the first and last red pixel along
# that row or column, "first last" (a red pixel: red more than twice green
# and blue and over 40). The PPM's header is its first three lines.
red_span() {
    local file=$1 along=$2 at=$3 size width height
    size=$(sed -n 2p "$file")
    width=${size% *}
    height=${size#* }
    tail -c +$(($(head -n 3 "$file" | wc -c) + 1)) "$file" | od -An -tu1 -v -w3 |
        awk -v along="$along" -v at="$at" -v w="$width" '
            { x = (NR - 1) % w; y = int((NR - 1) / w)
              i = along == "row" ? x : y
              if ((along == "row" ? y : x) == at && $1 > 40 && $1 > 2 * $2 && $1 > 2 * $3) {
                  if (first == "") first = i
                  last = i } }
            END { print first, last }'
}

# expected_span SIZE SHARE: the first and last pixel centre within SHARE of
# an image SIZE pixels across, about its centre.
expected_span() {
    awk -v n="$1" -v s="$2" 'BEGIN {
        for (i = 0; i < n; i++) if ((2 * i + 1 - n) ^ 2 < (s * n) ^ 2) { if (first == "") first = i; last = i }
        print first, last }'
}

# framed WIDTH HEIGHT SHARE_X SHARE_Y: the top view's red top face spans
# SHARE_X of the width along the middle row and SHARE_Y of the height down
# the middle column.
framed() {
    local w=$1 h=$2 got want
    if ! "$GLINT" box.obj --view top -w "$w" -h "$h" --spp 1 -q -o top.ppm; then
        echo "FAIL: $w x $h: glint failed"
        failed=$((failed + 1))
        return
    fi
    for axis in "row $(((h - 1) / 2)) $w $3" "column $(((w - 1) / 2)) $h $4"; do
        read -r along at size share <<<"$axis"
        got=$(red_span top.ppm "$along" "$at")
        want=$(expected_span "$size" "$share")
        if [ "$got" = "$want" ]; then
            passed=$((passed + 1))
        else
            echo "FAIL: $w x $h, $along $at: red from $got, expected $want"
            failed=$((failed + 1))
        fi
    done
}

# Square: the width limits (2 across, 1 up the picture: half the share).
framed 101 101 0.85 0.425
# Wide (161/61): the height limits; across, 0.85 * 2 / (161/61) of the width.
framed 161 61 "$(awk 'BEGIN { print 0.85 * 2 * 61 / 161 }')" 0.85

for view in auto front back left right top iso; do
    if "$GLINT" box.obj --view "$view" -w 8 -h 6 --spp 1 -q -o "$view.png" && [ -s "$view.png" ]; then
        passed=$((passed + 1))
    else
        echo "FAIL: --view $view"
        failed=$((failed + 1))
    fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
