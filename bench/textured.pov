// bench/textured.pov - bench/textured.yaml for POV-Ray 3.7: a tiled Moon
// floor, a Moon-mapped ball, and balls of marble, wood, granite and bozo
// with six octaves of turbulence. Anti-aliasing as the seed room: +AM1
// +A0.0 +R2 (2x2 a pixel). Needs moon.jpg beside it.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.2 max_trace_level 5 }
camera { perspective location <0, 3, -7> look_at <0, 0.6, 0> right x up y angle 40 }
background { rgb <0.2, 0.25, 0.3> }
light_source { <4, 8, -6> color rgb 1 }
#declare Shiny = finish { ambient 1 diffuse 1 phong 0.5 phong_size 60 }
plane { y, 0
  texture { pigment { image_map { jpeg "moon.jpg" interpolate 2 } rotate x*90 scale 1.5 }
            finish { ambient 1 diffuse 1 } } }
sphere { <-2.4, 0.7, 0>, 0.7
  texture { pigment { marble turbulence 1 octaves 6 omega 0.5 lambda 2
                      color_map { [0 rgb <0.9, 0.88, 0.85>] [0.8 rgb <0.6, 0.58, 0.55>] [1 rgb <0.1, 0.1, 0.12>] }
                      scale 0.5 }
            finish { Shiny } } }
sphere { <-0.8, 0.7, -0.6>, 0.7
  texture { pigment { wood turbulence 0.3 octaves 6 omega 0.5 lambda 2
                      color_map { [0 rgb <0.6, 0.35, 0.15>] [1 rgb <0.3, 0.15, 0.05>] } scale 0.12 rotate x*90 }
            finish { Shiny } } }
sphere { <0.8, 0.7, -0.6>, 0.7
  texture { pigment { granite octaves 6 omega 0.5 lambda 2
                      color_map { [0 rgb <0.8, 0.78, 0.75>] [0.5 rgb <0.4, 0.38, 0.36>] [1 rgb 0.05] } scale 0.5 }
            finish { Shiny } } }
sphere { <2.4, 0.7, 0>, 0.7
  texture { pigment { bozo turbulence 0 octaves 6 omega 0.5 lambda 2
                      color_map { [0 rgb <0.1, 0.2, 0.6>] [1 rgb 0.95] } scale 0.3 }
            finish { Shiny } } }
sphere { <0, 0.9, 1.6>, 0.9
  texture { pigment { image_map { jpeg "moon.jpg" map_type 1 interpolate 2 } }
            finish { ambient 1 diffuse 1 phong 0.3 phong_size 40 } } }
