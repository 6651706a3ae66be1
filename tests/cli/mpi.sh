#!/usr/bin/env bash
# glint-mpi (src/mpi/), found beside glint: the default scene and every
# example scene render to the bytes glint gives, on 1, 2, 3, 4 and 7 ranks
# with various thread counts, the regular and the jittered sampler, and
# the sobol sampler with a filter and adaptive sampling; a scene
# error is reported once, by rank 0, with glint's message, and every rank
# exits with glint's code, writing nothing; bad flags likewise. (The
# scene's files sent by rank 0: mpi_files.sh; signals, a rank killed and
# mismatched builds: mpi_faults.sh.) Skipped (exit 77) when glint-mpi was
# not built (no MPI found) or mpirun is missing.
# Usage: mpi.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"
source "$(dirname "$0")/lib/mpi.sh"

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

# Sobol points through a filter with negative lobes, adaptive sampling, a
# thin lens and an area light, all at once.
cat >anti-aliasing.yaml <<'YAML'
glint: 1
settings:
  samples: 3
  sampler: sobol
  filter: { type: mitchell }
  adaptive: { threshold: 0.05, max_samples: 12 }
  light_samples: 6
camera: { type: thin_lens, position: [0, 1.5, 5], look_at: [0, 0.5, 0], aperture: 0.15 }
textures: { floor: { type: checker, colors: [[0.9, 0.9, 0.9], [0.2, 0.2, 0.2]], size: 0.25 } }
materials: { floor: { texture: floor }, ball: { color: [0.8, 0.3, 0.2], roughness: 0.3, reflectivity: 0.5 } }
lights: [{ type: disk, position: [0, 4, 0], direction: [0, -1, 0], radius: 1, samples: 4 }]
objects:
  - { type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor }
  - { type: sphere, center: [0, 0.6, 0], radius: 0.6, material: ball }
YAML
same 3 2 anti-aliasing.exr anti-aliasing.yaml --exr-pixel float
same 7 1 anti-aliasing.png anti-aliasing.yaml

# Every example scene, each on another rank count (two under the sanitizers).
i=0
for scene in "$here"/scenes/*.yaml; do
    [ "$full" -eq 1 ] || [ "$i" -lt 2 ] || break
    # An animation's frames: mpi_frames.sh.
    grep -q '^  frames:' "$scene" && continue
    same "${ranks[$((i % 5))]}" "${threads[$(((i + 1) % 5))]}" "$(basename "$scene" .yaml).png" "$scene"
    i=$((i + 1))
done
[ "$full" -eq 0 ] || [ "$i" -ge 6 ]
verdict $? "at least six example scenes, found $i"
[ "$full" -eq 0 ] || same 4 1 refraction-jittered.png "$here/scenes/refraction.yaml" --sampler jittered --spp 4

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

# Through the library: glint_mpi_render's tile_done, on rank 0 alone, once
# for every rank's tiles, with the image's pixels (tests/mpi_tiles.c).
timeout "$limit" mpirun --oversubscribe -np 3 "$(dirname "$GLINT")/mpi_tiles" >mpi.log 2>&1
verdict $? "tile_done tells rank 0 of every rank's tiles once, with the image's pixels: $(head -c 300 mpi.log)"

finish
