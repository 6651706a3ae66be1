#!/usr/bin/env bash
# bench/huge.sh - huge but legitimate scenes against their targets: a scene
# file of 1,000,000 spheres loads in under 3 s and 1 GiB and renders; the
# same spheres in NFF (a sphere set) load, build and render at 1920x1080 on
# 2 threads in under 3 s and 200 bytes a sphere; one of 100,000 textures
# and 100,000 materials loads in under 1 s.
#
#   bench/huge.sh                   glint from build/, 3 runs each
#   BENCH_RUNS=5 bench/huge.sh      5 runs each
#   GLINT_BIN=/path/to/glint bench/huge.sh
#
# The scenes are generated into a temporary folder (removed at the end).
# Times are medians of the runs, memory the largest peak resident set; see
# bench/README.md ("Huge scenes").
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh" huge.sh 3
/usr/bin/time -f %e true 2>/dev/null || die "needs GNU time (/usr/bin/time; Debian package 'time')"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A million spheres on a 1000 x 1000 grid, one a line (about 60 MB: within
# the 64 MiB a scene may have), seen from in front, with one light; and
# 100,000 textures and materials.
"$REPO/tools/huge_scene.sh" spheres 1000000 >"$tmp/spheres.yaml"
"$REPO/tools/huge_scene.sh" nff-spheres 1000000 >"$tmp/spheres.nff"
"$REPO/tools/huge_scene.sh" names 100000 >"$tmp/names.yaml"

# measure NAME TARGET_S TARGET_MIB ARGS...: runs glint ARGS RUNS times and
# prints the median wall time, the peak memory and whether both are within
# the targets (a target of 0 is none).
measure() {
    local name=$1 target_s=$2 target_mib=$3 times=() peak=0 line
    shift 3
    for ((r = 0; r < RUNS; r++)); do
        /usr/bin/time -f '%e %M' -o "$tmp/time" "$GLINT" "$@" >/dev/null 2>"$tmp/err" \
            || die "$name: glint $* failed: $(cat "$tmp/err")"
        read -r s kib <"$tmp/time"
        times+=("$s")
        ((kib > peak)) && peak=$kib
    done
    line=$(printf '%s\n' "${times[@]}" | sort -g | awk -v n="$RUNS" '{ t[NR] = $1 } END { print t[int((n + 1) / 2)] }')
    awk -v name="$name" -v s="$line" -v mib="$((peak / 1024))" -v ts="$target_s" -v tm="$target_mib" -v all="${times[*]}" 'BEGIN {
        ok = (ts == 0 || s < ts) && (tm == 0 || mib < tm)
        printf "%-22s %8.2f s %8d MiB   %s   (runs: %s)\n", name, s, mib, ok ? "within target" : "MISSES target", all
    }'
}

echo "glint: $GLINT; $RUNS runs each; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-22s %10s %12s\n' row "median" "peak"
measure "1M spheres --check" 3 1024 --check "$tmp/spheres.yaml"
measure "1M spheres 160x120" 0 0 "$tmp/spheres.yaml" -w 160 -h 120 --quiet -o "$tmp/spheres.png"
measure "1M NFF spheres 1080p" 3 $((200 * 1000000 / 1048576)) "$tmp/spheres.nff" --threads 2 --quiet \
    -o "$tmp/spheres.png"
measure "100k materials --check" 1 0 --check "$tmp/names.yaml"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
