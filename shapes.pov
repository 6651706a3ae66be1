#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0 }
camera { perspective location <0, 3, -5> look_at <0, 0.4, 0> right x*4/3 up y angle  }
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
