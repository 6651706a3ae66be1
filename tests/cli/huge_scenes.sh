#!/usr/bin/env bash
# Huge but legitimate inputs load, each well inside a hang guard (20 s,
# times GLINT_TIME_SCALE under the sanitizers, where the code before issue
# 21 took minutes or refused them): 250,000 spheres, 100,000 lights and
# 60,000 placements of a model, which the alias limit once refused for
# their own nodes; 100,000 textures and materials, whose names were once
# looked up one by one; and faces of 100,000 corners, convex and zigzag,
# whose triangulation and normals once took minutes; 300,000 vertices of
# a PLY at one point, which Assimp's smoothing took minutes over; and the
# spheres' peak memory. Speed targets are in bench/huge.sh, not here.
# Usage: huge_scenes.sh PATH/TO/glint
TOOLS=$(cd "$(dirname "$0")/../../tools" && pwd)
source "$(dirname "$0")/lib/harness.sh"

# expect_ok FILE REPORT: glint --check FILE exits 0 within the guard and
# prints REPORT.
expect_ok() {
    local file=$1 report=$2 actual status
    actual=$(timeout $((20 * ${GLINT_TIME_SCALE:-1})) "$GLINT" --check "$file" 2>&1)
    status=$?
    [ "$status" -eq 0 ] && [ "$actual" = "$report" ]
    verdict $? "$file:
  expected exit 0: $report
  got      exit $status: $actual"
}

# grid COUNT WIDTH FORMAT: COUNT lines of FORMAT, the i-th filled with
# i % WIDTH and i / WIDTH (a grid of positions).
grid() {
    awk -v n="$1" -v w="$2" -v f="$3\n" 'BEGIN { for (i = 0; i < n; i++) printf f, i % w, int(i / w) }'
}

"$TOOLS/huge_scene.sh" spheres 250000 >spheres.yaml
expect_ok spheres.yaml "spheres.yaml: ok: 0 textures, 1 material, 1 shape (1 sphere set of 250000 spheres), 1 light"

# Their objects are read while the file is parsed, each sphere's nodes
# given back once read: the peak is the file and the spheres (a sphere
# set, 36 bytes each; 31 MB in all), not the 3 million nodes of its whole
# tree, which took 200 MB more. Memory is the same from run to run, unlike time; not
# measured under AddressSanitizer, whose shadow memory is most of it, nor
# without GNU time (Debian package 'time').
if ldd "$GLINT" 2>/dev/null | grep -q libasan; then
    echo "peak memory: skipped under AddressSanitizer"
elif ! /usr/bin/time -f %M true >/dev/null 2>&1; then
    echo "peak memory: skipped without GNU time"
else
    /usr/bin/time -f %M -o peak.txt "$GLINT" --check spheres.yaml >/dev/null 2>&1
    peak=$(tail -n 1 peak.txt)
    [ "$peak" -lt 80000 ]
    verdict $? "spheres.yaml: a peak of $peak KiB, expected under 80000 KiB (no whole tree of the objects)"
fi

{
    printf 'materials: {m: {}}\nobjects: [{type: sphere, material: m, radius: 1}]\nlights:\n'
    grid 100000 500 '- {type: point, position: [%d, %d, 5], intensity: 0.00001}'
} >lights.yaml
expect_ok lights.yaml "lights.yaml: ok: 0 textures, 1 material, 1 shape, 100000 lights"

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >tri.obj
{
    printf 'materials: {m: {}}\nobjects:\n'
    grid 60000 300 '- {type: mesh, file: tri.obj, material: m, transform: [{translate: [%d, %d, 0]}]}'
} >placements.yaml
expect_ok placements.yaml "placements.yaml: ok: 0 textures, 2 materials, 0 shapes, 0 lights, 1 mesh (1 triangle) placed 60000 times"

"$TOOLS/huge_scene.sh" names 100000 >names.yaml
expect_ok names.yaml "names.yaml: ok: 100000 textures, 100000 materials, 1 shape, 0 lights"

# One face of 100,000 corners on a circle, and one whose corners go in
# and out (every other one 1% nearer the centre), without normals.
for shape in convex zigzag; do
    awk -v zigzag=$([ $shape = zigzag ] && echo 1 || echo 0) 'BEGIN {
        n = 100000
        for (i = 0; i < n; i++) {
            r = zigzag && i % 2 ? 0.99 : 1
            printf "v %.9g %.9g 0\n", r * cos(6.283185307179586 * i / n), r * sin(6.283185307179586 * i / n)
        }
        printf "f"
        for (i = 1; i <= n; i++)
            printf " %d", i
        print ""
    }' >$shape.obj
    expect_ok $shape.obj "$shape.obj: ok: 1 texture, 2 materials, 1 shape, 2 lights, 1 mesh (99998 triangles) placed once"
done

# 300,000 vertices at one point (a PLY of 100,000 coincident triangles,
# without normals), whose smoothing by Assimp took minutes.
awk 'BEGIN {
    n = 100000
    printf "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n", 3 * n
    printf "element face %d\nproperty list uchar int vertex_indices\nend_header\n", n
    for (i = 0; i < n; i++)
        print "0 0 0\n1 0 0\n0 1 0"
    for (i = 0; i < n; i++)
        printf "3 %d %d %d\n", 3 * i, 3 * i + 1, 3 * i + 2
}' >coincident.ply
expect_ok coincident.ply "coincident.ply: ok: 1 texture, 2 materials, 1 shape, 2 lights, 1 mesh (100000 triangles) placed once"

finish
