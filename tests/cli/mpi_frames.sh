#!/usr/bin/env bash
# glint-mpi renders an animation's frames with glint's bytes: whole frames
# to each rank when there are at least as many frames as ranks (1, 2 and 3
# ranks, 1 and 2 threads), every rank on each frame by tiles when there
# are fewer (--frame N, --frames A-B); with motion blur; the other ranks
# load every frame from rank 0's files (they run where the scene's files
# are decoys); --resume renders only the frames missing or cut short; a
# sequence's flags are refused as glint refuses them; and a signal to any
# rank stops every rank, leaving only whole frames (with --partial, the
# frames cut short too, said). Skipped (exit 77) without glint-mpi or
# mpirun.
# Usage: mpi_frames.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"
source "$(dirname "$0")/lib/mpi.sh"

# A moving, colour-changing ball under a moving camera, with a texture and
# an include, so that the frames read files; motion blur over half a frame.
mkdir -p lead/maps decoy/maps empty
cat >lead/ball.yaml <<'EOF'
include: [looks.yaml]
settings: {width: 40, height: 30, samples: 4, sampler: sobol, frames: {start: 0, end: 6, fps: 10},
           shutter: {open: 0, close: 0.5, steps: 3}}
camera: {position: {keys: [[0, [0, 1, 6]], [0.6, [1, 1.5, 6]]], interpolate: smooth}, look_at: [0, 0.5, 0]}
lights: [{type: point, position: [4, 6, 4]}]
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor}
  - {type: sphere, radius: 0.5, material: m, transform: [{translate: {keys: [[0, [-2, 0.5, 0]], [0.6, [2, 0.5, 0]]]}}]}
EOF
looks() {
    printf 'textures: {moon: {type: image, file: maps/moon.jpg}}\nmaterials: {m: {color: {keys: [[0, %s], [0.6, [0, 0, 1]]]}}, floor: {texture: moon}}\n' \
        "$2" >"$1/looks.yaml"
}
looks lead "[1, 0, 0]"
cp "$here/assets/moon.jpg" lead/maps/moon.jpg
cp lead/ball.yaml decoy/ball.yaml
looks decoy "[0, 1, 0]"
"$GLINT" -w 40 -h 30 -q -o decoy/maps/moon.png && mv decoy/maps/moon.png decoy/maps/moon.jpg

# glint's frames: the reference.
(cd lead && "$GLINT" ball.yaml -q --threads 2 -o ../ref-##.png)
check "glint renders the seven frames" [ -f ref-00.png ] && [ -f ref-06.png ] && [ ! -e ref-07.png ]
(cd decoy && "$GLINT" ball.yaml -q --frame 3 -o ../decoy.png)
! cmp -s decoy.png ref-03.png
verdict $? "the decoys make another frame"

# same_frames WHAT FIRST LAST: frames FIRST to LAST in lead/ are glint's, and
# no other frame was written; they are then removed.
same_frames() {
    local what=$1 first=$2 last=$3 k ok=0 n
    for ((k = first; k <= last; k++)); do
        n=$(printf '%02d' "$k")
        cmp -s "ref-$n.png" "lead/out-$n.png" || ok=1
    done
    [ "$(ls lead | grep -c '^out-')" -eq $((last - first + 1)) ] || ok=1
    verdict "$ok" "$what: frames $first to $last are glint's bytes, and no other is written; $(tail -c 400 mpi.log)"
    rm -f lead/out-*
}

# lead_and DIR N ARGS...: rank 0 in lead/, N more ranks in DIR, ARGS for
# all; mpi.log has what they said, the progress line's rewrites as lines.
lead_and() {
    local dir=$1 n=$2
    shift 2
    if [ "$n" -eq 0 ]; then
        timeout "$limit" mpirun --oversubscribe -np 1 --wdir lead "$GLINT_MPI" ball.yaml "$@" >said 2>&1
    else
        timeout "$limit" mpirun --oversubscribe -np 1 --wdir lead "$GLINT_MPI" ball.yaml "$@" : \
            -np "$n" --wdir "$dir" "$GLINT_MPI" ball.yaml "$@" >said 2>&1
    fi
    tr '\r' '\n' <said | sed 's/\x1b\[K//g' >mpi.log
}

# Whole frames to each rank: more frames than ranks.
lead_and empty 0 --threads 2 -o out-##.png
same_frames "1 rank x 2 threads" 0 6
lead_and empty 1 --threads 1 -o out-##.png
same_frames "2 ranks x 1 thread, rank 1 without the files" 0 6
grep -qE 'frames: rank 0 [1-9][0-9]* \(busy [0-9]+%\), rank 1 [1-9]' mpi.log
verdict $? "both ranks rendered frames: $(tail -c 300 mpi.log)"
grep -qE '^glint-mpi: frame 4 \([1-7] of 7\), rank [01]: 40x30: ' mpi.log
verdict $? "each frame is said as it is written: $(head -c 300 mpi.log)"
if [ "$full" -eq 1 ]; then
    lead_and decoy 2 --threads 2 -o out-##.png
    same_frames "3 ranks x 2 threads, ranks 1 and 2 among decoys" 0 6
    lead_and empty 2 --threads 1 --frames 2-5 -o out-##.png
    same_frames "--frames 2-5 on 3 ranks" 2 5
fi

# Every rank on each frame, by tiles: fewer frames than ranks.
lead_and decoy 1 --threads 1 --frame 3 -o out-##.png
same_frames "--frame 3 on 2 ranks, rank 1 among decoys" 3 3
grep -qE '^glint-mpi: 40x30, 4 spp, 2 ranks x 1 thread: .* busy: rank 0 [0-9]+% \([0-9]+ tiles?\), rank 1' mpi.log
verdict $? "frame 3 was rendered by tiles: $(tail -c 300 mpi.log)"
lead_and empty 3 --threads 1 --frames 4-6 -o out-##.png
same_frames "--frames 4-6 on 4 ranks" 4 6

# --resume: frame 2 missing, frame 4 cut short, frame 1 another whole image
# (left alone: it is whole); only 2 and 4 are rendered.
for k in 00 03 05 06; do cp "ref-$k.png" "lead/out-$k.png"; done
cp ref-00.png lead/out-01.png
head -c 200 ref-04.png >lead/out-04.png
lead_and empty 1 --threads 1 --resume -o out-##.png
grep -q '^glint-mpi: frame 1 is done: out-01.png$' mpi.log && ! grep -q 'frame 2 is done' mpi.log &&
    [ "$(grep -c '^glint-mpi: frame [0-9] (' mpi.log)" -eq 2 ]
verdict $? "--resume renders frames 2 and 4 alone: $(head -c 500 mpi.log)"
cmp -s lead/out-01.png ref-00.png && cmp -s lead/out-02.png ref-02.png && cmp -s lead/out-04.png ref-04.png
verdict $? "--resume leaves the whole frame, and writes glint's bytes for the others"
rm -f lead/out-*

# A sequence's flags are refused as glint refuses them: glint's message,
# glint's code, nothing written.
refused() {
    local what=$1
    shift
    (cd lead && "$GLINT" "$@" 2>../glint.err >/dev/null)
    local st=$?
    (cd lead && mpi 2 "$@" 2>../mpi.err >/dev/null)
    local mst=$?
    [ "$st" -ne 0 ] && [ "$mst" -eq "$st" ] && [ "$(grep -cxF -- "$(head -n 1 glint.err)" mpi.err)" -eq 1 ] &&
        [ -z "$(ls lead | grep '^out')" ]
    verdict $? "$what: exit $st from glint, $mst from glint-mpi, glint's message once: $(head -c 300 mpi.err)"
}
refused "an output name without #" ball.yaml -q -o out.png
refused "frames to standard output" ball.yaml -q -o -
(cd lead && mpi 2 - -q --frames 1-2 -o out-#.png <ball.yaml 2>../mpi.err >/dev/null)
[ $? -eq 2 ] && grep -qxF "glint: frames 1 to 2 need the scene in a file: standard input is read once" mpi.err
verdict $? "frames from standard input are refused: $(head -c 300 mpi.err)"

# --print-scene prints a frame's still as glint does.
(cd lead && "$GLINT" ball.yaml --print-scene --frame 3 >../glint.yaml && mpi 2 ball.yaml --print-scene --frame 3 >../mpi.yaml)
cmp -s glint.yaml mpi.yaml && grep -q 'seed' mpi.yaml
verdict $? "--print-scene --frame 3 prints glint's still of frame 3"

# A signal to one rank stops every rank: exit 4, every frame file whole
# (glint's bytes), none cut short, no temporary file; with --partial the
# frames being rendered are written as far as they got, and said.
long_run() {
    rm -f lead/long-* pid.* job.err
    mpirun --oversubscribe -np 2 --wdir lead sh -c 'echo $$ >"../pid.$OMPI_COMM_WORLD_RANK"; exec "$@"' sh \
        "$GLINT_MPI" ball.yaml -w 200 -h 150 --spp 64 --threads 1 --frames 0-40 -o long-##.png "$@" >/dev/null 2>job.err &
    job=$!
    for _ in $(seq $((10 * limit))); do
        grep -q 'glint-mpi: frame' job.err 2>/dev/null && return 0
        kill -0 "$job" 2>/dev/null || return 1
        sleep 0.1
    done
    return 1
}
for partial in "" --partial; do
    if long_run $partial; then
        kill -TERM "$(cat pid.1)"
        wait "$job"
        st=$?
        whole=0 cut=0
        for f in lead/long-*; do
            if grep -q "written to ${f#lead/} (the rest black)" job.err; then
                cut=$((cut + 1))
            else
                k=$(basename "$f" .png)
                (cd lead && "$GLINT" ball.yaml -q -w 200 -h 150 --spp 64 --frame "${k#long-}" -o ../check.png) &&
                    cmp -s check.png "$f" || whole=1
            fi
        done
        ok=0
        [ "$st" -eq 4 ] && [ "$whole" -eq 0 ] && [ -z "$(ls -A lead | grep '^\.')" ] || ok=1
        # Without --partial no frame is cut short. With it, a frame in
        # progress when the signal lands is written cut short, but the
        # signal may land between frames, so none need be.
        if [ -z "$partial" ]; then
            [ "$cut" -eq 0 ] && grep -q 'interrupted: [0-9]* of 41 frames written whole' job.err || ok=1
        fi
        verdict "$ok" "SIGTERM to rank 1 ${partial:-without --partial}: exit 4 ($st), whole frames glint's, $cut cut short, no temporary file: $(tail -c 400 job.err)"
    else
        verdict 1 "the long sequence begins: $(tail -c 300 job.err)"
    fi
    [ "$full" -eq 1 ] || break
done

finish
