// bench/csg.pov - bench/csg.yaml for POV-Ray 3.7: 16 dice of CSG.
// Anti-aliasing as the seed room: +AM1 +A0.0 +R2 (2x2 a pixel).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.1 max_trace_level 5 }
camera { perspective location <0, 6, -6> look_at <0, 0, 0> right x up y angle 40 }
background { rgb <0.2, 0.25, 0.3> }
light_source { <4, 8, -5> color rgb 1 }
#declare Ivory = texture { pigment { rgb <0.85, 0.8, 0.7> } finish { ambient 1 diffuse 1 phong 0.5 phong_size 40 } }
#declare Pip = texture { pigment { rgb 0.05 } finish { ambient 1 diffuse 1 phong 0.5 phong_size 40 } }
plane { y, 0 texture { pigment { rgb 0.5 } finish { ambient 1 diffuse 1 } } }
#declare Die = difference {
  intersection { box { <-0.4, -0.4, -0.4>, <0.4, 0.4, 0.4> } sphere { 0, 0.55 } texture { Ivory } }
  sphere { <0, 0.46, 0>, 0.09 texture { Pip } }
  sphere { <-0.2, 0.2, -0.46>, 0.09 texture { Pip } }
  sphere { <0.46, 0.1, -0.1>, 0.09 texture { Pip } }
}
object { Die rotate <0, 0, 0> translate <-1.8, 0.4, 1.8> }
object { Die rotate <0, -23, 0> translate <-1.8, 0.4, 0.6> }
object { Die rotate <0, -46, 0> translate <-1.8, 0.4, -0.6> }
object { Die rotate <0, -69, 0> translate <-1.8, 0.4, -1.8> }
object { Die rotate <0, -92, 0> translate <-0.6, 0.4, 1.8> }
object { Die rotate <0, -115, 0> translate <-0.6, 0.4, 0.6> }
object { Die rotate <0, -138, 0> translate <-0.6, 0.4, -0.6> }
object { Die rotate <0, -161, 0> translate <-0.6, 0.4, -1.8> }
object { Die rotate <0, -184, 0> translate <0.6, 0.4, 1.8> }
object { Die rotate <0, -207, 0> translate <0.6, 0.4, 0.6> }
object { Die rotate <0, -230, 0> translate <0.6, 0.4, -0.6> }
object { Die rotate <0, -253, 0> translate <0.6, 0.4, -1.8> }
object { Die rotate <0, -276, 0> translate <1.8, 0.4, 1.8> }
object { Die rotate <0, -299, 0> translate <1.8, 0.4, 0.6> }
object { Die rotate <0, -322, 0> translate <1.8, 0.4, -0.6> }
object { Die rotate <0, -345, 0> translate <1.8, 0.4, -1.8> }
