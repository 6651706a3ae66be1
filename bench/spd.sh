#!/usr/bin/env bash
# bench/spd.sh - glint against Tachyon on the seven SPD scenes in NFF
# (../shared/data/spd/), each read by both from the same file: 512 x 512,
# one sample a pixel, ray depth 5, 2 threads, the whole process timed (start,
# parse, build, render, write a PNG). Runs alternate, glint then Tachyon, and
# each side's median is reported with glint's speed-up and its geometric
# mean over the scenes. Tachyon (Debian's tachyon-bin-nox) is installed when
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
