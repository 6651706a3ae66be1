#!/usr/bin/env bash
# bench/sequence.sh - an animation's cost: scenes/bouncing-ball.yaml's 48
# frames (640x360, 16 samples, a half-frame shutter) rendered as one run,
# the whole command's wall time and each frame's (reading the scene again
# at the frame's time and at the shutter's poses, building, rendering,
# writing); then motion blur's cost a sample: frame 22 with its shutter
# against the same frame without one, in alternating runs, each run's
# render time over its samples, medians.
#
#   GLINT_BIN=/path/to/glint bench/sequence.sh      BENCH_RUNS=5 (default 3)
#
# Results: bench/README.md.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" sequence.sh 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=$REPO/scenes/bouncing-ball.yaml
grep -v '^  shutter:' "$scene" >"$work/still.yaml"

start=$(date +%s.%N)
"$GLINT" "$scene" --threads 2 -q -o "$work/f-####.png"
end=$(date +%s.%N)
frames=$(find "$work" -name 'f-*.png' | wc -l)
awk -v s="$start" -v e="$end" -v n="$frames" \
    'BEGIN { printf "sequence: %d frames in %.2f s, %.3f s a frame (2 threads, whole command)\n", n, e - s, (e - s) / n }'

# ns_per_sample SCENE: one render of frame 22, its nanoseconds a sample.
ns_per_sample() {
    "$GLINT" "$1" --frame 22 --threads 2 -o "$work/one.png" 2>&1 |
        sed -n 's/.*threads: \([0-9.]*\) s, \([0-9]*\) samples.*/\1 \2/p' | awk '{ printf "%.1f\n", $1 / $2 * 1e9 }'
}
: >"$work/blur"
: >"$work/still"
for _ in $(seq "$RUNS"); do
    ns_per_sample "$scene" >>"$work/blur"
    ns_per_sample "$work/still.yaml" >>"$work/still"
done
blur=$(median <"$work/blur")
still=$(median <"$work/still")
awk -v b="$blur" -v s="$still" -v r="$RUNS" \
    'BEGIN { printf "frame 22: %.1f ns a sample with the shutter, %.1f without: %.2fx (medians of %d alternating runs)\n", b, s, b / s, r }'
