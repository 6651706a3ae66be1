#!/usr/bin/env bash
# bench/display.sh - what the --display window costs a render: the seed
# room (1000x1000, 4 spp) and the bunny (1920x1080, 1 spp) rendered by glint
# with and without the window, in turn in each round, on a virtual X server
# (Xvfb, 1920x1080 at 24 bits, so neither image is scaled). Prints, per
# scene, the median render time of each (glint's own summary: the render,
# not SDL's start-up nor the wait for the user) and the median of the
# rounds' ratios of window to none. The issue's target: no measurable cost.
#
#   bench/display.sh                 glint from build/, 9 rounds
#   BENCH_RUNS=21 GLINT_BIN=/path/to/glint bench/display.sh
#
# See bench/README.md ("The display window").
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh" display.sh 9
for tool in Xvfb xdotool; do
    command -v "$tool" >/dev/null || die "no $tool (Debian: xvfb, xdotool)"
done

tmp=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp 3>"$tmp/display" 2>/dev/null &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; rm -rf "$tmp"' EXIT
for _ in $(seq 100); do
    [ -s "$tmp/display" ] && break
    sleep 0.1
done
export DISPLAY=":$(head -n 1 "$tmp/display")"


# seconds FILE: the render time in glint's summary on stderr, saved in FILE.
seconds() { sed -n 's/.* threads\?: \([0-9.]*\) s, .*/\1/p' "$1"; }

# plain ARGS...: glint ARGS; prints its render time.
plain() {
    "$GLINT" "$@" -o "$tmp/plain.png" 2>"$tmp/err" || die "glint $* failed: $(cat "$tmp/err")"
    seconds "$tmp/err"
}

# windowed ARGS...: glint --display ARGS, closed with q once its summary
# says the render is done; prints its render time. The summary is read
# from a pipe: nothing polls meanwhile, which on two cores would cost the
# render more than the window does.
windowed() {
    rm -f "$tmp/fifo"
    mkfifo "$tmp/fifo"
    "$GLINT" --display "$@" -o "$tmp/shown.png" 2>"$tmp/fifo" &
    local pid=$! wid summary
    read -r summary <"$tmp/fifo" || die "glint --display $* said nothing"
    wid=$(xdotool search --onlyvisible --name '^glint - ' | head -n 1)
    xdotool key --window "$wid" q 2>/dev/null || true
    wait "$pid" || die "glint --display $* failed: $summary"
    cmp -s "$tmp/plain.png" "$tmp/shown.png" || die "glint --display $* wrote other bytes"
    echo "$summary" >"$tmp/err"
    seconds "$tmp/err"
}

# scene NAME ARGS...: RUNS rounds of a render without and with the window.
scene() {
    local name=$1
    shift
    : >"$tmp/plain.t"
    : >"$tmp/shown.t"
    : >"$tmp/ratio.t"
    for ((i = 0; i < RUNS; i++)); do
        local a b
        a=$(plain "$@")
        b=$(windowed "$@")
        echo "$a" >>"$tmp/plain.t"
        echo "$b" >>"$tmp/shown.t"
        awk -v a="$a" -v b="$b" 'BEGIN { print b / a }' >>"$tmp/ratio.t"
    done
    printf '%-24s no window %.3f s   window %.3f s   window/none %.3f (median of %d rounds)\n' "$name" \
        "$(median <"$tmp/plain.t")" "$(median <"$tmp/shown.t")" "$(median <"$tmp/ratio.t")" "$RUNS"
}

scene "seed room 1000x1000" -w 1000 -h 1000
if [[ -f "$REPO/../shared/data/stanford-bunny.obj" ]]; then
    scene "bunny 1920x1080 1 spp" "$REPO/bench/bunny.yaml" -w 1920 -h 1080 --spp 1
else
    echo "bunny: skipped (no ../shared/data/stanford-bunny.obj)"
fi
