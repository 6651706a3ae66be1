#!/usr/bin/env bash
# bench/sequence.sh - an animation's cost: scenes/bouncing-ball.yaml's 48
# frames (640x360, 16 samples, a half-frame shutter) rendered as one run,
# the whole command's wall time and each frame's (reading the scene again
# at the frame's time and at the shutter's poses, building, rendering,
# writing), by glint on 2 threads and, when glint-mpi is beside glint and
# mpirun is found, by glint-mpi on 2 ranks of 1 thread (whole frames to
# each rank; every frame compared byte for byte with glint's) and by glint
# on 1 thread (one rank's share of the machine), in turn in each round,
# with the medians of the rounds' speed-ups; then motion
# blur's cost a sample: frame 22 with its shutter against the same frame
# without one, in alternating runs, each run's render time over its
# samples, medians.
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

GLINT_MPI=$(dirname "$GLINT")/glint-mpi
with_mpi=0
if [[ -x "$GLINT_MPI" ]] && command -v mpirun >/dev/null; then
    with_mpi=1
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

# whole OUT COMMAND...: the sequence into $work/OUT/, its wall seconds
# appended to $work/OUT.times.
whole() {
    local out=$1 start end
    shift
    rm -rf "${work:?}/$out"
    mkdir "$work/$out"
    start=$(date +%s.%N)
    "$@" "$scene" -q -o "$work/$out/f-####.png" || die "$* failed"
    end=$(date +%s.%N)
    echo "$end - $start" | bc >>"$work/$out.times"
}
: >"$work/ratios"
# ratio A B FILE: the last round's time of A over B's, appended to FILE.
ratio() {
    paste <(tail -n 1 "$work/$1.times") <(tail -n 1 "$work/$2.times") | awk '{ print $1 / $2 }' >>"$work/$3"
}
: >"$work/ratios_one"
for _ in $(seq "$RUNS"); do
    whole glint "$GLINT" --threads 2
    [ "$with_mpi" -eq 1 ] || continue
    whole mpi mpirun -np 2 "$GLINT_MPI" --threads 1
    for f in "$work"/glint/f-*.png; do
        cmp -s "$f" "$work/mpi/${f##*/}" || die "glint-mpi's ${f##*/} differs from glint's"
    done
    whole one "$GLINT" --threads 1
    ratio glint mpi ratios
    ratio one mpi ratios_one
done
frames=$(find "$work/glint" -name 'f-*.png' | wc -l)
glint_s=$(median <"$work/glint.times")
awk -v s="$glint_s" -v n="$frames" -v r="$RUNS" \
    'BEGIN { printf "sequence: %d frames in %.2f s, %.3f s a frame (glint, 2 threads, whole command, median of %d)\n", n, s, s / n, r }'
if [ "$with_mpi" -eq 1 ]; then
    mpi_s=$(median <"$work/mpi.times")
    ratio=$(median <"$work/ratios")
    one_s=$(median <"$work/one.times")
    ratio_one=$(median <"$work/ratios_one")
    awk -v s="$mpi_s" -v n="$frames" -v q="$ratio" -v o="$one_s" -v qo="$ratio_one" \
        'BEGIN { printf "glint-mpi, 2 ranks x 1 thread: %.2f s, %.3f s a frame: %.2fx glint on 2 threads (the same cores), %.2fx glint on 1 thread (%.2f s: one rank'"'"'s core) (medians of the rounds; every frame the same bytes)\n", s, s / n, q, qo, o }'
fi

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
