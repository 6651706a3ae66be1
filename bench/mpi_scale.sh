#!/usr/bin/env bash
# bench/mpi_scale.sh - glint-mpi past this machine: times every tile of a
# one-thread 4K render of the bunny (bench_tile_times), replays those times
# through a model of glint-mpi's scheduler for 2 to 256 ranks of one thread
# over a 50 us, 10 Gbit/s network, with the 4K frame scaled to one minute on
# one core (bench_mpi_model), and prints the predicted efficiency table.
# Then it checks the model against glint-mpi itself: 2 ranks x 1 thread on
# this machine, at 3840x2160 with 1 sample a pixel and at 1920x1080 with 16
# (tiles 16 times longer), the render time glint-mpi reports against the
# model's for the same image and start-up.
#
#   bench/mpi_scale.sh                        build (Release) and run, 3 renders of each
#   MPI_SCALE_RUNS=5 bench/mpi_scale.sh       5 renders of each
#   MPI_SCALE_BUILD=DIR bench/mpi_scale.sh    build in DIR (default bench/build-mpi-scale)
#
# It needs the Stanford bunny in the shared data folder beside the
# repository (bench/bunny.yaml says where) and skips with a message without
# it. The check against glint-mpi needs MPI (mpirun, and CMake finding MPI
# to build glint-mpi); without it only the model runs. See bench/README.md,
# "glint-mpi past this machine: the scaling model".
#
# bench/README.md's scheduler comparison ("The pull queue stays", under "glint-mpi
# past this machine") is not run here; these commands give it, the model's rows
# 8, 64 and 256 of each run (the last column: without start-up; the
# bunny's files are 2409696 bytes):
#   bench_tile_times bench/bunny.yaml --size 3840x2160 --spp 1 --runs 5 >t.txt
#   awk '$1 == "tile" && $2 < 1920 && $3 >= 1080 { $4 = sprintf("%.7f", $4 * 10) } { print }' t.txt >bl.txt
#   awk '$1 == "tile" && $2 < 1920 && $3 < 1080 { $4 = sprintf("%.7f", $4 * 10) } { print }' t.txt >tl.txt
#   for f in t bl tl; do for s in pull static steal; do
#       bench_mpi_model $f.txt --one-core 60 --file-bytes 2409696 --schedule $s --ranks 8,64,256; done; done
set -euo pipefail

BENCH_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(dirname "$BENCH_DIR")
BUILD_DIR=${MPI_SCALE_BUILD:-$BENCH_DIR/build-mpi-scale}
RUNS=${MPI_SCALE_RUNS:-3}
SCENE="$BENCH_DIR/bunny.yaml"
BUNNY_OBJ="$(dirname "$REPO")/shared/data/stanford-bunny.obj"
ONE_CORE=60    # seconds: the 4K frame on one core, as the issue sets it

die() { echo "mpi_scale: $*" >&2; exit 1; }
note() { echo "mpi_scale: $*" >&2; }

[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || die "MPI_SCALE_RUNS must be a positive integer, not '$RUNS'"
if [[ ! -f "$BUNNY_OBJ" ]]; then
    note "skipped: $BUNNY_OBJ not found (the shared data folder beside the repository is absent)"
    exit 0
fi
command -v cmake >/dev/null 2>&1 || die "cmake is missing"
command -v taskset >/dev/null 2>&1 || die "taskset is missing (Debian: util-linux)"

# ------------------------------------------------------------------ build
note "building in $BUILD_DIR (Release)"
mkdir -p "$BUILD_DIR"
LOG="$BUILD_DIR/mpi-scale-build.log"
cmake -S "$REPO" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DGLINT_BUILD_TESTS=OFF >"$LOG" 2>&1 \
    || { tail -n 30 "$LOG" >&2; die "configuring failed (log: $LOG)"; }
TARGETS=(bench_tile_times bench_mpi_model)
REAL=1
BUILD_TARGETS=$(cmake --build "$BUILD_DIR" --target help 2>/dev/null || true)
if grep -q 'glint-mpi' <<<"$BUILD_TARGETS" && command -v mpirun >/dev/null 2>&1; then
    TARGETS+=(glint-mpi)
else
    REAL=0
    note "no MPI (mpirun, or glint-mpi in the build): the model runs, the check against glint-mpi does not"
fi
cmake --build "$BUILD_DIR" -j2 --target "${TARGETS[@]}" >>"$LOG" 2>&1 \
    || { tail -n 30 "$LOG" >&2; die "build failed (log: $LOG)"; }

WORK=$(mktemp -d /tmp/glint-mpi-scale.XXXXXX)
cleanup() { rm -rf "$WORK"; }
trap cleanup EXIT

# The files a worker would be sent: the scene and its model.
FILE_BYTES=$(($(stat -c %s "$SCENE") + $(stat -c %s "$BUNNY_OBJ")))

# tile_times_of SIZE SPP: times every tile of the bunny at SIZE and SPP samples a
# pixel into $WORK/times-SIZE-SPP.txt (once) and prints that path.
tile_times_of() {
    local out="$WORK/times-$1-$2.txt"
    if [[ ! -f "$out" ]]; then
        note "timing every tile at $1, $2 spp, one thread ($RUNS renders)"
        # On one core, as a rank of one core loads: the OBJ reader's
        # threads (one per processor online) share it.
        taskset -c 0 "$BUILD_DIR/bench_tile_times" "$SCENE" --size "$1" --spp "$2" --runs "$RUNS" >"$out"
    fi
    echo "$out"
}

# ------------------------------------------------------------------ the model
"$BUILD_DIR/bench_mpi_model" "$(tile_times_of 3840x2160 1)" --one-core "$ONE_CORE" --file-bytes "$FILE_BYTES"

# ------------------------------------------------------------------ the check
((REAL)) || exit 0
if [[ $(id -u) -eq 0 ]]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
echo
echo "### The model against glint-mpi, 2 ranks x 1 thread on this machine ($(nproc) cores)"
echo
echo "| image | glint-mpi's render s (median of $RUNS) | model s | time on tiles, glint-mpi's ranks / one thread alone | rank 0's tiles, glint-mpi | model |"
echo "| --- | --- | --- | --- | --- | --- |"
# column N: the Nth column of $WORK/runs.txt, one line; median N: its median.
column() { awk -v n="$1" '{ printf "%s%s", (NR > 1 ? " " : ""), $n }' "$WORK/runs.txt"; }
median() { tr ' ' '\n' <<<"$(column "$1")" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
for check in "3840x2160 1" "1920x1080 16"; do
    read -r size spp <<<"$check"
    times_file=$(tile_times_of "$size" "$spp")
    alone=$(awk '/^tile/ { t += $4 } END { print t }' "$times_file")
    model_row=$("$BUILD_DIR/bench_mpi_model" "$times_file" --ranks 2 --startup loaded | grep '^| 2 |')
    : >"$WORK/runs.txt"
    for ((i = 0; i < RUNS; i++)); do
        mpirun --oversubscribe --bind-to none -np 2 "$BUILD_DIR/glint-mpi" "$SCENE" -w "${size%x*}" -h "${size#*x}" \
            --spp "$spp" --threads 1 -o "$WORK/out.png" >"$WORK/run.log" 2>&1 \
            || { tail -n 20 "$WORK/run.log" >&2; die "glint-mpi failed"; }
        # The summary, "... 1 thread: S s, ...; busy: rank 0 B0% (N0 tiles), rank 1 B1% (N1 tiles)",
        # as "S (B0 + B1) x S / alone N0".
        tr '\r' '\n' <"$WORK/run.log" | grep -a 'glint-mpi: .*busy:' | tail -n 1 | awk -v alone="$alone" '{
            s = $0; sub(/.*thread: /, "", s)
            n = split($0, part, "busy:"); split(part[n], ranks, ",")
            for (r in ranks) { b = ranks[r]; sub(/^ rank [0-9]+ /, "", b); busy += b / 100 }
            t = ranks[1]; sub(/.*\(/, "", t)
            printf "%s %.2f %d\n", s + 0, busy * (s + 0) / alone, t + 0 }' >>"$WORK/runs.txt"
    done
    awk -F'|' -v image="$size, $spp spp" -v seconds="$(median 1) ($(column 1))" -v slower="$(median 2)" \
        -v tiles="$(column 3)" '{ printf "| %s | %s | %.3f | %sx | %s | %d |\n", image, seconds, $3, slower, tiles, $7 }' \
        <<<"$model_row"
done
