#!/usr/bin/env bash
# The --display window, on a virtual X server (Xvfb) of its own: it shows
# exactly the image written (and again after being covered), a dim
# placeholder where tiles are still to come, its percentage and then its
# time in the title; it fits a large image to the screen keeping the
# aspect; s saves the image; q, Esc and the close button close it; closing
# it early interrupts the render (exit 4, the old file kept, or --partial's
# tiles written); without a display --display is refused before anything
# is rendered, while glint without it needs none; glint-mpi shows the
# window on rank 0.
# Usage: display.sh PATH/TO/glint, with GLINT_X11_CLOSE the path of
# tests/x11_close. Needs Debian's xvfb, xdotool and imagemagick.
source "$(dirname "$0")/lib/harness.sh"
scale=${GLINT_TIME_SCALE:-1}
for tool in Xvfb xdotool import compare identify; do
    command -v "$tool" >/dev/null || { echo "FAIL: $tool is missing (Debian: xvfb, xdotool, imagemagick)"; exit 1; }
done

# Under ASan, libdbus's allocations for the life of the process (started
# by SDL) are not leaks (tests/cli/display.supp).
here=$(cd "$(dirname "$0")/../.." && pwd)
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$here/tests/cli/display.supp:print_suppressions=0"

# A screen of 1024 x 768 at 24 bits (at 16 the screenshots would not be
# the image's bytes), on the first free display number.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>display.txt 2>xvfb.log &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; rm -rf "$work"' EXIT
for _ in $(seq 100); do
    [ -s display.txt ] && break
    sleep 0.1
done
[ -s display.txt ] || { echo "FAIL: Xvfb did not start: $(cat xvfb.log)"; exit 1; }
export DISPLAY=":$(head -n 1 display.txt)"
unset WAYLAND_DISPLAY
# No session bus, as on a bare X server: libdbus, asked for one, would fork
# glint and run dbus-launch (the fork hung under ASan). A dbus-launch first
# on PATH that leaves a mark tells whether glint let it.
unset DBUS_SESSION_BUS_ADDRESS
mkdir bin
printf '#!/bin/sh\ntouch "%s/dbus-launch-ran"\nexit 1\n' "$PWD" >bin/dbus-launch
chmod +x bin/dbus-launch
export PATH="$PWD/bin:$PATH"

# start PROGRAM ARGS...: once no earlier glint window is left, runs
# PROGRAM ARGS in the background, its stderr in err.txt, and sets pid and
# wid (its window, once it shows; empty if it never does within a minute,
# as wait_title allows, or it ends first). Its wait was 10 s until a CI run
# on a loaded machine: a window not shown by then failed the next check at
# once, and the signal meant for a finished render interrupted it.
start() {
    local i=0
    # The last run's window may outlive its process a moment in the
    # server: it must not be taken for this one's.
    while [ -n "$(xdotool search --name '^glint - ' 2>/dev/null)" ] && ((i++ < 100 * scale)); do
        sleep 0.1
    done
    local attempt
    for attempt in 1 2 3; do
        "$@" 2>err.txt &
        pid=$!
        i=0
        wid=
        while [ -z "$wid" ] && ((i++ < 600 * scale)) && kill -0 "$pid" 2>/dev/null; do
            wid=$(xdotool search --onlyvisible --name '^glint - ' 2>/dev/null | head -n 1)
            [ -n "$wid" ] || sleep 0.1
        done
        # A loaded machine has seen SDL fail to reach this Xvfb, which then
        # still answered xdotool: glint says so (exit 2), and the run is
        # tried again. A server that died is reported as such.
        [ -z "$wid" ] && ! kill -0 "$pid" 2>/dev/null && grep -q 'the window could not open' err.txt || return 0
        wait "$pid"
        kill -0 "$xvfb" 2>/dev/null || { echo "FAIL: Xvfb died: $(cat xvfb.log)"; return 0; }
        echo "note: attempt $attempt: the window could not open on a live Xvfb; trying again" >&2
        sleep 1
    done
}

# shot FILE: a screenshot of the window (none when it never showed: import
# would wait for a click on some window).
shot() {
    rm -f "$1"
    [ -n "$wid" ] && timeout $((20 * scale)) import -window "$wid" "$1"
}

# title: the window's title now.
title() {
    xdotool getwindowname "$wid" 2>/dev/null
}

# wait_title PATTERN: waits (up to a minute) until the title matches the
# shell pattern PATTERN.
wait_title() {
    local i
    [ -n "$wid" ] || return 1
    for ((i = 0; i < 600 * scale; i++)); do
        # shellcheck disable=SC2053
        [[ $(title) == $1 ]] && return 0
        sleep 0.1
    done
    return 1
}

# ended: waits for the program (at most 10 s, else kills it) and sets status.
ended() {
    local i
    for ((i = 0; i < 100 * scale; i++)); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    kill -0 "$pid" 2>/dev/null && kill -9 "$pid"
    wait "$pid"
    status=$?
}

# key KEY: the user presses KEY in the window. (xdotool may complain when
# the window goes away with the key: its status is not the test's.)
key() {
    [ -z "$wid" ] || xdotool key --window "$wid" "$1" 2>/dev/null
}

# same_pixels A B: images A and B have the same size and pixels.
same_pixels() {
    [ "$(identify -format '%wx%h' "$1")" = "$(identify -format '%wx%h' "$2")" ] &&
        [ "$(compare -metric AE "$1" "$2" null: 2>&1)" = "0" ]
}

# No display: refused before any rendering, with exit 2 and nothing
# written; glint without --display renders without one.
env -u DISPLAY -u WAYLAND_DISPLAY "$GLINT" --display -w 64 -h 48 -o out.png 2>err.txt
status=$?
check "no display: exit $status, expected 2" test "$status" -eq 2
check "no display: the message, got '$(cat err.txt)'" \
    test "$(cat err.txt)" = "glint: --display needs a screen, and neither DISPLAY nor WAYLAND_DISPLAY is set"
check "no display: nothing written" test ! -e out.png
env -u DISPLAY -u WAYLAND_DISPLAY "$GLINT" -w 64 -h 48 -q -o plain.png
check "glint without --display needs no display" test -s plain.png
# A display that is not there: the window cannot open.
DISPLAY=:4095 "$GLINT" --display -w 64 -h 48 -o out.png 2>err.txt
status=$?
check "a display that is not there: exit $status, expected 2" test "$status" -eq 2
check "a display that is not there: the message, got '$(cat err.txt)'" \
    grep -qx "glint: --display: the window could not open: .*" err.txt
check "a display that is not there: nothing written" test ! -e out.png
"$GLINT" --display --check /dev/null 2>err.txt
status=$?
check "--display --check: exit $status and '$(cat err.txt)'" \
    test "$status" -eq 2 -a "$(cat err.txt)" = "glint: --display shows a render, and --check renders nothing"

# The finished image: the window shows exactly the pixels written, which
# are the bytes glint writes without a window; its title gives the time;
# it shows them again after being hidden and shown (no one keeps a covered
# window's pixels: glint draws them again); q closes it, and glint exits 0.
"$GLINT" -w 320 -h 240 --threads 2 -q -o plain.png
start "$GLINT" --display -w 320 -h 240 --threads 2 -o out.png
check "the window shows" test -n "$wid"
check "the title gives the time when done, got '$(title)'" wait_title "glint - seed room - done in [0-9]*.[0-9][0-9][0-9] s"
check "the window is the image's size, got $(xdotool getwindowgeometry "$wid" | sed -n 's/.*Geometry: //p')" \
    test "$(xdotool getwindowgeometry "$wid" | sed -n 's/.*Geometry: //p')" = "320x240"
shot shot.png
check "the window shows the image written" same_pixels shot.png out.png
check "the image written is glint's without a window" cmp -s out.png plain.png
xdotool windowunmap --sync "$wid"
xdotool windowmap --sync "$wid"
sleep 0.3
shot shot.png
check "hidden and shown again, the window still shows the image" same_pixels shot.png out.png
key q
ended
check "q: exit $status, expected 0" test "$status" -eq 0
check "the summary is on stderr" grep -q "^glint: 320x240, 4 spp, 2 threads: .* -> out.png$" err.txt

# s saves the image shown: with the image on standard output, to glint.png.
start sh -c 'exec "$0" --display -w 200 -h 150 --threads 2 -q -o - >stdout.png' "$GLINT"
wait_title "glint - seed room - done in * s"
key s
for ((i = 0; i < 50 * scale; i++)); do
    grep -q "saved" err.txt && break
    sleep 0.1
done
check "s: said, got '$(cat err.txt)'" test "$(cat err.txt)" = "glint: s: saved the image (100% rendered) to glint.png"
check "s: saves the bytes written" cmp -s glint.png stdout.png
key Escape
ended
check "Esc after the render: exit $status, expected 0" test "$status" -eq 0

# A large image: the window fits the screen (1024 x 768) keeping the
# aspect, and shows the image scaled (compared with ImageMagick's scaling:
# a small difference of filters, nothing like another image).
start "$GLINT" --display -w 2048 -h 1024 --spp 1 --threads 2 -q -o big.png
wait_title "glint - seed room - done in * s"
geometry=$(xdotool getwindowgeometry "$wid" | sed -n 's/.*Geometry: //p')
check "a 2048x1024 image fits in a 1024x512 window, got $geometry" test "$geometry" = "1024x512"
shot shot.png
convert big.png -resize 1024x512 small.png
rmse=$(compare -metric RMSE shot.png small.png null: 2>&1 | sed 's/.*(\(.*\))/\1/')
check "the scaled window shows the image: RMSE $rmse, expected under 0.03" awk -v e="$rmse" 'BEGIN { exit !(e < 0.03) }'
"$GLINT_X11_CLOSE" "$wid"
ended
check "the close button after the render: exit $status, expected 0" test "$status" -eq 0

# During a long render: the title gives the share done, unfinished tiles
# show the placeholder's dim greys; Esc interrupts: exit 4, nothing
# written, the old file kept, within a second.
printf 'an earlier image\n' >out.png
start "$GLINT" --display -w 700 -h 700 --spp 256 --threads 2 -o out.png
check "the title gives the share done, got '$(title)'" wait_title "glint - seed room - [0-9]*%"
shot shot.png
corner=$(convert shot.png -crop 1x1+699+699 -format '%[fx:int(255*r)] %[fx:int(255*g)] %[fx:int(255*b)]' info:)
check "a tile still to come shows the placeholder, got $corner" \
    awk -v c="$corner" 'BEGIN { split(c, v, " "); exit !(v[1] == v[2] && v[2] == v[3] && (v[1] == 28 || v[1] == 44)) }'
t0=$(date +%s%N)
key Escape
ended
stop_ms=$((($(date +%s%N) - t0) / 1000000))
check "Esc while rendering: exit $status, expected 4" test "$status" -eq 4
check "Esc while rendering: stopped in $stop_ms ms" test "$stop_ms" -lt $((1000 * scale))
check "Esc while rendering: the message, got '$(cat err.txt)'" grep -qx "glint: interrupted: nothing written" err.txt
check "Esc while rendering: the old file kept" test "$(cat out.png)" = "an earlier image"

# The close button while rendering, with --partial: the finished tiles
# are written, the whole size, and the exit is still 4.
start "$GLINT" --display -w 700 -h 700 --spp 256 --threads 2 --partial -q -o out.png
wait_title "glint - seed room - [0-9]*%"
"$GLINT_X11_CLOSE" "$wid"
ended
check "closed while rendering, --partial: exit $status, expected 4" test "$status" -eq 4
check "closed while rendering, --partial: the message, got '$(cat err.txt)'" \
    grep -qx "glint: interrupted: [0-9]* of 484 tiles finished, written to out.png (the rest black)" err.txt
check "closed while rendering, --partial: a whole image written" test "$(identify -format '%wx%h' out.png)" = "700x700"

# A signal once the image is written closes the window: the run succeeded.
# Tried twice: on a loaded CI machine a window once showed and then had
# not finished its 64 x 48 render a minute later (cause unknown; the run
# is noted in the log), and the signal then interrupted it.
for attempt in 1 2; do
    start "$GLINT" --display -w 64 -h 48 -q -o out.png
    wait_title "glint - seed room - done in * s" && break
    [ "$attempt" -eq 2 ] && break
    echo "note: attempt $attempt: no finished render shown within a minute (title '$(title)'); trying again" >&2
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
done
check "SIGINT with the image written: the window shows, done" wait_title "glint - seed room - done in * s"
kill -INT "$pid"
ended
check "SIGINT with the image written: exit $status, expected 0 (stderr: $(cat err.txt))" test "$status" -eq 0

# glint-mpi: rank 0 shows the window, with the image written.
GLINT_MPI=$(dirname "$GLINT")/glint-mpi
if [ -x "$GLINT_MPI" ] && command -v mpirun >/dev/null; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    # Under ASan, OpenMPI's leaks are suppressed too, as in mpi.sh.
    cat "$here/tests/cli/mpi.supp" "$here/tests/cli/display.supp" >mpi-display.supp
    export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}fast_unwind_on_malloc=0"
    export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$PWD/mpi-display.supp"
    start mpirun --oversubscribe -np 2 "$GLINT_MPI" --display -w 160 -h 120 --threads 1 -q -o mpi.png
    check "glint-mpi: the title gives the time when done, got '$(title)'" wait_title "glint - seed room - done in * s"
    shot shot.png
    check "glint-mpi: the window shows the image written" same_pixels shot.png mpi.png
    key q
    ended
    check "glint-mpi: q: exit $status, expected 0" test "$status" -eq 0
    env -u DISPLAY mpirun --oversubscribe -np 2 "$GLINT_MPI" --display -w 64 -h 48 -o mpi-none.png 2>err.txt
    status=$?
    check "glint-mpi, no display: exit $status, expected 2" test "$status" -eq 2
    check "glint-mpi, no display: the message once, got '$(cat err.txt)'" \
        test "$(grep -c "glint: --display needs a screen, and neither DISPLAY nor WAYLAND_DISPLAY is set" err.txt)" = 1
    check "glint-mpi, no display: nothing written" test ! -e mpi-none.png
fi
check "no window started a session bus (dbus-launch)" test ! -e dbus-launch-ran
finish
