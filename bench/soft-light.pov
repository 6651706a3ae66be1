// soft-light.pov - POV-Ray 3.7 copy of bench/soft-light.yaml for bench/equal-noise.sh: the same
// room, ball, block and 2 x 2 square lamp (an area_light of LIGHT_N x LIGHT_N jittered
// points, centred on its location as POV-Ray centres them), made to give glint's image
// (the floor and the ball agree within 3%), as bench/cornell-box.pov says how: spotlights
// falling as the cosine for glint's Lambertian lamp, the inverse square (fade_distance
// 0.01), its intensity 3 times its area 4 over pi and 2 d^2, and the lamp seen
// (looks_like), as glint's is. glint's colours are sRGB, here made linear. This lamp is
// large: area_illumination is on, as without it POV-Ray shades by the direction to the
// lamp's centre alone, and leaves the block's front, which that direction grazes, black
// (it is then about 1.6 times as fast).
// Where a point sees the lamp at a slant (the block's front, the wall above the ball)
// POV-Ray's light is 16-47% weaker than the integral over the lamp, which glint's
// matches within 0.5%.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 5 }
camera { perspective location <0, 2, 6> look_at <0, 0.7, 0> right -x*image_width/image_height angle 45*image_width/image_height }
light_source { <0, 3, 0> color rgb 3 * 4 / (pi * 2 * 0.01 * 0.01)
  spotlight point_at <0, 0, 0> radius 90 falloff 90 tightness 1
  area_light <2, 0, 0>, <0, 0, 2>, LIGHT_N, LIGHT_N jitter area_illumination on
  fade_distance 0.01 fade_power 2
  looks_like { box { <-1, -0.001, -1>, <1, 0, 1> texture { pigment { rgb 1 } finish { emission 1 ambient 0 diffuse 0 } } } } }
#declare White = texture { pigment { rgb 0.6038 } finish { diffuse 1 ambient 0 specular 0 } }
plane { y, 0 texture { White } }
plane { z, -2 texture { White } }
sphere { <0, 0.7, 0>, 0.7 texture { pigment { rgb <0.6038, 0.0732, 0.0331> } finish { diffuse 1 ambient 0 } } }
box { <-1.6, 0, -0.6>, <-1.0, 1.2, 0> texture { White } }
