#!/usr/bin/env bash
# glint-mpi's faults: a signal to any one rank stops every rank at once,
# as glint stops (exit 4; with --partial rank 0 writes the tiles finished,
# else nothing), and so does Ctrl-C or SIGTERM to mpirun (which passes it
# on to every rank a second later and exits 1 itself, whatever the ranks
# say); a rank killed ends the job; and a rank running another build is
# refused before anything is read. Nothing hangs, no rank is left, and the
# output is left as it was unless written whole. Skipped (exit 77) without
# glint-mpi or mpirun.
# Usage: mpi_faults.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"
source "$(dirname "$0")/lib/mpi.sh"

# launch ARGS...: glint-mpi on 3 ranks of one thread, rendering a large
# image for a long time with ARGS, in the background ($job is mpirun),
# each rank's pid in pid.RANK and stderr in job.err. True once rank 0's
# progress line shows that the render has begun.
launch() {
    rm -f pid.* job.err
    mpirun --oversubscribe -np 3 sh -c 'echo $$ >"pid.$OMPI_COMM_WORLD_RANK"; exec "$@"' sh \
        "$GLINT_MPI" -w 2000 -h 2000 --spp 64 --threads 1 -o out.png "$@" >/dev/null 2>job.err &
    job=$!
    for _ in $(seq $((10 * limit))); do
        grep -q '%' job.err 2>/dev/null && return 0
        sleep 0.1
    done
    return 1
}

# ends_within SECONDS: true when the job ended within SECONDS and no rank
# is left, with $st its exit code; a job still running is killed.
ends_within() {
    local tenths=$(($1 * 10 * ${GLINT_TIME_SCALE:-1})) alive
    st=none
    for _ in $(seq "$tenths"); do
        kill -0 "$job" 2>/dev/null || break
        sleep 0.1
    done
    if kill -0 "$job" 2>/dev/null; then
        kill -9 "$job" $(cat pid.* 2>/dev/null) 2>/dev/null
        wait "$job" 2>/dev/null
        return 1
    fi
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
    [ "$alive" -eq 0 ]
}

# untouched: out.png is as it was, with no temporary file beside it.
untouched() {
    [ "$(cat out.png)" = old ] && [ "$(ls -A | grep -c '^\.\?out\.png.')" -eq 0 ]
}

# A signal to one worker, with --partial: every rank stops, rank 0 writes
# the finished tiles and says so once, and the job's code is glint's 4.
echo old >out.png
if launch --partial; then
    kill -INT "$(cat pid.1)"
    ends_within 10
    verdict $? "SIGINT to rank 1: the job ends within 10 s, no rank left"
    [ "$st" = 4 ] && [ "$(grep -c 'interrupted: [0-9]* of 3969 tiles finished, written to out.png (the rest black)' job.err)" -eq 1 ] &&
        [ "$(head -c 4 out.png | tail -c 3)" = PNG ]
    verdict $? "SIGINT to rank 1 with --partial: exit 4 ($st), the finished tiles written, said once: $(tail -c 300 job.err)"
else
    verdict 1 "the long render begins: $(tail -c 300 job.err)"
fi

# SIGTERM to rank 0, without --partial: nothing written.
echo old >out.png
if launch; then
    kill -TERM "$(cat pid.0)"
    ends_within 10
    verdict $? "SIGTERM to rank 0: the job ends within 10 s, no rank left"
    [ "$st" = 4 ] && [ "$(grep -c 'interrupted: nothing written' job.err)" -eq 1 ] && untouched
    verdict $? "SIGTERM to rank 0: exit 4 ($st), nothing written, said once: $(tail -c 300 job.err)"
else
    verdict 1 "the long render begins: $(tail -c 300 job.err)"
fi

# Ctrl-C to mpirun, with --partial: mpirun signals every rank, which stop
# and write the finished tiles before mpirun would kill them.
if [ "$full" -eq 1 ]; then
    echo old >out.png
    if launch --partial; then
        kill -INT "$job"
        ends_within 10
        verdict $? "SIGINT to mpirun: the job ends within 10 s, no rank left"
        [ "$st" != 0 ] && [ "$(grep -c 'interrupted: [0-9]* of 3969 tiles finished, written to out.png' job.err)" -eq 1 ] &&
            [ "$(head -c 4 out.png | tail -c 3)" = PNG ]
        verdict $? "SIGINT to mpirun with --partial: the finished tiles written, said once (exit $st): $(tail -c 300 job.err)"
    else
        verdict 1 "the long render begins: $(tail -c 300 job.err)"
    fi
fi

# A rank killed mid-render ends the whole job within seconds, non-zero,
# with no rank left and the output as it was (mpirun's own doing, kept
# here so that nothing glint-mpi does defeats it: no rank may hang).
if [ "$full" -eq 1 ]; then
    echo old >out.png
    if launch; then
        kill -9 "$(cat pid.1)"
        ends_within 10
        verdict $? "a rank killed: the job ends within 10 s, no rank left"
        [ "$st" != 0 ] && untouched
        verdict $? "a rank killed: exit $st, the output as it was"
    else
        verdict 1 "the long render begins: $(tail -c 300 job.err)"
    fi
fi

# A rank short of memory (its address space limited) fails the job
# cleanly, saying so: taking rank 0's files, loading the scene (rank 0
# then names it), or starting to render. The limits are tried from small to large until the job
# succeeds, so that whatever OpenMPI itself takes, some fail in the load.
# Not under ASan, whose shadow memory needs no such limit.
if [ "$full" -eq 1 ]; then
    awk 'BEGIN { n = 500
        for (i = 0; i <= n; i++) for (j = 0; j <= n; j++) print "v", i, j, 0
        for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
            a = i * (n + 1) + j + 1; print "f", a, a + 1, a + n + 2; print "f", a, a + n + 2, a + n + 1 } }' >grid.obj
    printf 'glint: 1
settings: { width: 64, height: 48 }
camera: { position: [250, 250, 600], look_at: [250, 250, 0], fov: 60 }
lights:
  - { type: point, position: [0, 0, 100] }
objects:
  - { type: mesh, file: grid.obj }
' >grid.yaml
    in_load=0 clean=0 tries=0
    for kib in $(seq 250000 50000 1500000); do
        echo old >out.png
        timeout "$limit" mpirun --oversubscribe -np 1 "$GLINT_MPI" grid.yaml -q -o out.png : \
            -np 1 sh -c "ulimit -v $kib; exec \"\$0\" grid.yaml -q -o out.png" "$GLINT_MPI" >/dev/null 2>mpi.err
        st=$?
        [ "$st" -ne 0 ] || break
        tries=$((tries + 1))
        if { [ "$st" -eq 5 ] || [ "$st" -eq 1 ]; } && grep -q 'out of memory\|^glint: rank 1: ' mpi.err && untouched; then
            clean=$((clean + 1))
        else
            echo "a rank limited to $kib KiB: exit $st: $(head -c 300 mpi.err)"
        fi
        ! grep -q 'rank 1: it could not load the scene rank 0 loaded' mpi.err || in_load=1
    done
    [ "$tries" -gt 0 ] && [ "$clean" -eq "$tries" ] && [ "$in_load" -eq 1 ]
    verdict $? "a rank short of memory: $clean of $tries failed runs clean (exit 1 or 5, said, output untouched), some in the load ($in_load)"
fi

# A rank running another build (here glint-mpi with another build ID, as
# another compiler or version would have) is refused before any work.
build_id=$(readelf -n "$GLINT_MPI" 2>/dev/null | sed -n 's/.*Build ID: *//p')
if [ -n "$build_id" ]; then
    cp "$GLINT_MPI" other-glint-mpi
    other_id=$(tr '0-9a-f' '1-9a-f0' <<<"$build_id")
    perl -0777 -pi -e 'BEGIN { $from = pack("H*", shift); $to = pack("H*", shift) } s/\Q$from\E/$to/' \
        "$build_id" "$other_id" other-glint-mpi
    readelf -n other-glint-mpi | grep -q "Build ID: $other_id"
    verdict $? "the copy of glint-mpi has another build ID"
    echo old >out.png
    timeout "$limit" mpirun --oversubscribe -np 1 "$GLINT_MPI" -w 64 -h 48 -q -o out.png : \
        -np 2 ./other-glint-mpi -w 64 -h 48 -q -o out.png >/dev/null 2>mpi.err
    st=$?
    [ "$st" -eq 2 ] && untouched &&
        [ "$(grep -c "rank 1 runs another build of glint (.* build $other_id) than rank 0 (.* build $build_id)" mpi.err)" -eq 1 ]
    verdict $? "another build on rank 1 is refused: exit 2 ($st), said once: $(head -c 400 mpi.err)"
else
    echo "note: glint-mpi has no build ID (readelf missing?): the mismatched build is not checked"
fi

finish
