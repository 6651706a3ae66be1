#!/usr/bin/env bash
# Files in and out, the cases that need files made at run time (FIFOs,
# links, modes) rather than kept in tests/bad/: no input that is not a
# regular file is ever opened in a way that blocks (a FIFO as a scene, an
# include, a texture, a model, an MTL file, a glTF buffer: each refused
# within seconds); a missing MTL file is a warning, one that exists but
# cannot be read an error; an output naming one of the run's own inputs is
# refused before rendering, the input untouched; a replaced image keeps its
# mode; a link as the output has its target replaced; a legal 250-character
# name is written; glTF buffers larger than half the memory, alone or
# together, are refused before they are read.
# Usage: files.sh PATH/TO/glint
. "$(dirname "$0")/lib/harness.sh"
small=(-w 8 -h 8 --spp 1 --quiet)

# expect CODE FIRST -- ARGS...: glint ARGS (killed after 10 s: a blocked
# open must fail the test, not hang it) exits with CODE and FIRST as the
# first line of stderr.
expect() {
    local code=$1 first=$2 status actual
    shift 3
    timeout 10 "$GLINT" "$@" 2>err >/dev/null
    status=$?
    actual=$(head -n 1 err)
    verdict "$([ "$status" -eq "$code" ] && [ "$actual" = "$first" ]; echo $?)" \
        "glint $*: expected exit $code: $first; got exit $status: $actual"
}

# A triangle whose glTF names its buffer `uri`.
gltf() { # URI FILE
    printf '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"buffers":[{"uri":"%s","byteLength":36}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]}\n' "$1" >"$2"
}
triangle='v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n'

mkfifo fifo
gltf fifo fifo-buffer.gltf
expect 1 "glint: fifo-buffer.gltf: cannot read buffer 'fifo': not a regular file" -- fifo-buffer.gltf "${small[@]}" -o a.png
printf 'include: fifo\n' >fifo-include.yaml
expect 1 "fifo-include.yaml:1:10: cannot include 'fifo': not a regular file" -- fifo-include.yaml "${small[@]}" -o a.png
expect 1 "glint: cannot read texture 'fifo': not a regular file" -- "${small[@]}" --texture moon=fifo -o a.png
ln -s fifo fifo.obj
expect 1 "glint: fifo.obj: cannot read: not a regular file" -- fifo.obj "${small[@]}" -o a.png
printf "mtllib fifo\n$triangle" >fifo-mtl.obj
expect 1 "glint: fifo-mtl.obj: MTL file: fifo: cannot read: not a regular file" -- fifo-mtl.obj "${small[@]}" -o a.png
ln -s fifo fifo.yaml
expect 1 "cannot read scene 'fifo.yaml': not a regular file" -- fifo.yaml "${small[@]}" -o a.png
check "no refused input wrote an image" [ ! -e a.png ]

# A buffer reached through a link out of the model's folder is outside it.
mkdir model
printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\77\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\77\0\0\0\0' >tri.bin
ln -s ../tri.bin model/tri.bin
gltf tri.bin model/linked.gltf
expect 1 "glint: model/linked.gltf: buffer 'model/tri.bin' lies outside the model's folder (a model may name only files in it or below it)" -- model/linked.gltf "${small[@]}" -o a.png
cp tri.bin model/own.bin
gltf own.bin model/own.gltf
expect 0 "" -- model/own.gltf "${small[@]}" -o a.png
check "a buffer in the model's folder is read" [ -s a.png ]
rm -f a.png

# Assimp reads a buffer whole: one larger than half the machine's memory
# (a sparse file, as large as the memory) is refused before a byte of it is
# read, and so is one that fits alone but not with the buffer before it.
memory=$(($(getconf _PHYS_PAGES) * $(getconf PAGESIZE)))
truncate -s "$memory" model/huge.bin
gltf huge.bin model/huge.gltf
expect 1 "glint: model/huge.gltf: buffer 'model/huge.bin' is too large to import: $memory bytes, which with the model come to more than half of this machine's memory ($memory bytes)" -- model/huge.gltf "${small[@]}" -o a.png
truncate -s $((memory / 3)) model/third-1.bin model/third-2.bin
printf '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}},{"attributes":{"POSITION":1}}]}],
"buffers":[{"uri":"third-1.bin","byteLength":36},{"uri":"third-2.bin","byteLength":36}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":1,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]}\n' >model/thirds.gltf
expect 1 "glint: model/thirds.gltf: buffer 'model/third-2.bin' is too large to import: $((memory / 3)) bytes, which with the model and the buffers before it come to more than half of this machine's memory ($memory bytes)" -- model/thirds.gltf "${small[@]}" -o a.png
rm -f model/huge.bin model/third-1.bin model/third-2.bin

# Only a missing MTL file may be skipped, with a warning; the image is made.
printf "mtllib none.mtl\n$triangle" >no-mtl.obj
expect 0 "glint: warning: no-mtl.obj: MTL file 'none.mtl' does not exist: its materials are grey" -- no-mtl.obj "${small[@]}" -o a.png
check "a model without its MTL file is still rendered" [ -s a.png ]
rm -f a.png
printf "mtllib dir.mtl\n$triangle" >dir-mtl.obj
mkdir dir.mtl
expect 1 "glint: dir-mtl.obj: MTL file: dir.mtl: cannot read: Is a directory" -- dir-mtl.obj "${small[@]}" -o a.png

# An output that names one of the run's inputs is refused before the
# render (exit 3), and the input is left as it was: the scene itself (a
# scene file may have any name), an include, a texture, a model, and any
# other name for them (a link, a "./").
printf 'settings: {width: 8, height: 8, samples: 1, output: self.png}\n' >self.png
cp self.png self.before
expect 3 "glint: will not write 'self.png': it is one of the files this scene was read from" -- self.png
check "a scene naming itself as output is untouched" cmp -s self.png self.before
"$GLINT" self.png --print-scene >printed.yaml
check "--print-scene of such a scene writes no image, so is not refused" cmp -s self.png self.before
printf 'include: part.png\n' >with-part.yaml
printf 'settings: {width: 8, height: 8, samples: 1}\n' >part.png
expect 3 "glint: will not write './part.png': it is one of the files this scene was read from" -- with-part.yaml -o ./part.png
"$GLINT" "${small[@]}" -o moon.png
printf 'textures: {moon: {type: image, file: moon.png}}\nsettings: {width: 8, height: 8, samples: 1}\n' >tex.yaml
ln -s moon.png moon-link.png
expect 3 "glint: will not write 'moon-link.png': it is one of the files this scene was read from" -- tex.yaml -o moon-link.png
expect 3 "glint: will not write 'moon.png': it is one of the files this scene was read from" -- "${small[@]}" --texture moon=moon.png -o moon.png
printf "$triangle" >model.png.obj
ln -s model.png.obj model-alias.png
expect 3 "glint: will not write 'model-alias.png': it is one of the files this scene was read from" -- model.png.obj "${small[@]}" -o model-alias.png
check "the model named as output is untouched" [ "$(cat model.png.obj)" = "$(printf "$triangle")" ]

# A replaced image keeps the old one's mode; a link as the output keeps
# being a link, its target replaced (one that does not exist yet, too).
printf 'old' >private.png
chmod 600 private.png
"$GLINT" "${small[@]}" -o private.png
check "a 0600 image stays 0600" [ "$(stat -c %a private.png)" = 600 ] && [ "$(head -c 4 private.png | tail -c 3)" = PNG ]
printf 'old' >target.png
ln -s target.png link.png
"$GLINT" "${small[@]}" -o link.png
check "a link as output has its target replaced" [ -L link.png ] && [ "$(head -c 4 target.png | tail -c 3)" = PNG ]
ln -s later.png dangling.png
"$GLINT" "${small[@]}" -o dangling.png
check "a link to no file yet makes that file" [ -L dangling.png ] && [ -s later.png ]

# A legal name of 250 characters is written: the temporary file then has
# a shorter name of its own, and none is left behind.
long=$(printf 'a%.0s' $(seq 246)).png
"$GLINT" "${small[@]}" -o "$long"
check "a 250-character output name is written" [ -s "$long" ]
check "no temporary file is left" [ -z "$(ls -A | grep tmp)" ]

finish
