#!/usr/bin/env bash
# pgo-build.sh DIR [cmake args...] - a Release build of glint in DIR,
# optimised with GCC from a profile of glint's own renders:
#   1. configure with GLINT_PGO=generate and build glint, which then records
#      how often each branch and call runs;
#   2. render the training set below with it (a few seconds);
#   3. configure with GLINT_PGO=use and build everything from that record
#      (or only the targets listed in PGO_TARGETS, e.g. "glint glint-mpi":
#      build.sh render needs no tests).
# It also compiles for the build machine's processor (GLINT_NATIVE, unless
# the arguments say -DGLINT_NATIVE=OFF). The images do not change (no
# floating-point option differs); renders are 5 to 15% faster
# (bench/README.md). With another compiler CMake ignores GLINT_PGO and this
# is a plain Release build. build.sh render and bench/run build through here.
set -euo pipefail
dir=$(realpath -m "${1:?usage: cmake/pgo-build.sh DIR [cmake args...]}")
shift
cd "$(dirname "$0")/.."
jobs=$(nproc)

cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DGLINT_NATIVE=ON -DGLINT_PGO=generate "$@" >/dev/null
rm -rf "$dir/pgo-data" "$dir/pgo-train"
cmake --build "$dir" -j "$jobs" --target glint

# The training set: the default scene and a generated smooth mesh on a
# floor under a point light, one thread each, so the counts do not depend
# on timing. The mesh is moved, as imported models usually are, so the
# code that maps rays into a moved mesh's space is trained too (the bunny:
# 1% fewer instructions). Adding the example scenes made it worse:
# scenes/refraction.yaml alone outweighs the rest and steers inlining
# towards glass (seed room +2% instead of +10%). Also a small depth of
# field, for the thin lens and the Sobol sampler the rest never run: its
# own render 7% faster, the seed room the same. (A soft light as well
# gained under 5%, and nothing elsewhere.) And the combinations and solid
# textures of two example scenes, small, which the rest never run (GCC
# then optimises that code for size): bench's textured row 6% faster, its
# csg row 2%, the seed room the same.
train="$dir/pgo-train"
mkdir -p "$train"
awk -v n=120 'BEGIN {
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++) {
            x = 2 * i / n - 1; z = 2 * j / n - 1
            printf "v %.6f %.6f %.6f\n", x, 0.3 + 0.1 * sin(6 * x) * cos(5 * z), z
        }
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; d = c + 1
            printf "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d
        }
}' >"$train/grid.obj"
cat >"$train/grid.yaml" <<'EOF'
glint: 1
settings: { width: 320, height: 180, samples: 1, background: [0.18, 0.2, 0.23] }
camera: { position: [0.9, 1.4, 2.6], look_at: [0, 0.2, 0], fov: 40 }
materials:
  grid: { color: [0.85, 0.62, 0.45], specular: 0 }
  floor: { color: [0.75, 0.75, 0.75], specular: 0 }
lights:
  - { type: point, position: [-2.5, 4.5, 3] }
objects:
  - { type: plane, normal: [0, 1, 0], material: floor }
  - type: mesh
    file: grid.obj
    crease_angle: 180
    material: grid
    transform: [{ translate: [0, 0.01, 0] }, { scale: 1.5 }]
EOF
# A floor of an image tiled by a planar mapping, repeated both ways and
# read from its mipmap levels, which the Moon of the default scene (a
# sphere, clamped along v) never reaches: code the training misses is
# compiled for size, libm's floor called instead of one instruction
# (bench's textured row: see bench/README.md).
cat >"$train/tiles.yaml" <<EOF
glint: 1
settings: { width: 160, height: 120, samples: 4, sampler: regular }
camera: { position: [0, 3, 7], look_at: [0, 0.6, 0], fov: 40 }
textures:
  tiles: { type: image, file: $PWD/assets/moon.jpg, wrap_v: repeat, mapping: { type: planar, scale: 1.5 } }
materials:
  tiles: { texture: tiles, specular: 0 }
lights:
  - { type: point, position: [4, 8, 6] }
objects:
  - { type: plane, normal: [0, 1, 0], material: tiles }
EOF
glint="$dir/glint"
"$glint" -o "$train/seed-room.ppm" -w 200 -h 200 --threads 1 --quiet
"$glint" "$train/grid.yaml" -o "$train/grid.ppm" --threads 1 --quiet
"$glint" scenes/depth-of-field.yaml -o "$train/lens.ppm" -w 160 -h 120 --spp 16 --sampler sobol --threads 1 --quiet
"$glint" scenes/csg.yaml -o "$train/csg.ppm" -w 120 -h 80 --threads 1 --quiet
"$glint" scenes/still-life.yaml -o "$train/still.ppm" -w 120 -h 80 --threads 1 --quiet
"$glint" "$train/tiles.yaml" -o "$train/tiles.ppm" --threads 1 --quiet

cmake -S . -B "$dir" -DGLINT_PGO=use >/dev/null
read -r -a targets <<<"${PGO_TARGETS:-all}"
cmake --build "$dir" -j "$jobs" --target "${targets[@]}"

# Leave DIR configured as a plain Release build: the programs just built
# stay, and a later rebuild after an edit compiles without the profile,
# which no longer matches the sources (with GLINT_WERROR that would fail).
cmake -S . -B "$dir" -DGLINT_PGO= >/dev/null
