#!/usr/bin/env bash
# glint --print-scene writes a scene file that renders to the same image
# bytes as what it was printed from: the seed room, every example scene,
# the test scenes, model files (small test meshes; the teapot, the Cornell
# box and the bunny from ../shared/data when they are there), with flags
# applied, with paths relative to the current directory, and with a
# swapped texture. A small scene prints exactly the expected text.
# Usage: print_scene.sh PATH/TO/glint
here=$(cd "$(dirname "$0")/../.." && pwd)
source "$here/tests/cli/lib/harness.sh"
fail() { verdict 1 "$1"; }

# same_text WHAT WANT GOT: the file GOT holds exactly the text of WANT.
same_text() {
    if cmp -s "$2" "$3"; then
        verdict 0 ""
    else
        fail "$1"; diff "$2" "$3" | sed 's/^/  /'
    fi
}

# round_trip NAME [ARGS...]: `glint ARGS -o a.ppm` and `glint --print-scene
# ARGS > NAME.yaml; glint NAME.yaml -o b.ppm` write the same bytes.
round_trip() {
    local name=$1
    shift
    if ! "$GLINT" "$@" -q --threads 2 -o "$work/a.ppm" >"$work/err" 2>&1; then
        fail "$name: does not render"; sed 's/^/  /' "$work/err"; return
    fi
    if ! "$GLINT" --print-scene "$@" >"$work/$name.yaml" 2>"$work/err"; then
        fail "$name: --print-scene fails"; sed 's/^/  /' "$work/err"; return
    fi
    if ! "$GLINT" "$work/$name.yaml" -q --threads 2 -o "$work/b.ppm" >"$work/err" 2>&1; then
        fail "$name: the printed scene does not render"; sed 's/^/  /' "$work/err"; return
    fi
    if cmp -s "$work/a.ppm" "$work/b.ppm"; then
        verdict 0 ""
    else
        fail "$name: the printed scene renders different bytes"
    fi
}

size=(-w 48 -h 36)
round_trip seed-room "${size[@]}"
for scene in "$here"/scenes/*.yaml "$here"/tests/cli/*.yaml; do
    # A still prints without its motion over the shutter (docs/animation.md).
    grep -q '^  shutter:' "$scene" && continue
    # An animated scene's frame 12 prints as a still (a still ignores --frame).
    round_trip "$(basename "$scene" .yaml)" "$scene" "${size[@]}" --spp 1 --frame 12
done
for model in "$here"/tests/fuzz/corpus/mesh/obj-groups-usemtl.obj "$here"/tests/fuzz/corpus/mesh/obj-ngon-concave.obj; do
    round_trip "model-$(basename "$model")" "$model" "${size[@]}"
done
data=$here/../shared/data
if [ -d "$data" ]; then
    for scene in "$here"/scenes/models/*.yaml; do
        round_trip "models-$(basename "$scene" .yaml)" "$scene" "${size[@]}" --spp 1
    done
    for model in teapot.obj CornellBox-Original.obj stanford-bunny.obj; do
        [ -f "$data/$model" ] && round_trip "model-$model" "$data/$model" "${size[@]}"
    done
fi

# The flags that change settings are in what is printed: the settings list
# every key, in the order of the docs, and -o becomes the output.
"$GLINT" --print-scene -w 33 -h 21 --spp 9 --sampler jittered --seed 7 --depth 3 --exposure -1.5 --filter mitchell \
    -o x.exr >"$work/flags.yaml"
sed -n '/^settings:/,/^camera:/p' "$work/flags.yaml" >"$work/settings.txt"
cat >"$work/settings.want" <<'EOF'
settings:
  width: 33
  height: 21
  samples: 9
  sampler: jittered
  seed: 7
  depth: 3
  background: [0, 0, 0]
  ambient: [1, 1, 1]
  exposure: -1.5
  emission_samples: 16
  light_samples: 0
  dispersion_bands: 16
  filter: {type: mitchell, radius: 0}
  output: x.exr
camera:
EOF
same_text "flags: the settings printed" "$work/settings.want" "$work/settings.txt"

# Paths are printed relative to the current directory, as the scene holds
# them: a file printed there renders the same.
mkdir "$work/cwd"
ln -s "$here/scenes" "$work/cwd/scenes"
ln -s "$here/assets" "$work/cwd/assets"
(cd "$work/cwd" && "$GLINT" --print-scene scenes/textures.yaml -w 40 -h 30 >textures.yaml &&
    "$GLINT" textures.yaml -q -o a.ppm && "$GLINT" scenes/textures.yaml -w 40 -h 30 -q -o b.ppm &&
    grep -q '^  moon-globe: {type: image, mapping: spherical, file: scenes/../assets/moon.jpg}$' textures.yaml &&
    cmp -s a.ppm b.ppm) && verdict 0 "" || fail "relative paths"

# --texture swaps the picture in what is printed too.
"$GLINT" "$here/scenes/seed-room.yaml" -w 40 -h 40 --texture "moon=$here/assets/moon.jpg" -q -o "$work/a.ppm"
"$GLINT" --print-scene --texture "moon=$here/assets/moon.jpg" >"$work/swap.yaml"
if grep -q "^  moon: {type: image, file: $here/assets/moon.jpg}\$" "$work/swap.yaml"; then
    verdict 0 ""
else
    fail "--texture: the swapped file is not printed"
fi

# A small scene prints exactly: defaults left out, names quoted where YAML
# would misread them, display colours where exact and linear ones where
# not, a light's intensity folded into its colour, a group's transform
# composed into one matrix step, a mesh as its file.
cp "$here/tests/fuzz/corpus/mesh/obj-groups-usemtl.obj" "$work/model.obj"
cat >"$work/small.yaml" <<'EOF'
settings: {output: out.png}
camera: {position: [0, 1, 5], look_at: [0, 0.5, 0]}
materials:
  "red: bright": {color: "#ff0000", specular: 0}
  glow: {color: {linear: [2, 0.5, 0.25]}}
lights:
  - {type: point, position: [5, 5, 5], intensity: 0.5}
objects:
  - type: group
    material: "red: bright"
    transform: [{translate: [1, 0, 0]}]
    objects:
      - {type: sphere, radius: 0.5, transform: [{scale: 2}]}
      - {type: cylinder, radius: 1, height: 2, capped: false, material: {ior: 1.33}}
  - {type: mesh, file: model.obj, crease_angle: 30, material: glow}
EOF
cat >"$work/small.want" <<EOF
# A glint scene file (docs/scene-format.md). Settings and camera list every key;
# elsewhere a key at its default is left out.
glint: 1
settings:
  width: 640
  height: 480
  samples: 4
  sampler: regular
  seed: 0
  depth: 5
  background: [0, 0, 0]
  ambient: [1, 1, 1]
  exposure: 0
  emission_samples: 16
  light_samples: 0
  dispersion_bands: 16
  output: out.png
camera:
  position: [0, 1, 5]
  look_at: [0, 0.5, 0]
  up: [0, 1, 0]
  fov: 45
  type: pinhole
  aperture: 0
  focus_distance: 0
  f_number: 0
  sensor_width: 0
  blades: 0
  view_width: 0
materials:
  "red: bright": {color: [1, 0, 0], specular: 0}
  glow: {color: {linear: [2, 0.5, 0.25]}}
lights:
  - {type: point, position: [5, 5, 5], color: [0.7353569830524495, 0.7353569830524495, 0.7353569830524495]}
objects:
  - type: sphere
    radius: 0.5
    material: "red: bright"
    transform:
      - matrix:
          - [2, 0, 0, 1]
          - [0, 2, 0, 0]
          - [0, 0, 2, 0]
  - type: cylinder
    radius: 1
    height: 2
    capped: false
    material: {ior: 1.33}
    transform:
      - matrix:
          - [1, 0, 0, 1]
          - [0, 1, 0, 0]
          - [0, 0, 1, 0]
  - {type: mesh, file: $work/model.obj, crease_angle: 30, material: glow}
EOF
"$GLINT" --print-scene "$work/small.yaml" >"$work/small.txt" 2>&1
same_text "small scene: the printed text" "$work/small.want" "$work/small.txt"

finish
