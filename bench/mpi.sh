#!/usr/bin/env bash
# bench/mpi.sh - the cost of MPI on one machine: the seed room and the
# bunny rendered by glint with 1 and 2 threads and by glint-mpi with 2
# ranks of 1 thread (mpirun binds each to a core), every image compared
# byte for byte with glint's. The issue's target: 2 ranks within 5% of 2
# threads. Prints, per scene, the median render time (each program's own
# summary: the render, not the start-up), the median wall time, the median
# of the rounds' ratios of 2 ranks to 2 threads (the three run in turn in
# each round), and the bytes crossing between the ranks (the pixels of the
# tiles rank 1 rendered, 12 bytes each, and the scene's files sent to it).
#
#   bench/mpi.sh                     glint and glint-mpi from build/, 5 rounds
#   BENCH_RUNS=3 GLINT_BIN=/path/to/glint bench/mpi.sh
#
# See bench/README.md ("glint-mpi on one machine").
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh" mpi.sh 5
GLINT_MPI=$(dirname "$GLINT")/glint-mpi
[[ -x "$GLINT_MPI" ]] || die "no glint and glint-mpi in $(dirname "$GLINT"): build them (./build.sh)"
command -v mpirun >/dev/null || die "no mpirun (Debian: openmpi-bin)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT


# once OUT COMMAND...: one run; appends its render seconds (from the
# summary line) and wall seconds to $tmp/OUT.times; its stderr stays in
# $tmp/last.err.
once() {
    local out=$1 start end
    shift
    start=$(date +%s.%N)
    "$@" -o "$tmp/$out" 2>"$tmp/last.err" >/dev/null || die "$* failed: $(cat "$tmp/last.err")"
    end=$(date +%s.%N)
    echo "$(grep -oE ': [0-9.]+ s,' "$tmp/last.err" | grep -oE '[0-9.]+') $(echo "$end - $start" | bc)" \
        >>"$tmp/$out.times"
}

# show LABEL OUT: the median render and wall seconds of OUT's runs.
show() {
    printf '%-34s render %6.3f s   wall %6.3f s\n' "$1" "$(cut -d' ' -f1 "$tmp/$2.times" | median)" \
        "$(cut -d' ' -f2 "$tmp/$2.times" | median)"
}

# scene NAME FILE-OR-EMPTY FILES-BYTES ARGS...: RUNS rounds of one scene,
# each running glint with 1 and 2 threads and glint-mpi with 2 ranks of 1
# in turn: the machine's speed drifts by 20% within minutes, so the ratio
# that matters is taken within each round, and its median reported.
scene() {
    local name=$1 file=$2 file_bytes=$3
    shift 3
    echo "$name:"
    rm -f "$tmp"/*.times
    for ((r = 0; r < RUNS; r++)); do
        once one.png "$GLINT" $file "$@" --threads 1
        once two.png "$GLINT" $file "$@" --threads 2
        once mpi.png mpirun -np 2 "$GLINT_MPI" $file "$@" --threads 1
        cmp -s "$tmp/two.png" "$tmp/mpi.png" || die "$name: glint-mpi's image differs from glint's"
    done
    show "glint --threads 1" one.png
    show "glint --threads 2" two.png
    show "mpirun -np 2 glint-mpi --threads 1" mpi.png
    echo "  2 ranks / 2 threads, render time: median of the rounds' ratios" \
        "$(paste -d' ' "$tmp/two.png.times" "$tmp/mpi.png.times" | awk '{ printf "%.4f\n", $3 / $1 }' | median)"
    local size tiles1
    size=$(grep -oE 'glint-mpi: [0-9]+x[0-9]+' "$tmp/last.err" | grep -oE '[0-9]+x[0-9]+')
    tiles1=$(grep -oE 'rank 1 [0-9]+% \([0-9]+' "$tmp/last.err" | grep -oE '[0-9]+$')
    echo "  last glint-mpi run: $(grep -oE 'busy:.*' "$tmp/last.err")"
    echo "  sent to rank 0: at most ${tiles1} tiles x 32 x 32 pixels x 12 bytes = $((tiles1 * 32 * 32 * 12)) bytes" \
        "(the image, $size, is $(( ${size%x*} * ${size#*x} * 12 )) bytes); to rank 1: $file_bytes bytes of files"
}

scene "seed room 1000x1000, 4 spp" "" 0 -w 1000 -h 1000
BUNNY=$REPO/../shared/data/stanford-bunny.obj
if [[ -f "$BUNNY" ]]; then
    files=$(($(stat -c %s "$BUNNY") + $(stat -c %s "$REPO/bench/bunny.yaml")))
    scene "bunny 1920x1080, 1 spp" "$REPO/bench/bunny.yaml" "$files"
    # A longer render, where the other rank's late start (it loads the
    # scene after rank 0 has) weighs less.
    scene "bunny 3840x2160, 4 spp" "$REPO/bench/bunny.yaml" "$files" -w 3840 -h 2160 --spp 4
else
    echo "bunny: skipped (no $BUNNY)"
fi
