#!/usr/bin/env bash
# Allocation failures are reported, never used: glint runs under address-
# space limits (ulimit -v) from the least it starts with to more than it
# needs, on the seed room and on a generated model, and each run either
# finishes or says "out of memory" and exits 5, writing nothing, on one
# thread and on two (where TBB inside Embree once aborted the process in a
# band of limits: its threads now start with the device, which reports
# failing to start them). Skipped under AddressSanitizer, which needs far
# more address space than any such limit.
# Usage: memory.sh PATH/TO/glint
set -u
GLINT=$1
if ldd "$GLINT" 2>/dev/null | grep -q libasan; then
    echo "skipped: built with AddressSanitizer"
    exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
passed=0
failed=0

# A 180,000-triangle grid, so that importing it allocates a few megabytes.
awk 'BEGIN {
    n = 300
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++)
            printf "v %f %f %f\n", i / n, 0.1 * sin(i * 0.1) * cos(j * 0.1), j / n
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; d = c + 1
            printf "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d
        }
}' >grid.obj

# The least limit (in KiB) glint starts under: below it the dynamic loader
# itself fails, before glint's code runs.
start=40000
until (ulimit -v "$start" && "$GLINT" --version >/dev/null 2>&1); do
    start=$((start + 10000))
    [ "$start" -lt 1000000 ] || { echo "FAIL: glint does not start under 1 GB"; exit 1; }
done

# run LIMIT ARGS...: one run under LIMIT KiB; a finished render or a clean
# out-of-memory failure pass, anything else (a signal, another message) fails.
run() {
    local limit=$1
    shift
    rm -f out.png
    (ulimit -v "$limit" && exec "$GLINT" "$@" -q -o out.png) 2>err.txt
    local status=$? first
    first=$(head -n 1 err.txt)
    if [ "$status" -eq 0 ] && [ -s out.png ]; then
        passed=$((passed + 1))
    elif [ "$status" -eq 5 ] && [[ "$first" =~ ^glint:\ .*out\ of\ memory ]] && [ ! -e out.png ]; then
        passed=$((passed + 1))
    else
        echo "FAIL: ulimit -v $limit: glint $*: exit $status: $(tr '\n' '|' <err.txt)"
        failed=$((failed + 1))
    fi
}

finished=0
for threads in 1 2; do
    for ((limit = start; limit <= start + 400000; limit += 20000)); do
        run "$limit" -w 1500 -h 1500 --spp 1 --threads "$threads"
        run "$limit" grid.obj -w 600 -h 400 --spp 1 --threads "$threads"
        [ -s out.png ] && finished=$((finished + 1))
    done
    # Around where the 3000 x 3000 render on two threads used to abort.
    for ((limit = 290000; limit <= 330000; limit += 4000)); do
        run "$limit" -w 3000 -h 3000 --spp 1 --threads "$threads"
    done
done
# The sweep must reach limits where the renders finish, or it tested nothing.
[ "$finished" -gt 0 ] || { echo "FAIL: no render finished under any limit"; failed=$((failed + 1)); }

# Running out of memory while parsing is "out of memory" and exit 5 too,
# never a parser's own words: libyaml's failing allocations once read
# "1:1: syntax error: unknown" (exit 1), Assimp's "std::bad_alloc". A
# scene of one 40 MB value (libyaml buffers it whole) is checked and a
# 180,000-triangle PLY model (read by Assimp) rendered under rising
# limits; each run passes or fails so, and some must fail with the
# parser's message, or the sweep missed the parse.
{ printf 'settings:\n  output: '; head -c 40000000 /dev/zero | tr '\0' a; printf '.png\n'; } >long.yaml
awk 'NR == 1 { print "ply\nformat ascii 1.0\nelement vertex 90601\nproperty float x\nproperty float y\n" \
              "property float z\nelement face 180000\nproperty list uchar int vertex_indices\nend_header" }
     /^v / { print $2, $3, $4 } /^f / { print 3, $2 - 1, $3 - 1, $4 - 1 }' grid.obj >grid.ply
# parse_sweep EXACT ARGS...: glint ARGS under limits from $start up; EXACT
# is the first line of a failure in the parse, which must occur.
parse_sweep() {
    local exact=$1 limit status first seen=0
    shift
    for ((limit = start; limit <= start + 300000; limit += 10000)); do
        (ulimit -v "$limit" && exec "$GLINT" "$@") >/dev/null 2>err.txt
        status=$?
        first=$(head -n 1 err.txt)
        [ "$first" = "$exact" ] && seen=1
        if [ "$status" -eq 0 ] || { [ "$status" -eq 5 ] && [[ "$first" == *"out of memory"* ]]; }; then
            passed=$((passed + 1))
        else
            echo "FAIL: ulimit -v $limit: glint ${*:1:2}: exit $status: $(head -c 300 err.txt | tr '\n' '|')"
            failed=$((failed + 1))
        fi
    done
    [ "$seen" -eq 1 ] || { echo "FAIL: glint $1: no run failed with '$exact'"; failed=$((failed + 1)); }
}
parse_sweep "long.yaml: out of memory reading the scene" --check long.yaml
parse_sweep "glint: grid.ply: out of memory" grid.ply -w 8 -h 8 --spp 1 -q -o out.png
echo "$passed passed, $failed failed (limits from $start KiB)"
[ "$failed" -eq 0 ]
