// cornell-box.pov - POV-Ray 3.7 copy of the Cornell box for bench/equal-noise.sh:
// ../shared/data/CornellBox-Original.obj's triangles (z negated: POV-Ray's axes are
// left-handed) in its MTL's colours made linear, lit by an area light of LIGHT_N x
// LIGHT_N jittered points on the ceiling lamp, where glint lights the box by the
// lamp's own emission (Ke 17 12 4). The light is made to give glint's image, not
// POV-Ray's defaults' (the means of floor, walls and ceiling agree within 5%):
// - glint's lamp is a Lambertian emitter: the points are spotlights pointing down
//   whose intensity falls as the cosine (tightness 1, radius and falloff 90);
// - its light falls as the inverse square: fade_power 2 with a fade_distance d
//   much smaller than the box, where POV-Ray's 2 / (1 + (r / d)^2) is 2 d^2 / r^2;
// - its brightness is Ke times the exposure (2^1) times the lamp's area, over
//   pi (glint's radiance convention, docs/scene-format.md) and over 2 d^2;
// - area_illumination stays off (POV-Ray shades by the direction to the lamp's
//   centre alone): with a lamp this small the image is the same within 1%, and
//   POV-Ray is 3.5 times as fast as with it on;
// - glint's lamp lights its lit side only: the ceiling, 1 cm above it, gets
//   ambient light alone (diffuse 0);
// - the ambient is glint's: its scene colours are sRGB, so its ambient 0.25 is
//   0.0508 linear, doubled by the exposure (the finishes' ambient 0.2 is glint's
//   materials').
// Noise is compared relative to each renderer's own reference's mean.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.1016 max_trace_level 5 }
camera { perspective location <0, 1, -3.9> look_at <0, 1, 0> right x*image_width/image_height angle 37 }
light_source { <-0.005, 1.98, 0.03> color rgb <17, 12, 4> * 2 * 0.47 * 0.38 / (pi * 2 * 0.01 * 0.01)
  spotlight point_at <-0.005, 0, 0.03> radius 90 falloff 90 tightness 1
  area_light <0.47, 0, 0>, <0, 0, 0.38>, LIGHT_N, LIGHT_N jitter
  fade_distance 0.01 fade_power 2 }
#declare Matte = finish { ambient 0.2 diffuse 1 specular 0 }
#declare T_floor = texture { pigment { rgb <0.4844, 0.4624, 0.4200> } finish { Matte } }
#declare T_ceiling = texture { pigment { rgb <0.4844, 0.4624, 0.4200> } finish { ambient 0.2 diffuse 0 specular 0 } }
#declare T_backWall = texture { T_floor }
#declare T_leftWall = texture { pigment { rgb <0.3547, 0.0054, 0.0039> } finish { Matte } }
#declare T_rightWall = texture { pigment { rgb <0.0174, 0.1706, 0.0087> } finish { Matte } }
#declare T_shortBox = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 phong 0.725 phong_size 200 } }
#declare T_tallBox = texture { T_shortBox }
#declare T_light = texture { pigment { rgb <17, 12, 4> } finish { emission 1 ambient 0 diffuse 0 } }
mesh { // floor
  triangle { <-1.01, 0, -0.99>, <1, 0, -0.99>, <1, 0, 1.04> }
  triangle { <-1.01, 0, -0.99>, <1, 0, 1.04>, <-0.99, 0, 1.04> }
  texture { T_floor } }
mesh { // ceiling
  triangle { <-1.02, 1.99, -0.99>, <-1.02, 1.99, 1.04>, <1, 1.99, 1.04> }
  triangle { <-1.02, 1.99, -0.99>, <1, 1.99, 1.04>, <1, 1.99, -0.99> }
  texture { T_ceiling } }
mesh { // backWall
  triangle { <-0.99, 0, 1.04>, <1, 0, 1.04>, <1, 1.99, 1.04> }
  triangle { <-0.99, 0, 1.04>, <1, 1.99, 1.04>, <-1.02, 1.99, 1.04> }
  texture { T_backWall } }
mesh { // rightWall
  triangle { <1, 0, 1.04>, <1, 0, -0.99>, <1, 1.99, -0.99> }
  triangle { <1, 0, 1.04>, <1, 1.99, -0.99>, <1, 1.99, 1.04> }
  texture { T_rightWall } }
mesh { // leftWall
  triangle { <-1.01, 0, -0.99>, <-0.99, 0, 1.04>, <-1.02, 1.99, 1.04> }
  triangle { <-1.01, 0, -0.99>, <-1.02, 1.99, 1.04>, <-1.02, 1.99, -0.99> }
  texture { T_leftWall } }
mesh { // shortBox
  triangle { <0.53, 0.6, -0.75>, <0.7, 0.6, -0.17>, <0.13, 0.6, -0> }
  triangle { <0.53, 0.6, -0.75>, <0.13, 0.6, -0>, <-0.05, 0.6, -0.57> }
  triangle { <-0.05, 0, -0.57>, <-0.05, 0.6, -0.57>, <0.13, 0.6, -0> }
  triangle { <-0.05, 0, -0.57>, <0.13, 0.6, -0>, <0.13, 0, -0> }
  triangle { <0.53, 0, -0.75>, <0.53, 0.6, -0.75>, <-0.05, 0.6, -0.57> }
  triangle { <0.53, 0, -0.75>, <-0.05, 0.6, -0.57>, <-0.05, 0, -0.57> }
  triangle { <0.7, 0, -0.17>, <0.7, 0.6, -0.17>, <0.53, 0.6, -0.75> }
  triangle { <0.7, 0, -0.17>, <0.53, 0.6, -0.75>, <0.53, 0, -0.75> }
  triangle { <0.13, 0, -0>, <0.13, 0.6, -0>, <0.7, 0.6, -0.17> }
  triangle { <0.13, 0, -0>, <0.7, 0.6, -0.17>, <0.7, 0, -0.17> }
  triangle { <0.13, 0, -0>, <0.7, 0, -0.17>, <0, 0, 0> }
  triangle { <0.53, 0, -0.75>, <0.7, 0, -0.17>, <0.13, 0, -0> }
  triangle { <0.53, 0, -0.75>, <0.13, 0, -0>, <-0.05, 0, -0.57> }
  texture { T_shortBox } }
mesh { // tallBox
  triangle { <-0.53, 1.2, -0.09>, <0.04, 1.2, 0.09>, <-0.14, 1.2, 0.67> }
  triangle { <-0.53, 1.2, -0.09>, <-0.14, 1.2, 0.67>, <-0.71, 1.2, 0.49> }
  triangle { <-0.53, 0, -0.09>, <-0.53, 1.2, -0.09>, <-0.71, 1.2, 0.49> }
  triangle { <-0.53, 0, -0.09>, <-0.71, 1.2, 0.49>, <-0.71, 0, 0.49> }
  triangle { <-0.71, 0, 0.49>, <-0.71, 1.2, 0.49>, <-0.14, 1.2, 0.67> }
  triangle { <-0.71, 0, 0.49>, <-0.14, 1.2, 0.67>, <-0.14, 0, 0.67> }
  triangle { <-0.14, 0, 0.67>, <-0.14, 1.2, 0.67>, <0.04, 1.2, 0.09> }
  triangle { <-0.14, 0, 0.67>, <0.04, 1.2, 0.09>, <0.04, 0, 0.09> }
  triangle { <0.04, 0, 0.09>, <0.04, 1.2, 0.09>, <-0.53, 1.2, -0.09> }
  triangle { <0.04, 0, 0.09>, <-0.53, 1.2, -0.09>, <-0.53, 0, -0.09> }
  triangle { <-0.53, 0, -0.09>, <0.04, 0, 0.09>, <-0.14, 0, 0.67> }
  triangle { <-0.53, 0, -0.09>, <-0.14, 0, 0.67>, <-0.71, 0, 0.49> }
  texture { T_tallBox } }
mesh { // light: seen, casting no shadow
  triangle { <-0.24, 1.98, -0.16>, <-0.24, 1.98, 0.22>, <0.23, 1.98, 0.22> }
  triangle { <-0.24, 1.98, -0.16>, <0.23, 1.98, 0.22>, <0.23, 1.98, -0.16> }
  texture { T_light } no_shadow }
