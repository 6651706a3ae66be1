// soft-light.pov - POV-Ray 3.7 copy of bench/soft-light.yaml for bench/equal-noise.sh: the same
// room, ball, block and 2 x 2 square lamp (an area_light of LIGHT_N x LIGHT_N jittered
// points, centred on its location as POV-Ray centres them). Its brightness
// falls as fade_power 2, not exactly as an area light's; noise is compared
// relative to each renderer's own reference, so the brightness need not match.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 5 }
camera { perspective location <0, 2, 6> look_at <0, 0.7, 0> right -x*image_width/image_height angle 45*image_width/image_height }
light_source { <0, 3, 0> color rgb LIGHT_POWER
  area_light <2, 0, 0>, <0, 0, 2>, LIGHT_N, LIGHT_N jitter
  fade_distance 3 fade_power 2 }
#declare White = texture { pigment { rgb 0.8 } finish { diffuse 1 ambient 0 specular 0 } }
plane { y, 0 texture { White } }
plane { z, -2 texture { White } }
sphere { <0, 0.7, 0>, 0.7 texture { pigment { rgb <0.8, 0.3, 0.2> } finish { diffuse 1 ambient 0 } } }
box { <-1.6, 0, -0.6>, <-1.0, 1.2, 0> texture { White } }
