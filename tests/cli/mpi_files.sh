#!/usr/bin/env bash
# glint-mpi's nodes need no shared file system: rank 0 reads the scene,
# its includes, textures, models and their material files, and sends their
# bytes to the other ranks, which never open a scene path. Here the other
# ranks run in a folder that has none of the scene's files, or decoys of
# the same names with other contents (another include, texture and model):
# the image is glint's either way, through glint-mpi and through the C API
# (examples/embed_mpi.c). A scene on standard input and an image on
# standard output are glint's too, as are --check and --print-scene (rank
# 0's alone). Skipped (exit 77) without glint-mpi or mpirun.
# Usage: mpi_files.sh PATH/TO/glint
source "$(dirname "$0")/lib/harness.sh"
source "$(dirname "$0")/lib/mpi.sh"

# scene DIR COLOR SIZE: a scene in DIR/assets whose include, texture and
# model (with its MTL file) lie in folders below it, each given COLOR (an
# RGB list) or, for the model, a triangle of SIZE.
scene() {
    local dir=$1/assets color=$2 size=$3
    mkdir -p "$dir/parts" "$dir/maps" "$dir/models"
    cat >"$dir/scene.yaml" <<YAML
glint: 1
include: parts/looks.yaml
settings: { width: 320, height: 240, samples: 4 }
camera: { position: [0, 1, 4], look_at: [0, 0.5, 0], fov: 50 }
lights:
  - { type: point, position: [2, 4, 3] }
objects:
  - { type: plane, normal: [0, 1, 0], material: floor }
  - { type: sphere, center: [-1, 0.7, 0], radius: 0.6, material: globe }
  - { type: mesh, file: models/tri.obj }
YAML
    cat >"$dir/parts/looks.yaml" <<YAML
textures:
  moon: { type: image, file: ../maps/moon.jpg, mapping: spherical }
materials:
  globe: { texture: moon }
  floor: { color: $color }
YAML
    printf 'mtllib tri.mtl\nusemtl paint\nv 0 0 0\nv %s 0 0\nv 0.5 %s -0.5\nf 1 2 3\n' "$size" "$size" \
        >"$dir/models/tri.obj"
    printf 'newmtl paint\nKd %s\n' "$(tr -d '[],' <<<"$color")" >"$dir/models/tri.mtl"
}

mkdir -p lead decoy empty
scene lead "[0.8, 0.3, 0.2]" 1.5
cp "$here/assets/moon.jpg" lead/assets/maps/moon.jpg
scene decoy "[0.2, 0.8, 0.3]" 0.7
"$GLINT" -w 40 -h 30 -q -o decoy/assets/maps/moon.jpg.png && mv decoy/assets/maps/moon.jpg.png decoy/assets/maps/moon.jpg
(cd lead && "$GLINT" assets/scene.yaml -q -o ../glint.png)
(cd decoy && "$GLINT" assets/scene.yaml -q -o ../decoy.png)
! cmp -s glint.png decoy.png
verdict $? "the decoys make another image"

# others DIR N: the scene on rank 0 in lead/ and N more ranks in DIR, one
# thread each; true when the image is glint's and the other ranks
# rendered some of its tiles (the summary's busy list says how many). At
# 64 samples a pixel rank 0 alone takes about a second: at the scene's 4
# (0.08 s) it once finished every tile before the others, starting beside
# other tests on two cores, had asked for one.
(cd lead && "$GLINT" assets/scene.yaml --spp 64 -q -o ../glint-64.png)
others() {
    rm -f lead/out.png
    timeout "$limit" mpirun --oversubscribe -np 1 --wdir lead "$GLINT_MPI" assets/scene.yaml --spp 64 --threads 1 \
        -o out.png : -np "$2" --wdir "$1" "$GLINT_MPI" assets/scene.yaml --spp 64 --threads 1 -o out.png \
        >mpi.log 2>&1 && cmp -s glint-64.png lead/out.png && grep -qE 'rank [1-9][0-9]* [0-9]+% \([1-9]' mpi.log
}
others decoy 2
verdict $? "ranks among decoys render rank 0's files: glint's bytes; $(tail -c 300 mpi.log)"
[ ! -e decoy/out.png ]
verdict $? "only rank 0 writes the image"
others empty 3
verdict $? "ranks without the files render rank 0's: glint's bytes; $(tail -c 300 mpi.log)"

# A C program through libglint_mpi (examples/embed_mpi.c), built beside
# glint: the same bytes, from rank 0's files; a scene missing fails every
# rank alike.
EMBED_MPI=$(dirname "$GLINT")/embed_mpi
rm -f lead/out.png
timeout "$limit" mpirun --oversubscribe -np 1 --wdir lead "$EMBED_MPI" assets/scene.yaml out.png : \
    -np 2 --wdir decoy "$EMBED_MPI" assets/scene.yaml out.png >mpi.log 2>&1
st=$?
[ "$st" -eq 0 ] && cmp -s glint.png lead/out.png && [ ! -e decoy/out.png ]
verdict $? "embed_mpi renders rank 0's files across 3 ranks: glint's bytes (exit $st: $(head -c 300 mpi.log))"
timeout "$limit" mpirun --oversubscribe -np 3 "$EMBED_MPI" no-such.yaml out.png >mpi.log 2>&1
st=$?
[ "$st" -eq 1 ] && [ "$(grep -c "rank [012]: cannot read scene 'no-such.yaml': No such file or directory" mpi.log)" -eq 3 ]
verdict $? "embed_mpi with a scene missing: every rank fails with rank 0's message (exit $st: $(head -c 300 mpi.log))"

# The scene on standard input, the image on standard output.
scene_file=$here/scenes/shapes.yaml
"$GLINT" - -w 64 -h 48 -q -o - <"$scene_file" >glint-stdio.png
mpi 3 - -w 64 -h 48 -q -o - <"$scene_file" >mpi-stdio.png 2>mpi.log
st=$?
[ "$st" -eq 0 ] && [ -s glint-stdio.png ] && cmp -s glint-stdio.png mpi-stdio.png
verdict $? "a scene on standard input, the image on standard output: glint's bytes (exit $st: $(head -c 400 mpi.log))"
printf 'glint: 1\nsettings: { width: 16, heigth: 8 }\n' >bad.yaml
"$GLINT" - -q -o out.png <bad.yaml 2>glint.err
mpi 2 - -q -o out.png <bad.yaml 2>mpi.err
st=$?
[ "$st" -eq 1 ] && [ ! -e out.png ] && [ "$(grep -cxFf glint.err mpi.err)" -eq "$(wc -l <glint.err)" ] &&
    [ "$(grep -c '<stdin>:2' mpi.err)" -eq 1 ]
verdict $? "a bad scene on standard input: glint's message once, exit 1 ($st)"

# --check and --print-scene: what glint prints, once.
for flag in --check --print-scene; do
    "$GLINT" "$flag" lead/assets/scene.yaml >glint.out 2>&1
    gst=$?
    mpi 3 "$flag" lead/assets/scene.yaml >mpi.out 2>&1
    st=$?
    [ "$st" -eq "$gst" ] && [ "$gst" -eq 0 ] && cmp -s glint.out mpi.out
    verdict $? "glint-mpi $flag prints what glint prints, once (exit $st)"
done

finish
