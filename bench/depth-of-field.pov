// depth-of-field.pov - POV-Ray 3.7 copy of scenes/depth-of-field.yaml for
// bench/equal-noise.sh: a row of spheres on a checkered floor through a lens
// focused on the third (the mirror), focal_blur with BLUR_N jittered lens samples a
// pixel where glint takes that many samples of its thin lens. glint's colours are
// display (sRGB) values, here made linear; z is negated (POV-Ray's axes are
// left-handed). POV-Ray's aperture is four times the lens's radius (measured; see
// tests/cli/povray.sh): glint's aperture 0.12 is POV-Ray's 0.48. variance 0 turns
// off POV-Ray's early stop, so every pixel takes all BLUR_N samples, as glint's do.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 }
camera { perspective location <2.2, 1.1, -6> look_at <0, 0.6, 2>
  right x*image_width/image_height angle 45.6036
  aperture 0.48 blur_samples BLUR_N focal_point <0, 0.6, 2> confidence 0.9 variance 0 }
background { rgb <0.2633, 0.3801, 0.6038> }
light_source { <6, 8, -8> color rgb 0.7874 }
light_source { <1000, 2000, -1000> color rgb <0.0509, 0.0509, 0.0732> parallel point_at <0, 0, 0> }
#macro Ball(Z, Colour, Size)
  sphere { <0, 0.6, Z>, 0.6 pigment { rgb Colour } finish { ambient 0.2 diffuse 1 phong 1 phong_size Size } }
#end
plane { y, 0 pigment { checker rgb <0.8070, 0.7758, 0.7011> rgb <0.1470, 0.1590, 0.1946> }
  finish { ambient 0.2 diffuse 1 phong 0.2 phong_size 20 } }
Ball(-4, <0.8714, 0.1620, 0.0908>, 80)
Ball(-1, <0.0232, 0.3564, 0.3140>, 80)
sphere { <0, 0.6, 2>, 0.6 pigment { rgb 0.0039 } finish { ambient 0.2 diffuse 1 phong 1 phong_size 200 reflection 0.85 } }
Ball(5, <0.8879, 0.4678, 0.0296>, 60)
Ball(8, <0.2705, 0.0782, 0.3419>, 120)
Ball(11, <0.0356, 0.0953, 0.3916>, 80)
