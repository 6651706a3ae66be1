#!/usr/bin/env bash
# tools/huge_scene.sh - writes a huge but legitimate scene file to standard
# output, for bench/huge.sh (speed and memory) and tests/cli/huge_scenes.sh
# (that it loads at all):
#
#   tools/huge_scene.sh spheres COUNT   COUNT spheres of radius 0.4 on a grid
#                                       1000 wide, one a line, in front of a
#                                       camera, under one point light
#   tools/huge_scene.sh nff-spheres COUNT
#                                       the same spheres as an NFF file,
#                                       1920x1080 (the SPD's format)
#   tools/huge_scene.sh names COUNT     COUNT checker textures and COUNT
#                                       materials, each naming a texture (in
#                                       reverse order), and one sphere
set -euo pipefail
[[ $# -eq 2 && "$2" =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 spheres|nff-spheres|names COUNT" >&2; exit 2; }
case $1 in
spheres)
    awk -v n="$2" 'BEGIN {
        print "camera: {position: [500, 500, 1400], look_at: [500, 500, 0], fov: 45}"
        print "lights: [{type: point, position: [500, 1500, 1000]}]"
        print "materials:\n  m: {color: [0.8, 0.3, 0.2]}\nobjects:"
        for (i = 0; i < n; i++)
            printf "- {type: sphere, material: m, center: [%d,%d,0], radius: .4}\n", i % 1000, int(i / 1000)
    }' ;;
nff-spheres)
    awk -v n="$2" 'BEGIN {
        print "v\nfrom 500 500 1400\nat 500 500 0\nup 0 1 0\nangle 45\nhither 0.01\nresolution 1920 1080"
        print "l 500 1500 1000\nf 0.8 0.3 0.2 1 0 0 0 1"
        for (i = 0; i < n; i++)
            printf "s %d %d 0 0.4\n", i % 1000, int(i / 1000)
    }' ;;
names)
    awk -v n="$2" 'BEGIN {
        print "textures:"
        for (i = 0; i < n; i++)
            printf "  t%d: {type: checker, size: %d}\n", i, i + 1
        print "materials:"
        for (i = 0; i < n; i++)
            printf "  m%d: {texture: t%d}\n", i, n - 1 - i
        print "objects: [{type: sphere, material: m0, radius: 1}]"
    }' ;;
*)
    echo "$0: no scene '$1' (spheres, nff-spheres or names)" >&2
    exit 2 ;;
esac
