#!/usr/bin/env bash
# Frame sequences: a scene's settings.frames, --frames A-B and --frame N
# render each frame to the output's name with its #s replaced by the
# zero-padded number; frame k alone is byte for byte frame k of the whole
# sequence, with 1 and 2 threads; a sequence needs #s in the output's name
# (and a scene file, not standard input); --resume renders only the frames
# whose files are missing or cut short, an interrupted sequence leaves no
# half-written frame under its final name, and a scene without keys makes
# the same image at every frame, but for its noise, which each frame has
# its own of (the random seed moved by the frame).
# Usage: frames.sh PATH/TO/glint
. "$(dirname "$0")/lib/harness.sh"

# expect CODE FIRST -- ARGS...: glint ARGS exits with CODE and FIRST as the
# first line of stderr.
expect() {
    local code=$1 first=$2 status actual
    shift 3
    "$GLINT" "$@" 2>err >/dev/null
    status=$?
    actual=$(head -n 1 err)
    verdict "$([ "$status" -eq "$code" ] && [ "$actual" = "$first" ]; echo $?)" \
        "glint $*: expected exit $code: $first; got exit $status: $actual"
}

cat >ball.yaml <<'EOF'
settings: {width: 48, height: 32, frames: {start: 0, end: 5, fps: 10}}
camera: {position: {keys: [[0, [0, 1, 6]], [0.5, [1, 1.5, 6]]], interpolate: smooth}, look_at: [0, 0.5, 0]}
materials: {m: {color: {keys: [[0, [1, 0, 0]], [0.5, [0, 0, 1]]]}}, floor: {}}
lights: [{type: point, position: [4, 6, 4]}]
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor}
  - {type: sphere, radius: 0.5, material: m, transform: [{translate: {keys: [[0, [-2, 0.5, 0]], [0.5, [2, 0.5, 0]]]}}]}
EOF

# differ A B: the files are not the same.
differ() { ! cmp -s "$1" "$2"; }

# The scene's frames, each to its own file, each different.
expect 0 "" -- ball.yaml -q -o seq-###.png
check "six frames written, numbered from 000" [ -f seq-000.png ] && [ -f seq-005.png ] && [ ! -e seq-006.png ]
check "each frame differs from the last" differ seq-002.png seq-003.png
"$GLINT" ball.yaml -o one-#.png --frames 2-3 2>summary >/dev/null
check "the summary names each frame" grep -q "^glint: frame 3 (2 of 2), 48x32" summary

# Frame k alone is frame k of the sequence, for any thread count.
for k in 0 3 5; do
    for threads in 1 2; do
        "$GLINT" ball.yaml -q --frame "$k" --threads "$threads" -o "alone-$threads.png"
        check "frame $k alone with $threads threads is frame $k of the sequence" cmp -s "alone-$threads.png" "seq-00$k.png"
    done
done
expect 0 "" -- ball.yaml -q --frames 4-5 --threads 1 -o part-####.png
check "frames 4-5 alone are the sequence's" cmp -s part-0005.png seq-005.png
check "and only they are written" [ ! -e part-0003.png ]
expect 0 "" -- ball.yaml -q --frame 12 -o past-##.png
check "a frame past the keys holds their last values" cmp -s past-12.png seq-005.png
check "more digits than #s are written whole" "$GLINT" ball.yaml -q --frame 123 -o wide-#.png
check "frame 123's file" [ -f wide-123.png ]

# A sequence needs a name with #s, a file, and a scene that is a file.
expect 2 "glint: frames 0 to 5 need an output name with #s for the frame's number, such as -o frame-####.png; got 'plain.png'" -- ball.yaml -o plain.png
expect 2 "glint: frames 0 to 5 go to files, not standard output: give -o NAME-####.png" -- ball.yaml -o -
expect 2 "glint: frames 1 to 2 need the scene in a file: standard input is read once" -- - --frames 1-2 -o in-#.png <ball.yaml
expect 2 "glint: --frames needs FIRST-LAST, frames from 0 to 10000000 with LAST at least FIRST, got '5-2'" -- ball.yaml --frames 5-2
expect 2 "glint: --frames needs FIRST-LAST, frames from 0 to 10000000 with LAST at least FIRST, got '3'" -- ball.yaml --frames 3
expect 2 "glint: --frame needs a whole number from 0 to 10000000, got '-1'" -- ball.yaml --frame -1
expect 2 "glint: --display shows one frame: give --frame N" -- ball.yaml --display --frames 0-1
check "no refused sequence wrote a frame" [ ! -e plain.png ] && [ ! -e in-1.png ]
expect 0 "" -- ball.yaml -q --frame 2 -o plain.png
check "one frame takes a plain name" cmp -s plain.png seq-002.png

# --resume: the frames there and whole are skipped, the rest rendered.
mkdir resume
cp seq-002.png resume/
cp seq-001.png resume/seq-000.png # whole, if not frame 0: kept as it is
head -c 100 seq-004.png >resume/seq-004.png
printf 'P6\n48 32\n255\n' >resume/seq-005.png
"$GLINT" ball.yaml --resume -o resume/seq-###.png 2>resumed >/dev/null
check "--resume says which frames it skipped" grep -q "^glint: frame 2 is done: resume/seq-002.png" resumed
check "--resume keeps a whole frame as it was" cmp -s resume/seq-000.png seq-001.png
check "--resume renders a frame cut short again" cmp -s resume/seq-004.png seq-004.png
check "--resume renders a PPM header alone again" cmp -s resume/seq-005.png seq-005.png
check "--resume renders a missing frame" cmp -s resume/seq-003.png seq-003.png
check "--resume renders only the frames it must" [ "$(grep -c ' is done: ' resumed)" -eq 2 ]
"$GLINT" ball.yaml --resume --frame 2 -q -o - >stdout.png
check "--resume writes one frame to standard output, which it cannot find done" cmp -s stdout.png seq-002.png

# An interrupted sequence: the frames finished are whole, the one it
# stopped in is not there at all, under its name or a temporary one.
cat >slow.yaml <<'EOF'
settings: {width: 160, height: 120, samples: 16, sampler: sobol, frames: {start: 0, end: 500}}
materials: {m: {color: {keys: [[0, [1, 0, 0]], [1, [0, 1, 0]]]}}}
lights: [{type: point, position: [0, 5, 5]}]
objects: [{type: sphere, radius: 1, material: m}]
EOF
mkdir stop
"$GLINT" slow.yaml --threads 1 -q -o stop/f-#.png 2>/dev/null &
pid=$!
# Stopped once frame 0 is written (in a minute at most: a sanitizer build
# is slow), in the frames after it.
for _ in $(seq 600); do [ -f stop/f-0.png ] && break; sleep 0.1; done
kill -INT "$pid"
wait "$pid"
check "an interrupted sequence exits 4" [ $? -eq 4 ]
check "its finished frame is whole" "$GLINT" slow.yaml --frame 0 --threads 2 -q -o whole.png
check "and the same as rendered alone" cmp -s whole.png stop/f-0.png
check "no frame is half written" [ "$(ls stop | grep -vc '^f-[0-9]*.png$')" -eq 0 ]
check "the sequence stopped before its end" [ ! -e stop/f-500.png ]
for f in stop/f-*.png; do
    check "$f is whole" python3 -c "import sys; d=open(sys.argv[1],'rb').read(); sys.exit(d[-12:] != bytes.fromhex('0000000049454e44ae426082'))" "$f"
done

# Without keys every frame is the same image.
cat >still.yaml <<'EOF'
settings: {width: 32, height: 24, frames: {start: 0, end: 2}}
materials: {m: {}}
lights: [{type: point, position: [0, 5, 5]}]
objects: [{type: sphere, radius: 1, material: m}]
EOF
expect 0 "" -- still.yaml -q -o still-#.png
check "a scene without keys is the same at every frame" cmp -s still-0.png still-2.png

# Random patterns move with the frame (noise changes as film grain does),
# frame 0 keeping a still's; --print-scene's still of a frame carries the
# frame's seed, and renders its bytes.
cat >grain.yaml <<'EOF2'
settings: {width: 32, height: 24, samples: 3, sampler: sobol, frames: {start: 0, end: 1}}
camera: {type: thin_lens, position: [0, 0, 4], look_at: [0, 0, 0], aperture: 0.3, focus_distance: 2}
materials: {m: {}}
lights: [{type: sphere, position: [0, 3, 3], radius: 1, samples: 2}]
objects: [{type: sphere, radius: 1, material: m}]
EOF2
expect 0 "" -- grain.yaml -q -o grain-#.png
check "each frame's noise is its own" differ grain-0.png grain-1.png
sed 's/, frames: {start: 0, end: 1}//' grain.yaml >grain-still.yaml
expect 0 "" -- grain-still.yaml -q -o grain-still.png
check "frame 0's noise is a still's" cmp -s grain-0.png grain-still.png
"$GLINT" grain.yaml --print-scene --frame 1 >grain-1.yaml
expect 0 "" -- grain-1.yaml -q -o grain-printed.png
check "the printed still of frame 1 renders frame 1" cmp -s grain-printed.png grain-1.png
"$GLINT" grain.yaml --print-scene >grain-first.yaml 2>err
check "--print-scene of a sequence prints its first frame, with no output named" \
    cmp -s grain-first.yaml <("$GLINT" grain.yaml --print-scene --frame 0)

finish
