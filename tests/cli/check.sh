#!/usr/bin/env bash
# glint --check FILE...: one line for each file on stdout, "FILE: ok: ..."
# with counts in the singular for one ("1 texture", "placed once"), or its
# problems and "glint: FILE: N problems; not valid" on stderr, in the order
# of the files; the exit code is the worst: 0 only when all are valid.
# Usage: check.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"

# expect WHAT CODE OUTPUT -- ARGS...: glint ARGS, with one.yaml on stdin,
# exits CODE with OUTPUT on stdout and stderr together, and writes no image.
expect() {
    local what=$1 code=$2 output=$3 actual status
    shift 4
    actual=$("$GLINT" "$@" 2>&1 <one.yaml)
    status=$?
    [ "$status" -eq "$code" ] && [ "$actual" = "$output" ] && [ -z "$(ls ./*.png 2>/dev/null)" ]
    verdict $? "$what: glint $*
  expected exit $code: $output
  got      exit $status: $actual"
}

# Meshes with a material of their own in an MTL file, which each adds.
printf 'newmtl red\nKd 1 0 0\n' >red.mtl
printf 'mtllib red.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n' >tri.obj
printf 'mtllib red.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl red\nf 1 2 3\nf 2 4 3\n' >quad.obj
# One of everything; then with a mesh placed once.
cat >one.yaml <<'EOF'
textures: {t: {type: checker}}
materials: {m: {texture: t}}
lights: [{type: point, position: [0, 5, 5]}]
objects:
  - {type: sphere, radius: 1, material: m}
EOF
{ cat one.yaml; printf '  - {type: mesh, file: tri.obj}\n'; } >mesh.yaml
# Two of everything, and two meshes placed three times.
cat >two.yaml <<'EOF'
textures: {t: {type: checker}, u: {type: checker}}
materials: {m: {texture: t}, n: {texture: u}}
lights: [{type: point, position: [0, 5, 5]}, {type: directional, direction: [0, -1, 0]}]
objects:
  - {type: sphere, radius: 1, material: m}
  - {type: sphere, radius: 1, material: n}
  - {type: mesh, file: tri.obj}
  - {type: mesh, file: quad.obj}
  - {type: mesh, file: quad.obj, transform: [{translate: [2, 0, 0]}]}
EOF
printf 'objects:\n  - {type: sphere, radius: -1}\n  - {type: box}\n' >bad.yaml
printf 'settings: {width: 8}\n' >bare.yaml
one="one.yaml: ok: 1 texture, 1 material, 1 shape, 1 light"
two="two.yaml: ok: 2 textures, 4 materials, 2 shapes, 2 lights, 2 meshes (3 triangles) placed 3 times"

expect "one of each" 0 "$one" -- --check one.yaml
expect "one mesh" 0 "mesh.yaml: ok: 1 texture, 2 materials, 1 shape, 1 light, 1 mesh (1 triangle) placed once" -- --check mesh.yaml
expect "several of each" 0 "$two" -- --check two.yaml
# NFF spheres are sphere sets: one of the spheres of opaque fills, one of
# those that let light through.
printf '%s\n' v 'from 0 0 5' 'at 0 0 0' 'up 0 1 0' 'angle 40' 'hither 1' 'resolution 8 8' 'l 0 5 5' \
    's 0 0 0 1' 's 2 0 0 1' 'f 1 1 1 1 0 0 0.5 1.5' 's -2 0 0 1' 'c 0 0 0 1 0 2 0 1' >spheres.nff
expect "sphere sets" 0 "spheres.nff: ok: 0 textures, 2 materials, 3 shapes (2 sphere sets of 3 spheres), 1 light" \
    -- --check spheres.nff
expect "nothing in the scene" 0 "bare.yaml: ok: 0 textures, 0 materials, 0 shapes, 0 lights" -- --check bare.yaml
expect "several files, stdin among them, all valid" 0 "$two
<stdin>: ok: 1 texture, 1 material, 1 shape, 1 light" -- two.yaml --check -
expect "bad and missing files among good ones: each reported, exit 1" 1 "$one
bad.yaml:2:28: 'radius' must be positive, got -1
bad.yaml:2:5: sphere needs 'material'
bad.yaml:3:5: box needs 'min'
bad.yaml:3:5: box needs 'max'
bad.yaml:3:5: box needs 'material'
glint: bad.yaml: 5 problems; not valid
cannot read scene 'missing.yaml': No such file or directory
glint: missing.yaml: 1 problem; not valid
$two" -- --check one.yaml bad.yaml missing.yaml two.yaml

finish
