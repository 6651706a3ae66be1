#!/usr/bin/env bash
# bench/spd.sh - glint against Tachyon on the seven SPD scenes in NFF
# (../shared/data/spd/), each read by both from the same file: 512 x 512,
# one sample a pixel, ray depth 5, 2 threads, the whole process timed (start,
# parse, build, render, write a PNG). Runs alternate, glint then Tachyon, and
# each side's median is reported with glint's speed-up and its geometric
# mean over the scenes. Then, for balls and tetra, glint's trace against a
# bare Embree loop's (bench/ceiling.c). Tachyon (Debian's tachyon-bin-nox) is installed when
# missing and root.
#
#   bench/spd.sh                     build/glint, 5 runs each
#   BENCH_RUNS=9 GLINT_BIN=... bench/spd.sh
#   SPD_DIR=/path/to/spd bench/spd.sh
#   BENCH_IMAGES=DIR bench/spd.sh    keep both renders of every scene in DIR
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" spd.sh 5

SPD=${SPD_DIR:-$(dirname "$REPO")/shared/data/spd}
SCENES=(balls gears mount rings teapot tetra tree)
for s in "${SCENES[@]}"; do
    [[ -f "$SPD/$s.nff" ]] || die "no $SPD/$s.nff (set SPD_DIR to the folder of the SPD's NFF files)"
done
if ! command -v tachyon-nox >/dev/null 2>&1; then
    [[ $(id -u) -eq 0 ]] && command -v apt-get >/dev/null 2>&1 \
        || die "tachyon-nox is missing: install it ('sudo apt-get install tachyon-bin-nox')"
    apt-get update -qq >/dev/null || true
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq tachyon-bin-nox >/dev/null \
        || die "apt-get install tachyon-bin-nox failed"
fi

WORK=$(mktemp -d /tmp/glint-spd.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
# seconds CMD...: the wall time of CMD, which must succeed, in seconds.
seconds() {
    local t0=$EPOCHREALTIME
    "$@" >"$WORK/log" 2>&1 || { tail -n 5 "$WORK/log" >&2; die "failed: $*"; }
    awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.4f\n", b - a }'
}

echo "| scene  | glint s | tachyon s | glint faster |"
echo "| ------ | ------: | --------: | -----------: |"
log_sum=0
for s in "${SCENES[@]}"; do
    g=() t=()
    for ((r = 0; r < RUNS; r++)); do
        g+=("$(seconds "$GLINT" "$SPD/$s.nff" -w 512 -h 512 --spp 1 --depth 5 --threads 2 -q -o "$WORK/$s-glint.png")")
        t+=("$(seconds tachyon-nox "$SPD/$s.nff" -res 512 512 -numthreads 2 -raydepth 5 -format PNG \
               -o "$WORK/$s-tachyon.png")")
    done
    gm=$(printf '%s\n' "${g[@]}" | median)
    tm=$(printf '%s\n' "${t[@]}" | median)
    ratio=$(awk -v a="$gm" -v b="$tm" 'BEGIN { printf "%.2f", b / a }')
    log_sum=$(awk -v s="$log_sum" -v r="$ratio" 'BEGIN { print s + log(r) }')
    printf "| %-6s | %7.3f | %9.3f | %11sx |\n" "$s" "$gm" "$tm" "$ratio"
    if [[ -n "${BENCH_IMAGES:-}" ]]; then
        mkdir -p "$BENCH_IMAGES"
        cp "$WORK/$s-glint.png" "$WORK/$s-tachyon.png" "$BENCH_IMAGES/"
    fi
done
awk -v s="$log_sum" -v n="${#SCENES[@]}" 'BEGIN { printf "geometric mean: glint %.2fx faster\n", exp(s / n) }'
echo "($RUNS runs each, alternating; medians of the whole process; $(nproc) cores)"

# The ceiling: bench_ceiling (beside glint) traces the camera and shadow
# rays of a 1-sample render through bare Embree, with Embree's own spheres,
# triangles and cone curves (the rings' cylinders, the tree's cones), in
# packets of 8. glint renders the same rays with --depth 0 (no
# reflections); its trace time is its render's less a 1x1 render's (the
# build). At 2048 x 2048, where a trace takes long enough to time. The
# target (70%) is for balls and tetra; rings and tree show what Embree's
# own cone curves would give.
CEILING="$(dirname "$GLINT")/bench_ceiling"
[[ -x "$CEILING" ]] || die "no bench_ceiling beside $GLINT: build it (cmake --build BUILD --target bench_ceiling)"
# render_seconds ARGS...: the render time in glint's summary line.
render_seconds() {
    "$GLINT" "$@" --depth 0 --threads 2 -o "$WORK/ceiling.png" 2>&1 | tail -n 1 | grep -oE '[0-9.]+ s,' | grep -oE '[0-9.]+'
}
echo
echo "| scene | glint trace s | ceiling-8 trace s | glint/ceiling |"
echo "| ----- | ------------: | ----------------: | ------------: |"
for s in balls tetra rings tree; do
    sed 's/^resolution .*/resolution 2048 2048/' "$SPD/$s.nff" >"$WORK/$s-2048.nff"
    g=() c=()
    for ((r = 0; r < RUNS; r++)); do
        full=$(render_seconds "$WORK/$s-2048.nff")
        build=$(render_seconds "$WORK/$s-2048.nff" -w 1 -h 1)
        g+=("$(awk -v a="$full" -v b="$build" 'BEGIN { printf "%.4f\n", a - b }')")
        c+=("$("$CEILING" "$WORK/$s-2048.nff" --threads 2 --packet 8 --runs 1 | grep -oE 'trace [0-9.]+' | grep -oE '[0-9.]+')")
    done
    gm=$(printf '%s\n' "${g[@]}" | median)
    cm=$(printf '%s\n' "${c[@]}" | median)
    printf "| %-5s | %13.3f | %17.3f | %12.0f%% |\n" "$s" "$gm" "$cm" "$(awk -v a="$gm" -v b="$cm" 'BEGIN { print 100 * b / a }')"
done
echo "(2048x2048, 1 sample, camera and shadow rays only; target 70% for balls and tetra)"
