# common.sh - what bench/display.sh, huge.sh and mpi.sh share, sourced with
# the script's name and its default count of rounds: REPO, GLINT (GLINT_BIN,
# else build/glint, checked), RUNS (BENCH_RUNS, else the default, checked),
# die MESSAGE, and median (of the numbers on standard input, one a line).
# shellcheck disable=SC2034 # REPO, GLINT and RUNS are the scripts'
bench_name=$1
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
GLINT=${GLINT_BIN:-$REPO/build/glint}
RUNS=${BENCH_RUNS:-$2}
die() { echo "bench/$bench_name: $*" >&2; exit 1; }
[[ -x "$GLINT" ]] || die "no glint at $GLINT: build it (./build.sh) or set GLINT_BIN"
[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || die "BENCH_RUNS must be a positive integer, not '$RUNS'"
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
