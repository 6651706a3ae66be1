# mpi.sh - what the glint-mpi tests share, sourced after harness.sh:
# glint-mpi's path beside glint (the test skipped, exit 77, when it was not
# built or mpirun is missing), mpirun allowed to run as root and more ranks
# than cores, OpenMPI's own leaks suppressed under ASan, a hang guard, and
# ways to launch glint-mpi and see every rank's exit code.
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
GLINT_MPI=$(dirname "$GLINT")/glint-mpi
if [ ! -x "$GLINT_MPI" ]; then
    echo "SKIP: no glint-mpi beside $GLINT (configured without MPI)"
    exit 77
fi
if ! command -v mpirun >/dev/null; then
    echo "SKIP: no mpirun (Debian: openmpi-bin)"
    exit 77
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Under ASan, OpenMPI's own leaks are suppressed (tests/cli/mpi.supp), which
# needs whole stacks; glint's leaks are still found. Other builds ignore it.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}fast_unwind_on_malloc=0"
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$here/tests/cli/mpi.supp:print_suppressions=0"
# A hang fails the test instead of stalling it.
limit=$((60 * ${GLINT_TIME_SCALE:-1}))
# Under the sanitizers (a time scale above 1) each launch takes seconds:
# the sanitizer build checks fewer cases (every rank count still), the
# Release build all of them.
full=1
[ "${GLINT_TIME_SCALE:-1}" -le 1 ] || full=0

# mpi N ARGS...: glint-mpi ARGS on N ranks, and mpirun's exit code.
mpi() {
    local n=$1
    shift
    timeout "$limit" mpirun --oversubscribe -np "$n" "$GLINT_MPI" "$@"
}

# mpi_codes N ARGS...: glint-mpi ARGS on N ranks, each rank's exit code
# in the file code.RANK. mpirun is told not to end the other ranks when one
# exits with an error (as it does by default), so that each can be seen.
mpi_codes() {
    local n=$1
    shift
    rm -f code.*
    timeout "$limit" mpirun --oversubscribe --mca orte_abort_on_non_zero_status 0 -np "$n" \
        sh -c '"$@"; c=$?; echo "$c" >"code.$OMPI_COMM_WORLD_RANK"; exit "$c"' sh "$GLINT_MPI" "$@"
}

# codes_are N CODE: every one of N ranks exited with CODE.
codes_are() {
    local n=$1 code=$2 r
    for ((r = 0; r < n; r++)); do
        [ -f "code.$r" ] && [ "$(cat "code.$r")" = "$code" ] || return 1
    done
}

