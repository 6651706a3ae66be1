#!/usr/bin/env bash
# bench/equal-noise.sh - glint against POV-Ray 3.7 at equal noise, on the
# work Monte Carlo sampling does: for each sample count S (4 to 256) it
# prints each renderer's median time and its noise, the RMSE against its
# own 1024-sample reference over the reference's mean (bench/rmse.c), both
# images 16 bits a channel.
# Then, for each of glint's rows, the samples and time POV-Ray needs for
# the same noise (equal_noise, below). The cases:
#
#   soft-light      bench/soft-light.yaml / .pov: a 2 x 2 lamp over a ball and
#                   a block, 640x480, one camera ray a pixel; S samples of the
#                   lamp (POV-Ray: a jittered sqrt(S) x sqrt(S) area_light)
#   cornell-box     scenes/models/cornell-box.yaml / bench/cornell-box.pov:
#                   the box lit by its own ceiling lamp, 640x640, one camera
#                   ray a pixel; S samples of the lamp (emission_samples)
#   depth-of-field  scenes/depth-of-field.yaml / bench/depth-of-field.pov:
#                   a thin lens, 640x480; S samples a pixel (glint's Sobol
#                   sampler; POV-Ray's focal_blur with S blur_samples)
#   depth-of-field-adaptive  the same, glint with adaptive sampling: S/4
#                   samples a pixel (at least 2), more where they differ
#                   by over 0.05, up to 2 S; POV-Ray as above (its own
#                   early stop is no better a sample, bench/README.md)
#
#   GLINT_BIN=/path/to/glint bench/equal-noise.sh [CASE ...]   (default: all)
#   BENCH_RUNS=5 ...                         5 runs of each (default 3)
#
# The Cornell box needs ../shared/data/CornellBox-Original.obj (or
# GLINT_SHARED_DATA); without it that case is skipped. Results and what
# they mean: bench/README.md.
set -euo pipefail

BENCH_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(dirname "$BENCH_DIR")
RUNS=${BENCH_RUNS:-3}
SHARED=${GLINT_SHARED_DATA:-$(dirname "$ROOT")/shared/data}
die() { echo "bench/equal-noise.sh: $*" >&2; exit 1; }
[[ -x "${GLINT_BIN:-}" ]] || die "set GLINT_BIN to a built glint (./build.sh render builds one)"
command -v povray >/dev/null 2>&1 || die "povray is missing (Debian: apt-get install povray)"
[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || die "BENCH_RUNS must be a positive integer, not '$RUNS'"
CASES=("$@")
[[ ${#CASES[@]} -gt 0 ]] || CASES=(soft-light cornell-box depth-of-field)
for c in "${CASES[@]}"; do
    [[ $c =~ ^(soft-light|cornell-box|depth-of-field|depth-of-field-adaptive)$ ]] ||
        die "no case '$c' (soft-light cornell-box depth-of-field depth-of-field-adaptive)"
done

# POV-Ray's Debian configuration reads scenes only from a few folders: /tmp is one.
WORK=$(mktemp -d /tmp/glint-equal-noise.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
cp "$BENCH_DIR"/soft-light.pov "$BENCH_DIR"/cornell-box.pov "$BENCH_DIR"/depth-of-field.pov "$WORK/"
cc -O2 -o "$WORK/bench_rmse" "$BENCH_DIR/rmse.c" -lm || die "cannot build bench/rmse.c"

# glint_run CASE S OUT: renders CASE with S samples; prints the seconds.
glint_run() {
    local flags=()
    case $1 in
    soft-light) sed "s/samples: 16 /samples: $2 /" "$BENCH_DIR/soft-light.yaml" >"$WORK/scene.yaml" ;;
    cornell-box)
        sed -e "s/emission_samples: [0-9]*/emission_samples: $2/" -e "s|file: [./]*shared/data/|file: $SHARED/|" \
            "$ROOT/scenes/models/cornell-box.yaml" >"$WORK/scene.yaml"
        flags=(--spp 1) ;;
    depth-of-field)
        cp "$ROOT/scenes/depth-of-field.yaml" "$WORK/scene.yaml"
        flags=(--spp "$2" --sampler sobol) ;;
    depth-of-field-adaptive)
        # The 1024-sample reference is uniform, as the other cases'.
        local set="  samples: $(($2 / 4 < 2 ? 2 : $2 / 4))\n  adaptive: {threshold: 0.05, max_samples: $((2 * $2))}"
        [[ $2 == 1024 ]] && set="  samples: 1024"
        sed "s/^  samples: 64$/$set\n  sampler: sobol/" "$ROOT/scenes/depth-of-field.yaml" >"$WORK/scene.yaml" ;;
    esac
    "$GLINT_BIN" "$WORK/scene.yaml" "${flags[@]}" --threads 2 --bit-depth 16 -o "$3" 2>&1 |
        sed -n 's/.*threads: \([0-9.]*\) s,.*/\1/p'
}
# povray_run CASE S OUT: renders CASE's copy with S samples; prints the trace seconds.
povray_run() {
    local args
    case $1 in
    soft-light) args=(+W640 +H480 "Declare=LIGHT_N=$(isqrt "$2")") ;;
    cornell-box) args=(+W640 +H640 "Declare=LIGHT_N=$(isqrt "$2")") ;;
    depth-of-field*) args=(+W640 +H480 "Declare=BLUR_N=$2") ;;
    esac
    (cd "$WORK" && povray "${1%-adaptive}.pov" -D "${args[@]}" +FP16 "+O$3" -A +WT2 2>&1) |
        sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p'
}
isqrt() { awk -v s="$1" 'BEGIN { print int(sqrt(s) + 0.5) }'; }
# equal_noise: reads a case's rows (samples, glint s, glint noise, POV-Ray s,
# POV-Ray noise) and prints, for each of glint's rows, the samples POV-Ray
# needs for glint's noise and how many times glint's time POV-Ray then takes.
# The noise of each row is the same in every run (both renderers' samples
# are fixed); only the times move with the machine. So POV-Ray's samples at
# glint's noise come from its noise curve, log-log between the two rows
# about it (past the last, from the last two: "extrapolated"), and its time
# there from its time a sample in those rows, taken in the same run as
# glint's: steadier than interpolating its times alone.
equal_noise() {
    awk '{ s[NR] = $1; gt[NR] = $2; gn[NR] = $3; pt[NR] = $4; pn[NR] = $5 }
    END {
        printf "%-8s %-16s %s\n", "samples", "povray samples", "povray s / glint s at equal noise"
        for (i = 1; i <= NR; i++) {
            k = 0
            for (j = 1; j < NR; j++) if (pn[j] >= gn[i] && gn[i] >= pn[j + 1]) k = j
            past = k == 0; if (past) k = NR - 1
            f = log(gn[i] / pn[k]) / log(pn[k + 1] / pn[k])
            samples = s[k] * exp(f * log(s[k + 1] / s[k]))
            a = pt[k] / s[k]; b = pt[k + 1] / s[k + 1]
            g = log(samples / s[k]) / log(s[k + 1] / s[k])
            povray = samples * a * exp(g * log(b / a))
            printf "%-8s %-16.0f %.1fx%s\n", s[i], samples, povray / gt[i], past ? " (extrapolated)" : ""
        }
    }'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

for c in "${CASES[@]}"; do
    if [[ $c == cornell-box && ! -f $SHARED/CornellBox-Original.obj ]]; then
        echo "cornell-box: skipped, $SHARED/CornellBox-Original.obj is missing (set GLINT_SHARED_DATA)"
        continue
    fi
    echo "$c"
    glint_run "$c" 1024 "$WORK/glint-ref.ppm" >/dev/null
    povray_run "$c" 1024 "$WORK/povray-ref.ppm" >/dev/null
    printf '%-8s %-10s %-12s %-10s %-12s %s\n' samples "glint s" "glint noise" "povray s" "povray noise" "povray/glint"
    : >"$WORK/rows"
    for s in 4 9 16 36 64 144 256; do
        # Alternating, so that both see the same moods of a shared machine.
        : >"$WORK/glint-times"
        : >"$WORK/povray-times"
        for _ in $(seq "$RUNS"); do
            glint_run "$c" "$s" "$WORK/glint.ppm" >>"$WORK/glint-times"
            povray_run "$c" "$s" "$WORK/povray.ppm" >>"$WORK/povray-times"
        done
        g=$(median <"$WORK/glint-times")
        p=$(median <"$WORK/povray-times")
        row=$(printf '%-8s %-10s %-12s %-10s %-12s %s' "$s" "$g" "$("$WORK/bench_rmse" "$WORK/glint.ppm" "$WORK/glint-ref.ppm")" \
            "$p" "$("$WORK/bench_rmse" "$WORK/povray.ppm" "$WORK/povray-ref.ppm")" \
            "$(awk -v g="$g" -v p="$p" 'BEGIN { printf "%.2f", p / g }')")
        echo "$row"
        echo "$row" >>"$WORK/rows"
    done
    equal_noise <"$WORK/rows"
done
