#!/usr/bin/env bash
# bench/soft-light.sh - glint against POV-Ray 3.7 at equal noise on a soft
# shadow: bench/soft-light.yaml and its copy bench/soft-light.pov, a 2 x 2
# lamp over a ball and a block at 640 x 480, one camera ray a pixel. For
# each light sample count (glint's `samples` N^2, POV-Ray's jittered
# area_light N x N) it prints each renderer's median time and its noise:
# the RMSE against its own 1024-sample reference over the reference's mean
# (bench_rmse, bench/rmse.c). Equal noise is read off the table.
#
#   GLINT_BIN=/path/to/glint bench/soft-light.sh     (BENCH_RUNS=5: 5 runs each)
#
# Results and what they mean: bench/README.md.
set -euo pipefail

BENCH_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
RUNS=${BENCH_RUNS:-3}
die() { echo "bench/soft-light.sh: $*" >&2; exit 1; }
[[ -x "${GLINT_BIN:-}" ]] || die "set GLINT_BIN to a built glint (./build.sh render builds one)"
command -v povray >/dev/null 2>&1 || die "povray is missing (Debian: apt-get install povray)"
[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || die "BENCH_RUNS must be a positive integer, not '$RUNS'"

# POV-Ray's Debian configuration reads scenes only from a few folders: /tmp is one.
WORK=$(mktemp -d /tmp/glint-soft-light.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
cp "$BENCH_DIR/soft-light.pov" "$WORK/"
cc -O2 -o "$WORK/bench_rmse" "$BENCH_DIR/rmse.c" -lm || die "cannot build bench/rmse.c"

# glint N OUT: renders with N samples on the lamp; prints the seconds.
glint() {
    sed "s/samples: 16 }/samples: $1 }/" "$BENCH_DIR/soft-light.yaml" >"$WORK/scene.yaml"
    "$GLINT_BIN" "$WORK/scene.yaml" --threads 2 -o "$2" 2>&1 | sed -n 's/.*threads: \([0-9.]*\) s,.*/\1/p'
}
# povray N OUT: renders with an N x N area light; prints the trace seconds.
povray_run() {
    (cd "$WORK" && povray soft-light.pov -D +W640 +H480 +FP "+O$2" "Declare=LIGHT_N=$1" Declare=LIGHT_POWER=0.85 \
        -A +WT2 2>&1) | sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

glint 1024 "$WORK/glint-ref.ppm" >/dev/null
povray_run 32 "$WORK/povray-ref.ppm" >/dev/null
printf '%-4s %-8s %-12s %-12s %-12s %-12s %s\n' N samples "glint s" "glint noise" "povray s" "povray noise" "povray/glint"
for n in 2 3 4 6 8 12; do
    g=$(for _ in $(seq "$RUNS"); do glint $((n * n)) "$WORK/glint.ppm"; done | median)
    p=$(for _ in $(seq "$RUNS"); do povray_run "$n" "$WORK/povray.ppm"; done | median)
    printf '%-4s %-8s %-12s %-12s %-12s %-12s %s\n' "$n" $((n * n)) "$g" "$("$WORK/bench_rmse" "$WORK/glint.ppm" "$WORK/glint-ref.ppm")" \
        "$p" "$("$WORK/bench_rmse" "$WORK/povray.ppm" "$WORK/povray-ref.ppm")" "$(awk -v g="$g" -v p="$p" 'BEGIN { printf "%.2f", p / g }')"
done
