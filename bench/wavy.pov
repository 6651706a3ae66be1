// wavy.pov - POV-Ray 3.7 copy of bench/wavy.yaml (a wavy surface of
// 1,051,250 triangles, one low point light, a matte material), used by
// bench/run. The two scenes must stay the same: change one, change the other.
//
// wavy-mesh.inc is not in the repository (about 65 MB): bench/run writes
// wavy.obj and then wavy-mesh.inc in its temporary folder,
//
//   obj2pov wavy 725 wavy.obj
//   obj2pov mesh2 wavy.obj wavy-mesh.inc WavyMesh
//
// and renders this file there with one ray per pixel:
//
//   povray wavy.pov +W1920 +H1080 +Q9 -D +WT2 +FN +Owavy.png -A -J File_Gamma=sRGB
//
// Handedness, colours and gamma as in seed-room.pov and bunny.pov.

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 1        // glint's default ambient light: white
  max_trace_level 6          // glint's default depth 5 (no mirrors here anyway)
  adc_bailout 0
}

background { color srgb <0.18, 0.2, 0.23> }

#include "wavy-mesh.inc"

// glint's fov is vertical; POV-Ray's angle is horizontal.
#declare V_Fov = 30;
camera {
  perspective
  location <0.55, 1.55, 2.9>
  up y
  right -x*image_width/image_height
  angle degrees(2*atan(tan(radians(V_Fov/2))*image_width/image_height))
  look_at <-0.1, -0.12, 0.1>
}

light_source { <-2.6, 1.5, 1.3> color rgb 1 }

object { WavyMesh
  pigment { color srgb <0.4, 0.58, 0.78> }
  finish { ambient 0.2 diffuse 1 specular 0 phong 0 }
}
