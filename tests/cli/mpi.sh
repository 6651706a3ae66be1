#!/usr/bin/env bash
# glint-mpi (src/mpi/), found beside glint: the default scene and every
# example scene render to the bytes glint gives, on 1, 2, 3, 4 and 7 ranks
# with various thread counts, the regular and the jittered sampler; a scene
# error is reported once, by rank 0, with glint's message, and every rank
# exits with glint's code, writing nothing; bad flags likewise, and what
# glint-mpi cannot do yet (-o -, --partial) is refused; ranks that cannot
# read the scene rank 0 read fail it alike; a rank killed ends the job.
# Skipped (exit 77) when glint-mpi was not built (no MPI found) or mpirun is
# missing. Ranks run as root inside containers, and more ranks than cores.
# Under ASan the leaks OpenMPI leaves are suppressed (mpi.supp).
# Usage: mpi.sh PATH/TO/glint
here=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/lib/harness.sh"
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

# same N THREADS OUT [SCENE] [FLAGS...]: glint-mpi on N ranks of THREADS
# threads each writes OUT with the bytes glint writes on 2 threads.
same() {
    local n=$1 threads=$2 out=$3
    shift 3
    local what="${1:-the default scene} ${*:2} on $n ranks x $threads threads"
    [ -n "$1" ] || shift
    rm -f "ref-$out" "$out"
    if ! "$GLINT" "$@" -w 64 -h 48 --threads 2 -q -o "ref-$out"; then
        verdict 1 "glint renders $what"
        return
    fi
    if ! mpi "$n" "$@" -w 64 -h 48 --threads "$threads" -q -o "$out" >mpi.log 2>&1; then
        sed 's/^/  /' mpi.log
        verdict 1 "glint-mpi renders $what"
        return
    fi
    cmp -s "ref-$out" "$out"
    verdict $? "glint-mpi renders the bytes glint renders: $what"
}

# The default scene on every rank count, floats compared exactly (OpenEXR
# float pixels) and as PNG; jittered sampling too.
ranks=(1 2 3 4 7)
threads=(2 1 2 1 1)
for i in "${!ranks[@]}"; do
    same "${ranks[$i]}" "${threads[$i]}" default.exr "" --exr-pixel float
    [ "$full" -eq 0 ] || same "${ranks[$i]}" "${threads[$i]}" default.png ""
done
same 3 1 jittered.exr "" --sampler jittered --spp 9 --exr-pixel float
[ "$full" -eq 0 ] || same 7 2 jittered.png "" --sampler jittered --spp 4 --seed 7

# Every example scene, each on another rank count (two under the sanitizers).
i=0
for scene in "$here"/scenes/*.yaml; do
    [ "$full" -eq 1 ] || [ "$i" -lt 2 ] || break
    same "${ranks[$((i % 5))]}" "${threads[$(((i + 1) % 5))]}" "$(basename "$scene" .yaml).png" "$scene"
    i=$((i + 1))
done
[ "$full" -eq 0 ] || [ "$i" -ge 6 ]
verdict $? "at least six example scenes, found $i"
[ "$full" -eq 0 ] || same 4 1 refraction-jittered.png "$here/scenes/refraction.yaml" --sampler jittered --spp 4

# codes_are N CODE: every one of N ranks exited with CODE.
codes_are() {
    local n=$1 code=$2 r
    for ((r = 0; r < n; r++)); do
        [ -f "code.$r" ] && [ "$(cat "code.$r")" = "$code" ] || return 1
    done
}

# expect_failure N CODE WHAT ARGS...: glint ARGS and glint-mpi ARGS on N
# ranks fail alike: glint's messages (its name aside) once from glint-mpi,
# CODE from glint, mpirun and every rank, and out.png left as it was.
expect_failure() {
    local n=$1 code=$2 what=$3
    shift 3
    echo old >out.png
    "$GLINT" "$@" -o out.png 2>glint.err >/dev/null
    local st=$?
    mpi "$n" "$@" -o out.png >/dev/null 2>mpi.err
    local mst=$?
    mpi_codes "$n" "$@" -o out.png >/dev/null 2>&1
    [ "$st" -eq "$code" ] && [ "$mst" -eq "$code" ] && codes_are "$n" "$code"
    verdict $? "$what: exit $code from glint ($st), mpirun ($mst) and each of $n ranks ($(cat code.* 2>/dev/null | tr '\n' ' '))"
    local line ok=0
    while IFS= read -r line; do
        [ "$(grep -cxF -- "$line" mpi.err)" -eq 1 ] || ok=1
    done <glint.err
    [ -s glint.err ] && [ "$ok" -eq 0 ]
    verdict $? "$what: glint's message once from glint-mpi; got: $(head -c 600 mpi.err)"
    [ "$(cat out.png)" = old ] && [ "$(ls -A | grep -c '^\.\?out\.png.')" -eq 0 ]
    verdict $? "$what: the output left as it was, no temporary file"
}

printf 'glint: 1\nsettings: { width: 16, heigth: 8 }\n' >bad.yaml
expect_failure 3 1 "a scene error" bad.yaml -q
if [ "$full" -eq 1 ]; then
    expect_failure 4 1 "a missing scene" no-such-scene.yaml -q
    expect_failure 2 2 "a bad flag" --threads -3 -q
fi

mpi 2 -o - -q >/dev/null 2>mpi.err
st=$?
mpi_codes 2 -o - -q >/dev/null 2>&1
[ "$st" -eq 2 ] && codes_are 2 2 && [ "$(grep -c 'standard output' mpi.err)" -eq 1 ]
verdict $? "glint-mpi refuses -o - on every rank, saying so once"
if [ "$full" -eq 1 ]; then
    mpi 2 --partial -q -o out.png >/dev/null 2>mpi.err
    [ $? -eq 2 ] && [ "$(grep -c -- '--partial' mpi.err)" -eq 1 ] && [ "$(cat out.png)" = old ]
    verdict $? "glint-mpi refuses --partial, which it cannot honour yet, saying so once"
fi

# Workers that cannot read the scene rank 0 read (run elsewhere: for now
# each rank reads the files itself) say so, rank 0 says what it means, and
# every rank exits 1.
mkdir -p lead elsewhere
cp "$here/scenes/shapes.yaml" lead/
rm -f code.*
timeout "$limit" mpirun --oversubscribe --mca orte_abort_on_non_zero_status 0 \
    -np 1 --wdir lead sh -c '"$@"; c=$?; echo "$c" >"../code.0"; exit "$c"' sh \
    "$GLINT_MPI" shapes.yaml -w 64 -h 48 -q -o out.png : \
    -np 2 --wdir elsewhere sh -c '"$@"; c=$?; echo "$c" >"../code.$OMPI_COMM_WORLD_RANK"; exit "$c"' sh \
    "$GLINT_MPI" shapes.yaml -w 64 -h 48 -q -o out.png >/dev/null 2>mpi.err
codes_are 3 1 && [ "$(grep -c "cannot read scene 'shapes.yaml'" mpi.err)" -eq 2 ] &&
    [ "$(grep -c 'another rank could not load the scene rank 0 loaded' mpi.err)" -eq 1 ] && [ ! -e lead/out.png ]
verdict $? "ranks that cannot read rank 0's scene: each says so, rank 0 once what it means, every rank exits 1"

# A rank killed mid-render ends the whole job within seconds, non-zero,
# with no rank left and the output as it was (mpirun's own doing, kept
# here so that nothing glint-mpi does defeats it: no rank may hang).
if [ "$full" -eq 1 ]; then
    rm -f pid.*
    timeout "$limit" mpirun --oversubscribe -np 3 sh -c 'echo $$ >"pid.$OMPI_COMM_WORLD_RANK"; exec "$@"' sh \
        "$GLINT_MPI" -w 2000 -h 2000 --spp 64 --threads 1 -q -o out.png >/dev/null 2>&1 &
    job=$!
    for _ in $(seq 100); do
        [ -s pid.1 ] && break
        sleep 0.1
    done
    sleep 1
    kill -9 "$(cat pid.1)"
    for _ in $(seq 100); do
        kill -0 "$job" 2>/dev/null || break
        sleep 0.1
    done
    if kill -0 "$job" 2>/dev/null; then
        verdict 1 "the job ends within 10 s of a rank killed"
        kill "$job"
    else
        wait "$job"
        st=$?
        # mpirun may return while the ranks it ended are being reaped.
        for _ in $(seq 50); do
            alive=0
            for f in pid.*; do
                ! kill -0 "$(cat "$f")" 2>/dev/null || alive=1
            done
            [ "$alive" -eq 1 ] || break
            sleep 0.1
        done
        [ "$st" -ne 0 ] && [ "$alive" -eq 0 ] && [ "$(cat out.png)" = old ] &&
            [ "$(ls -A | grep -c '^\.\?out\.png.')" -eq 0 ]
        verdict $? "a rank killed: the job ends (exit $st), no rank left, the output as it was"
    fi
fi

finish
