// bunny.pov - POV-Ray 3.7 copy of bench/bunny.yaml (the Stanford bunny on a
// floor, one point light, matte materials), used by bench/run. The two
// scenes must stay the same: change one, change the other.
//
// bunny-mesh.inc is not in the repository: bench/run writes it into its
// temporary folder with bench/obj2pov.c from the OBJ file,
//
//   obj2pov mesh2 /work/shared/data/stanford-bunny.obj bunny-mesh.inc BunnyMesh --smooth
//
// (--smooth: the file has no normals; area-weighted vertex normals, smooth
// across every edge, as glint's crease_angle 180), and renders it there
// with one ray per pixel:
//
//   povray bunny.pov +W1920 +H1080 +Q9 -D +WT2 +FN +Obunny.png -A -J File_Gamma=sRGB
//
// Handedness, colours and gamma as in seed-room.pov: `right -x*...` keeps
// glint's right-handed picture unmirrored, `srgb` colours are display
// colours turned linear as glint does, and assumed_gamma 1 works in linear
// light.

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 1        // glint's default ambient light: white
  max_trace_level 6          // glint's default depth 5 (no mirrors here anyway)
  adc_bailout 0
}

background { color srgb <0.18, 0.2, 0.23> }

#include "bunny-mesh.inc"

// glint's fov is vertical; POV-Ray's angle is horizontal, so it follows
// from the image's shape.
#declare V_Fov = 34;
camera {
  perspective
  location <0.9, 1.5, 3.4>
  up y
  right -x*image_width/image_height
  angle degrees(2*atan(tan(radians(V_Fov/2))*image_width/image_height))
  look_at <0, 0.75, 0>
}

// glint's point lights have no falloff and always cast shadows.
light_source { <-2.5, 4.5, 3> color rgb 1 }

// glint's matte material: ambient 0.2, Lambert diffuse 1, no highlight.
#declare F_Matte = finish { ambient 0.2 diffuse 1 specular 0 phong 0 }

plane { y, 0
  pigment { color srgb <0.75, 0.75, 0.75> }
  finish { F_Matte }
}

object { BunnyMesh
  translate <0.0168405, -0.032987, 0.001537>
  scale 10
  pigment { color srgb <0.85, 0.62, 0.45> }
  finish { F_Matte }
}
