#!/usr/bin/env bash
# Soft shadows, depth of field, shapes and patterns against an independent
# renderer, POV-Ray 3.7, at thumbnail scale: each scene is rendered by both
# at 96x72 (16 bits a channel, sRGB), shrunk by averaging 2x2 or 4x4
# pixels, and compared by ImageMagick's mean and peak absolute error (as a
# share of full scale).
#
# - Soft shadow: glint's sphere light (radius 0.8, 1024 samples) against
#   POV-Ray's `area_light` of 32x32 jittered points on a disc of the same
#   radius turned to face each point (`circular orient`). Both light a white
#   floor and a ball; POV-Ray's fade_power 2 with a short fade_distance is
#   the inverse square a sphere light has, its colour r^2 / (2 fade^2) times
#   the sphere's radiance. The floor around the shadow, umbra and penumbra,
#   must agree. (A lamp 25% smaller in POV-Ray puts the peak error at 12%.)
# - Depth of field: glint's thin lens (aperture 0.15, 256 Sobol samples)
#   against POV-Ray's focal_blur (256 blur_samples, no early stop), focused
#   on look_at. POV-Ray's aperture is four times the lens's radius (measured
#   from a point's blur circle: 0.25 of its aperture at every fov, focus and
#   size tried). Three balls before, at and past the focus must blur alike.
#   (An aperture 25% smaller puts the peak error at 6%, here under 1%.)
# - The Cornell box lit by its own lamp (when ../shared/data has it):
#   scenes/models/cornell-box.yaml (1024 samples of the emissive quad)
#   against bench/cornell-box.pov, whose 32x32 spotlights falling as the
#   cosine are a Lambertian lamp, its power worked out from the MTL's Ke,
#   not tuned. Floor, walls, blocks and penumbrae must agree; the corner
#   where the right wall meets the floor is left out, as the two renderers'
#   one ray a pixel fall on either side of that edge. (The lamp 10% brighter
#   in POV-Ray puts the mean error at 0.5%, here 0.1%.)
# - A torus and a CSG difference (a box with a ball's bite out of it), matte
#   under a point light with hard shadows, one ray a pixel: the same
#   surfaces and normals give the same pixels to within a few parts in a
#   million on average. (The bite's ball 7% smaller in POV-Ray puts the mean
#   error at 0.06% and the peak at 6%; the torus's tube 12% thinner, 0.6%
#   and 19%.)
# - Marble and wood without turbulence, each through a two-colour map, lit
#   by ambient light alone: glint's marble, 0.5 - 0.5 cos(2 pi x / scale),
#   is POV-Ray's `marble sine_wave` moved a quarter period; its wood, the
#   fraction of the distance from the y axis over scale, POV-Ray's `wood
#   ramp_wave` turned from the z axis. The same patterns give the same
#   pixels to a few parts in a hundred thousand. (Marble's scale 5% larger
#   in POV-Ray puts the mean error at 5% and the peak at 51%; wood's, 5%
#   and 34%.)
# Usage: povray.sh PATH/TO/glint
root=$(cd "$(dirname "$0")/../.." && pwd)
shared=$root/../shared/data
source "$root/tests/cli/lib/harness.sh"

# POV-Ray's horizontal angle for glint's vertical fov of 40 degrees at 4:3.
ANGLE=51.77400875924256

# render NAME: glint renders NAME.yaml to NAME-glint.ppm, POV-Ray NAME.pov
# to NAME-povray.ppm (POV-Ray reads and writes only in the working folder,
# which Debian's povray.conf allows under /tmp).
render() {
    "$GLINT" "$1.yaml" --bit-depth 16 -q -o "$1-glint.ppm" &&
        povray -D "+I$1.pov" "+O$1-povray.ppm" +FP16 +W96 +H72 -A File_Gamma=sRGB >"$1-povray.log" 2>&1 ||
        { sed 's/^/  /' "$1-povray.log"; return 1; }
}

# close NAME CROP SCALE MAE PAE: the CROP (ImageMagick geometry) of both
# images, shrunk to SCALE, differ by at most MAE on average and PAE at the
# worst pixel.
close() {
    local name=$1 crop=$2 scale=$3 mae pae
    convert "$name-glint.ppm" -crop "$crop" +repage -scale "$scale" glint-t.ppm &&
        convert "$name-povray.ppm" -crop "$crop" +repage -scale "$scale" povray-t.ppm || return 1
    mae=$(compare -metric MAE glint-t.ppm povray-t.ppm null: 2>&1 | sed 's/.*(\(.*\))/\1/')
    pae=$(compare -metric PAE glint-t.ppm povray-t.ppm null: 2>&1 | sed 's/.*(\(.*\))/\1/')
    echo "  $name $crop at $scale: mean error $mae (at most $4), peak $pae (at most $5)"
    awk -v m="$mae" -v p="$pae" -v mm="$4" -v pp="$5" 'BEGIN { exit !(m <= mm && p <= pp) }'
}

cat >soft.yaml <<'EOF'
glint: 1
settings: { width: 96, height: 72, samples: 1, ambient: [0, 0, 0], background: [0, 0, 0] }
camera: { position: [0, 4, 5], look_at: [0, 0.4, 0], fov: 40 }
materials:
  white: { color: [1, 1, 1], specular: 0, ambient: 0 }
lights:
  - { type: sphere, position: [0.8, 5, 0.4], radius: 0.8, intensity: 25, samples: 1024 }
objects:
  - { type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: white }
  - { type: sphere, center: [0, 0.9, 0], radius: 0.5, material: white }
EOF
cat >soft.pov <<EOF
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 }
camera { perspective location <0, 4, -5> look_at <0, 0.4, 0> right x*4/3 up y angle $ANGLE }
background { rgb 0 }
// 25 * 0.8^2 / (2 * 0.05^2) = 3200
light_source { <0.8, 5, -0.4> color rgb 3200
  area_light <1.6, 0, 0>, <0, 0, 1.6>, 32, 32 jitter circular orient
  fade_distance 0.05 fade_power 2 }
#declare White = texture { pigment { rgb 1 } finish { ambient 0 diffuse 1 specular 0 phong 0 } }
plane { y, 0 texture { White } }
sphere { <0, 0.9, 0>, 0.5 texture { White } }
EOF

cat >dof.yaml <<'EOF'
glint: 1
settings: { width: 96, height: 72, samples: 256, sampler: sobol, ambient: [0, 0, 0],
            background: {linear: [0.2, 0.3, 0.5]} }
camera: { type: thin_lens, position: [0, 1, 6], look_at: [0, 0.5, 0], fov: 40, aperture: 0.15 }
materials:
  grey: { color: {linear: [0.5, 0.5, 0.5]}, specular: 0, ambient: 0 }
  red: { color: {linear: [0.8, 0.1, 0.05]}, specular: 0, ambient: 0 }
  green: { color: {linear: [0.1, 0.6, 0.1]}, specular: 0, ambient: 0 }
  blue: { color: {linear: [0.1, 0.2, 0.8]}, specular: 0, ambient: 0 }
lights:
  - { type: point, position: [4, 6, 6], color: {linear: [1, 1, 1]} }
objects:
  - { type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: grey }
  - { type: sphere, center: [-0.9, 0.5, 3], radius: 0.5, material: red }
  - { type: sphere, center: [0, 0.5, 0], radius: 0.5, material: green }
  - { type: sphere, center: [1.1, 0.5, -4], radius: 0.5, material: blue }
EOF
cat >dof.pov <<EOF
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 }
camera { perspective location <0, 1, -6> look_at <0, 0.5, 0> right x*4/3 up y angle $ANGLE
  aperture 0.6 blur_samples 256 focal_point <0, 0.5, 0> confidence 0.9 variance 0 }
background { rgb <0.2, 0.3, 0.5> }
light_source { <4, 6, -6> color rgb 1 }
#declare Matte = finish { ambient 0 diffuse 1 specular 0 phong 0 }
plane { y, 0 pigment { rgb 0.5 } finish { Matte } }
sphere { <-0.9, 0.5, -3>, 0.5 pigment { rgb <0.8, 0.1, 0.05> } finish { Matte } }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.1, 0.6, 0.1> } finish { Matte } }
sphere { <1.1, 0.5, 4>, 0.5 pigment { rgb <0.1, 0.2, 0.8> } finish { Matte } }
EOF

cat >shapes.yaml <<'EOF'
glint: 1
settings: { width: 96, height: 72, samples: 1, ambient: [0, 0, 0], background: [0, 0, 0] }
camera: { position: [0, 3, 5], look_at: [0, 0.4, 0], fov: 40 }
materials:
  white: { color: {linear: [0.8, 0.8, 0.8]}, specular: 0, ambient: 0 }
lights:
  - { type: point, position: [3, 6, 4], color: {linear: [1, 1, 1]} }
objects:
  - { type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: white }
  - { type: torus, center: [-1.1, 0.25, 0.2], major_radius: 0.8, minor_radius: 0.25, material: white }
  - type: difference
    material: white
    objects:
      - { type: box, min: [0.4, 0, -0.6], max: [1.6, 1.2, 0.6] }
      - { type: sphere, center: [1.6, 1.2, 0.6], radius: 0.75 }
EOF
cat >shapes.pov <<EOF
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 }
camera { perspective location <0, 3, -5> look_at <0, 0.4, 0> right x*4/3 up y angle $ANGLE }
background { rgb 0 }
light_source { <3, 6, -4> color rgb 1 }
#declare White = texture { pigment { rgb 0.8 } finish { ambient 0 diffuse 1 specular 0 phong 0 } }
plane { y, 0 texture { White } }
torus { 0.8, 0.25 translate <-1.1, 0.25, -0.2> texture { White } }
difference {
  box { <0.4, 0, -0.6>, <1.6, 1.2, 0.6> }
  sphere { <1.6, 1.2, -0.6>, 0.75 }
  texture { White }
}
EOF

cat >patterns.yaml <<'EOF'
glint: 1
settings: { width: 96, height: 72, samples: 1, ambient: [1, 1, 1], background: [0, 0, 0] }
camera: { position: [0, 3, 5], look_at: [0, 0.4, 0], fov: 40 }
textures:
  marble: { type: marble, scale: 0.6, turbulence: 0,
            colors: [[0, {linear: [0.9, 0.85, 0.8]}], [1, {linear: [0.1, 0.12, 0.2]}]] }
  wood: { type: wood, scale: 0.35, turbulence: 0,
          colors: [[0, {linear: [0.8, 0.5, 0.2]}], [1, {linear: [0.3, 0.12, 0.05]}]] }
materials:
  marble: { texture: marble, ambient: 1, diffuse: 0, specular: 0 }
  wood: { texture: wood, ambient: 1, diffuse: 0, specular: 0 }
objects:
  - { type: box, min: [-4, -0.1, -6], max: [0, 0, 3], material: marble }
  - { type: box, min: [0, -0.1, -6], max: [4, 0, 3], material: wood }
EOF
cat >patterns.pov <<EOF
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }
camera { perspective location <0, 3, -5> look_at <0, 0.4, 0> right x*4/3 up y angle $ANGLE }
background { rgb 0 }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 }
box { <-4, -0.1, -3>, <0, 0, 6>
  pigment { marble sine_wave color_map { [0 rgb <0.9, 0.85, 0.8>] [1 rgb <0.1, 0.12, 0.2>] }
            scale 0.6 translate x*0.15 }
  finish { Flat } }
box { <0, -0.1, -3>, <4, 0, 6>
  pigment { wood ramp_wave color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.3, 0.12, 0.05>] } scale 0.35 rotate x*90 }
  finish { Flat } }
EOF

if ! command -v povray >/dev/null || ! command -v compare >/dev/null; then
    echo "skipped: povray or ImageMagick is not installed (Debian: povray imagemagick)"
    exit 77
fi
check "glint and POV-Ray render the soft shadow" render soft
# The floor below the ball: the shadow's umbra and penumbra, at 2x2.
check "the soft shadow's umbra and penumbra match POV-Ray's" close soft 96x32+0+36 50% 0.0012 0.06
# The whole picture at 4x4: the lit ball too.
check "the soft-shadow scene matches POV-Ray's at 24x18" close soft 96x72+0+0 25% 0.0015 0.08
check "glint and POV-Ray render the depth of field" render dof
check "the depth of field matches POV-Ray's focal_blur at 24x18" close dof 96x72+0+0 25% 0.0015 0.02
check "the depth of field matches POV-Ray's focal_blur at 48x36" close dof 96x72+0+0 50% 0.002 0.04
check "glint and POV-Ray render the torus and the CSG difference" render shapes
check "the torus and the difference match POV-Ray's at 24x18" close shapes 96x72+0+0 25% 0.0002 0.01
check "the torus and the difference match POV-Ray's at 96x72" close shapes 96x72+0+0 100% 0.0002 0.01
check "glint and POV-Ray render marble and wood" render patterns
check "marble and wood match POV-Ray's at 24x18" close patterns 96x72+0+0 25% 0.0001 0.001
check "marble and wood match POV-Ray's at 96x72" close patterns 96x72+0+0 100% 0.0001 0.001

# render_cornell: the Cornell box by both at 96x96 into cornell-*.ppm.
render_cornell() {
    sed -e 's/emission_samples: [0-9]*/emission_samples: 1024/' -e "s|file: [./]*shared/data/|file: $shared/|" \
        "$root/scenes/models/cornell-box.yaml" >cornell.yaml &&
        cp "$root/bench/cornell-box.pov" cornell.pov &&
        "$GLINT" cornell.yaml --spp 1 -w 96 -h 96 --bit-depth 16 -q -o cornell-glint.ppm &&
        povray -D +Icornell.pov +Ocornell-povray.ppm +FP16 +W96 +H96 -A Declare=LIGHT_N=32 File_Gamma=sRGB \
            >cornell-povray.log 2>&1 || { sed 's/^/  /' cornell-povray.log; return 1; }
}
if [ -f "$shared/CornellBox-Original.obj" ]; then
    check "glint and POV-Ray render the Cornell box" render_cornell
    check "the Cornell box's top matches POV-Ray's at 24x19" close cornell 96x78+0+0 25% 0.0025 0.02
    check "the Cornell box's left matches POV-Ray's at 19x24" close cornell 78x96+0+0 25% 0.0025 0.02
else
    echo "skipped the Cornell box: $shared/CornellBox-Original.obj is absent"
fi
finish
