#!/usr/bin/env bash
# Interrupting a render: SIGINT, SIGTERM, SIGHUP or SIGQUIT stops glint
# within a second with exit code 4, writes nothing and leaves the file
# already at the output path as it was, whether it comes while a model
# loads, while its BVH builds or while the image renders, however deep its
# trees of rays or slow its rays; with --partial it writes the finished
# tiles as a valid PNG of the whole size, and still exits 4; the same to
# standard output.
# Usage: interrupt.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"
fail() {
    echo "FAIL: $*"
    failed=$((failed + 1))
}

# signal_after SIGNAL SECONDS ARGS...: runs glint with ARGS, its stderr in
# err.txt, sends it SIGNAL after SECONDS, and sets status, stop_ms (from the
# signal to the exit) and err (its stderr).
signal_after() {
    local sig=$1 delay=$2
    shift 2
    "$GLINT" "$@" 2>err.txt &
    local pid=$!
    sleep "$delay"
    local t0
    t0=$(date +%s%N)
    kill -"$sig" "$pid"
    wait "$pid"
    status=$?
    stop_ms=$((($(date +%s%N) - t0) / 1000000))
    err=$(cat err.txt)
}

# interrupt SIGNAL [FLAGS...]: starts a render of the seed room far too long
# to finish (2000 x 2000 pixels, 64 samples each: a minute or more), and
# sends SIGNAL once it is under way (signal_after).
interrupt() {
    local sig=$1
    shift
    printf 'an earlier image\n' >out.png
    signal_after "$sig" 1.5 -w 2000 -h 2000 --spp 64 --threads 2 -o out.png "$@"
}

# Nothing written: exit 4, the message, the old file intact, no other file;
# the same for a closed terminal (SIGHUP) and Ctrl-\ (SIGQUIT, no core).
for sig in INT TERM HUP QUIT; do
    before=$failed
    interrupt "$sig"
    [ "$status" -eq 4 ] || fail "SIG$sig: exit $status, expected 4"
    [ "$stop_ms" -lt 1000 ] || fail "SIG$sig: took $stop_ms ms to stop"
    [ "$err" = "glint: interrupted: nothing written" ] || fail "SIG$sig: stderr '$err'"
    [ "$(cat out.png)" = "an earlier image" ] || fail "SIG$sig: the earlier file was changed"
    [ "$(ls -A | sort | tr '\n' ' ')" = "err.txt out.png " ] || fail "SIG$sig: left $(ls -A)"
    [ "$failed" -eq "$before" ] && passed=$((passed + 1))
done

# While a large model loads, or while its BVH builds, a signal ends glint
# the same way: exit 4, the same message, nothing written, within a second.
# (Loading takes about 0.9 s here, the build 0.25 s; after half a second,
# glint is past its start-up, whose signals would end it by default, even
# on a slow or loaded machine.)
awk 'BEGIN {
    n = 600
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++)
            printf "v %d %d %d\n", i, (i * j) % 7, j
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; d = c + 1
            printf "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d
        }
}' >big.obj
for delay in 0.5 1.0; do
    before=$failed
    printf 'an earlier image\n' >out.png
    signal_after INT "$delay" big.obj -w 2000 -h 2000 --spp 16 -o out.png
    [ "$status" -eq 4 ] || fail "model, SIGINT after $delay s: exit $status, expected 4"
    [ "$stop_ms" -lt 1000 ] || fail "model, SIGINT after $delay s: took $stop_ms ms to stop"
    [ "$(cat err.txt)" = "glint: interrupted: nothing written" ] || fail "model, SIGINT after $delay s: stderr '$(cat err.txt)'"
    [ "$(cat out.png)" = "an earlier image" ] || fail "model, SIGINT after $delay s: the earlier file was changed"
    [ "$failed" -eq "$before" ] && passed=$((passed + 1))
done
rm -f big.obj

# --partial: the finished tiles in a PNG of the whole size, which glint
# itself decodes (as a texture). (Its time to stop includes writing the
# 2000 x 2000 image, so it is not held to the second.) SIGHUP, as when the
# terminal closes, keeps them as SIGINT does.
for sig in INT HUP; do
    before=$failed
    interrupt "$sig" --partial
    [ "$status" -eq 4 ] || fail "SIG$sig --partial: exit $status, expected 4"
    if [[ ! "$err" =~ ^glint:\ interrupted:\ ([0-9]+)\ of\ 3969\ tiles\ finished,\ written\ to\ out\.png\ \(the\ rest\ black\)$ ]]; then
        fail "SIG$sig --partial: stderr '$err'"
    elif [ "${BASH_REMATCH[1]}" -lt 1 ] || [ "${BASH_REMATCH[1]}" -ge 3969 ]; then
        fail "SIG$sig --partial: ${BASH_REMATCH[1]} tiles finished"
    fi
    # PNG signature, then IHDR: width and height 2000 (0x7d0).
    head=$(od -A n -t x1 -N 24 out.png | tr -d ' \n')
    [ "$head" = "89504e470d0a1a0a0000000d49484452000007d0000007d0" ] || fail "SIG$sig --partial: not a 2000x2000 PNG: $head"
    "$GLINT" --texture moon=out.png -w 4 -h 4 --spp 1 -q -o check.ppm || fail "SIG$sig --partial: glint cannot read the image back"
    [ "$(ls -A | sort | tr '\n' ' ')" = "check.ppm err.txt out.png " ] || fail "SIG$sig --partial: left $(ls -A)"
    [ "$failed" -eq "$before" ] && passed=$((passed + 1))
    rm -f check.ppm
done

# To standard output (-o -) the same: nothing without --partial, and with
# it the finished tiles as a whole image (a 2000 x 2000 PPM: its header and
# 12,000,000 bytes), exit 4 either way.
for partial in "" --partial; do
    before=$failed
    signal_after INT 1.5 -w 2000 -h 2000 --spp 64 --threads 2 -o - --format ppm $partial >out.ppm
    [ "$status" -eq 4 ] || fail "-o - $partial: exit $status, expected 4"
    if [ -z "$partial" ]; then
        [ "$err" = "glint: interrupted: nothing written" ] || fail "-o -: stderr '$err'"
        [ ! -s out.ppm ] || fail "-o -: $(stat -c %s out.ppm) bytes written"
    else
        [[ "$err" =~ ^glint:\ interrupted:\ [0-9]+\ of\ 3969\ tiles\ finished,\ written\ to\ \<stdout\>\ \(the\ rest\ black\)$ ]] ||
            fail "-o - --partial: stderr '$err'"
        head -c 17 out.ppm | cmp -s - <(printf 'P6\n2000 2000\n255\n') && [ "$(stat -c %s out.ppm)" -eq 12000017 ] ||
            fail "-o - --partial: not a whole 2000 x 2000 PPM"
    fi
    [ "$failed" -eq "$before" ] && passed=$((passed + 1))
done
rm -f out.ppm

# Runaway work stops within a second too: trees of rays that split at every
# hit for 64 levels (two nested spheres that mirror all and pass half; a
# Fresnel glass ball inside another), and rays that each cross 300,000
# coincident triangles (2 ms a ray: a row of blocks at 64 samples took 20 s
# when the flag was read only between rows). Each is far from finished
# after 1.5 s.
runaway() {
    cat <<EOF
settings: { width: 400, height: 300, samples: 16, depth: 64 }
camera: { position: [0, 0, 5], look_at: [0, 0, 0], fov: 40 }
materials:
  outer: $1
  inner: $1
lights:
  - { type: point, position: [3, 3, 3] }
objects:
  - { type: sphere, center: [0, 0, 0], radius: 1.5, material: outer }
  - { type: sphere, center: [0, 0, 0], radius: 1, material: inner }
EOF
}
runaway '{ color: [1, 1, 1], transparency: 0.5, reflectivity: 1 }' >nested.yaml
runaway '{ color: [0, 0, 0], refraction: 1, ior: 1.5, tint: 0, fresnel: true }' >glass.yaml
for scene in nested glass; do
    before=$failed
    signal_after INT 1.5 "$scene.yaml" --threads 2 -o runaway.png
    [ "$status" -eq 4 ] || fail "$scene: exit $status, expected 4"
    [ "$stop_ms" -lt 1000 ] || fail "$scene: took $stop_ms ms to stop"
    [ "$err" = "glint: interrupted: nothing written" ] || fail "$scene: stderr '$err'"
    [ ! -e runaway.png ] || fail "$scene: wrote runaway.png"
    [ "$failed" -eq "$before" ] && passed=$((passed + 1))
done
# One 32 x 32 tile, on one thread: --partial's message says the signal came
# while it rendered (past the model's loading, 0.6 s here), and none was
# finished.
before=$failed
awk 'BEGIN { print "v -1 -1 0\nv 1 -1 0\nv 0 1 0"; for (i = 0; i < 300000; i++) print "f 1 2 3" }' >coincident.obj
signal_after INT 3 coincident.obj -w 32 -h 32 --spp 64 --partial -o out.png
[ "$status" -eq 4 ] || fail "coincident: exit $status, expected 4"
[ "$stop_ms" -lt 1000 ] || fail "coincident: took $stop_ms ms to stop"
[ "$err" = "glint: interrupted: 0 of 1 tiles finished, written to out.png (the rest black)" ] ||
    fail "coincident: stderr '$err'"
[ "$failed" -eq "$before" ] && passed=$((passed + 1))

finish
