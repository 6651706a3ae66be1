// cornell-box.pov - POV-Ray 3.7 copy of the Cornell box for bench/equal-noise.sh:
// ../shared/data/CornellBox-Original.obj's triangles (z negated: POV-Ray's axes are
// left-handed) in its MTL's colours made linear, lit by an area light of LIGHT_N x
// LIGHT_N jittered points on the ceiling lamp, where glint lights the box by the
// lamp's own emission (Ke 17 12 4). fade_power 2 stands in for an area light's
// inverse square; the light is dimmed to look alike (POV-Ray's lamp has no cosine
// at its face), and glint's exposure 1 is folded into the ambient. Noise is
// compared against each renderer's own reference, so brightness need not match.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.5 max_trace_level 5 }
camera { perspective location <0, 1, -3.9> look_at <0, 1, 0> right x*image_width/image_height angle 37 }
light_source { <-0.005, 1.98, 0.03> color rgb <0.68, 0.48, 0.16>
  area_light <0.47, 0, 0>, <0, 0, 0.38>, LIGHT_N, LIGHT_N jitter
  fade_distance 1 fade_power 2 }
#declare Matte = finish { ambient 0.2 diffuse 1 specular 0 }
#declare T_floor = texture { pigment { rgb <0.4844, 0.4624, 0.4200> } finish { Matte } }
#declare T_ceiling = texture { T_floor }
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
