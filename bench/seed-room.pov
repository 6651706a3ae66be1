// seed-room.pov - POV-Ray 3.7 copy of glint's built-in "seed room" (the
// COSC363 assignment scene), used by bench/run to time POV-Ray against glint
// on the same work. Speed equivalence matters more than an exact look: the
// same objects, lights, shadows, recursion limit and samples per pixel.
// The facts follow glint's src/scene/seed_room.c (materials, tints, which
// surfaces have a specular highlight) and src/render/integrator.c (depth).
//
// Known differences that remain:
// - POV-Ray traces 5.06 camera rays per pixel to glint's 4 (see Sampling).
// - Fog: exponential in POV-Ray, linear in glint (see the fog block).
// - POV-Ray does not dim a transparent surface's Phong highlight by its
//   transparency (glint does), so the glass sphere's highlight is brighter.
// - A ray that passes into an object of the same ior (the red glass sphere)
//   does not use up a POV-Ray trace level; in glint it uses a depth level.
//
// Render it the way bench/run does (the anti-aliasing settings are command
// line options, they cannot be set from a scene file):
//
//   mkdir -p /tmp/seed && cp bench/seed-room.pov assets/moon.jpg /tmp/seed &&
//   cd /tmp/seed &&
//   povray seed-room.pov +W1000 +H1000 +Q9 -D +WT2 +FN +O/tmp/seed-room-pov.png \
//          +AM1 +A0.0 +R2 -J File_Gamma=sRGB
//
// Why the copy: Debian's /etc/povray/3.7/povray.conf restricts reads to the
// current directory, /tmp and a few system folders, so the scene and
// moon.jpg are rendered from a folder under /tmp.
//
// Sampling: glint shoots 4 camera rays per pixel on a regular 2x2 grid at the
// sub-cell centres. POV-Ray's non-adaptive method 1 with threshold 0
// supersamples every pixel (its test is "difference >= threshold", always true
// at 0). With depth 2 (+R2) a supersampled pixel gets rays at offsets
// +-0.25 px, i.e. exactly glint's 2x2 grid, but POV-Ray also keeps the first
// ray through the pixel centre in the average (it divides by depth^2 + 1) and
// traces one extra row and column of pixels around each 32x32 render block.
// Measured at 1000x1000 (POV-Ray's statistics): +R2 gives "Pixels: 1064000
// Samples: 4000000", i.e. 5.06 camera rays per pixel against glint's 4, and
// 13.48 M rays of all kinds (6.27 M + 7.21 M shadow tests); +R3 gives 9000000
// samples (3x3). +R2 is the closest POV-Ray gets. Method 0 (-A) at 2000x2000
// traces exactly 4 camera rays per output pixel (10.65 M rays in all) but
// writes a 4x larger image and would need resampling outside POV-Ray; its
// trace time measured about the same as +R2's here (1.59 s against 1.46 s,
// single runs on a noisy 2-core machine), so the extra rays of +R2 did not
// make it measurably slower.
// Jitter is off (-J). See bench/README.md.
//
// Handedness: POV-Ray is left-handed; glint is right-handed (x right, y up,
// camera looking down -z). `right -x*image_width/image_height` flips the
// image's horizontal axis, so +x (the red wall) appears on the right as in
// glint, and the picture is not mirrored.
//
// Colours: the scene's colours are display (sRGB) values. With assumed_gamma
// 1.0 POV-Ray works in linear RGB like glint; the `srgb` keyword (present in
// this 3.7.0 build, checked with #debug) converts them to linear with the sRGB
// formula. The output is sRGB-encoded by File_Gamma=sRGB on the command line.

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 1        // white ambient light, as glint's settings
  // glint's recursion limit is max_depth 5: the camera ray has depth 0 and
  // a secondary ray is spawned while depth < 5, so up to 5 bounces after the
  // camera ray (src/render/integrator.c). POV-Ray refuses a ray whose trace
  // level is already >= max_trace_level, and the camera ray takes level 1,
  // so max_trace_level 5 would allow only 4 bounces: 6 is glint's 5.
  // (In this scene no path goes deeper than 4 levels in POV-Ray's statistics,
  // "Max Level: 4/6", so 5 or 6 render the same.)
  max_trace_level 6
  adc_bailout 0              // never prune weak rays: glint does not
  // no radiosity, no photons
}

background { rgb 0 }         // glint: black background (never seen: closed room)

// ------------------------------------------------------------------ camera
// Pinhole at (0,0,4) looking at (0,0,-1). Vertical field of view
// 2*atan(10/40) = 28.0725 degrees. POV-Ray's `angle` is the horizontal field
// of view; the image is square so it equals the vertical one.
camera {
  perspective
  location <0, 0, 4>
  look_at  <0, 0, -1>
  up y
  right -x*image_width/image_height
  angle 28.0725
}

// ------------------------------------------------------------------ lights
// White point light; shadows are on by default in POV-Ray. No distance
// attenuation (fade_power 0 is the default), as in glint.
light_source { <10, 40, -3> color rgb 1 }

// Spotlight straight down, full cone 17 degrees: half-angle 8.5, hard edge
// (radius = falloff = 8.5, tightness 0), as glint's cone_angle 8.5, falloff 0.
light_source {
  <3, 50, -80> color rgb 1
  spotlight
  point_at <3, 0, -80>
  radius 8.5
  falloff 8.5
  tightness 0
}

// ------------------------------------------------------------------ fog
// glint: linear fog by ray segment length d, f = clamp((d - start)/(end -
// start), 0, 1), start -16, end 284, colour (0.8,0.8,0.8). POV-Ray's fog is
// also applied per ray segment, but exponential: f = 1 - exp(-d/distance).
// It is matched at the half-way point: glint reaches f = 0.5 at d = 134, so
// distance = 134/ln 2 = 193.32. (At d = 50 glint gives 0.22, POV-Ray 0.23;
// at d = 280 glint 0.99, POV-Ray 0.77.)
fog {
  fog_type 1
  distance 193.32
  color srgb <0.8, 0.8, 0.8>
}

// ------------------------------------------------------------------ finishes
// glint's materials: ambient 0.2 of the colour, diffuse 1, Phong specular 1
// with shininess 50 (POV-Ray's phong is the same (r.v)^size highlight).
#declare F_Matte = finish { ambient 0.2 diffuse 1 phong 0 specular 0 }
#declare F_Shiny = finish { ambient 0.2 diffuse 1 phong 1 phong_size 50 specular 0 }

#default { finish { F_Matte } }

// ------------------------------------------------------------------ room
// The walls are finite quads closing the room: x -50..50, y -15..100,
// z -300..5. Matte, no specular.

// Floor: y = -15, 5-unit black and white checker, black where
// floor(x/5) + floor(z/5) is even (checked with eval_pigment). POV-Ray's 3D checker also
// counts floor(y); the pattern is moved by half a cell in y so the plane
// y = -15 lies inside a cell (not on a cell boundary, where rounding would
// decide) and the xz cells match glint's floor(x/5) + floor(z/5) parity.
// The floor has glint's default specular highlight.
polygon {
  5, <-50, -15, 5>, <50, -15, 5>, <50, -15, -300>, <-50, -15, -300>, <-50, -15, 5>
  pigment {
    checker color srgb <0, 0, 0> color srgb <1, 1, 1>
    scale 5
    translate <0, 2.5, 0>
  }
  finish { F_Shiny }
}

// Back wall z = -300, grey.
polygon {
  5, <-50, -15, -300>, <50, -15, -300>, <50, 100, -300>, <-50, 100, -300>, <-50, -15, -300>
  pigment { color srgb <0.192, 0.192, 0.192> }
}

// Right wall x = 50, red.
polygon {
  5, <50, -15, 5>, <50, -15, -300>, <50, 100, -300>, <50, 100, 5>, <50, -15, 5>
  pigment { color srgb <1, 0, 0> }
}

// Left wall x = -50, cyan.
polygon {
  5, <-50, -15, 5>, <-50, -15, -300>, <-50, 100, -300>, <-50, 100, 5>, <-50, -15, 5>
  pigment { color srgb <0, 1, 1> }
}

// Front wall z = 5 (behind the camera, seen in reflections), blue.
polygon {
  5, <-50, -15, 5>, <50, -15, 5>, <50, 100, 5>, <-50, 100, 5>, <-50, -15, 5>
  pigment { color srgb <0, 0, 1> }
}

// Ceiling y = 100, white-ish.
polygon {
  5, <-50, 100, 5>, <50, 100, 5>, <50, 100, -300>, <-50, 100, -300>, <-50, 100, 5>
  pigment { color srgb <0.8, 0.8, 0.8> }
}

// ------------------------------------------------------------------ mirror sphere on a cylinder
sphere {
  <-10, 1, -50>, 3
  pigment { color srgb <0, 0, 0> }
  finish { F_Shiny reflection 1 }
}

// Capped cylinder (POV-Ray cylinders are capped unless `open`), base centre
// (-10,-15,-50), radius 2, height 13.
cylinder {
  <-10, -15, -50>, <-10, -2, -50>, 2
  pigment { color srgb <1, 0.4, 0.2> }
  finish { F_Shiny }
}

// ------------------------------------------------------------------ transparent red sphere
// transparency 0.8 with tint 0.5, no specular: glint adds
// 0.8 * ((1 - 0.5) + 0.5 * colour) of the straight-through ray, i.e. 0.4 of it
// filtered by the colour plus 0.4 unfiltered: POV-Ray's filter 0.4 transmit
// 0.4. No refraction (the default interior has ior 1).
sphere {
  <3, -10, -60>, 5
  pigment { color srgbft <1, 0, 0, 0.4, 0.4> }
  finish { F_Matte }
}

// ------------------------------------------------------------------ moon on a cone
// glint maps the moon by the sphere's own (u, v); assumed to be the same as
// its spherical mapping, in the sphere's own coordinates with
// d = unit(p - centre): u = 0.5 + atan2(dx, dz)/2pi, v = 0.5 - asin(dy)/pi,
// u left to right and v top to bottom in the image. POV-Ray's map_type 1
// gives u = atan2(z, x)/2pi (from +x towards +z) and the image's top at +y.
// The matrix (x,y,z) -> (-z,y,-x) (its own inverse) turns one into the
// other: POV-Ray then shows the same texel at the same point as glint.
sphere {
  <0, 0, 0>, 4
  texture {
    pigment {
      image_map {
        #if (file_exists("moon.jpg"))
          jpeg "moon.jpg"
        #else
          jpeg "../assets/moon.jpg"
        #end
        gamma srgb
        map_type 1
        interpolate 2
      }
      matrix <0, 0, -1,
              0, 1,  0,
             -1, 0,  0,
              0, 0,  0>
    }
    finish { F_Matte }       // glint: the moon has no specular
  }
  translate <3, 2, -80>
}

// Cone: base centre (3,-5,-80), radius 4, height 6, apex above. POV-Ray's
// cone is capped at the base (and at the zero-radius apex, which is nothing).
cone {
  <3, -5, -80>, 4, <3, 1, -80>, 0
  pigment { color srgb <0.5, 0.5, 0.5> }
  finish { F_Shiny }
}

// ------------------------------------------------------------------ refractive sphere
// Black, refraction 0.8: 80% of the refracted ray (transmit, so unfiltered),
// ior 1.2.
sphere {
  <15, -10, -70>, 3
  pigment { color srgbt <0, 0, 0, 0.8> }
  finish { F_Shiny }
  interior { ior 1.2 }
}

// ------------------------------------------------------------------ pyramid
// Apex (12,-10,-65); base (12,-15,-60), (15,-15,-65), (12,-15,-70),
// (9,-15,-65). One face (0.6,0,0.01), the other three (0.6,0.55,0.01).
#declare P_Apex = <12, -10, -65>;
#declare P_B1 = <12, -15, -60>;
#declare P_B2 = <15, -15, -65>;
#declare P_B3 = <12, -15, -70>;
#declare P_B4 = <9, -15, -65>;
triangle { P_Apex, P_B1, P_B2 pigment { color srgb <0.6, 0, 0.01> } finish { F_Shiny } }
triangle { P_Apex, P_B2, P_B3 pigment { color srgb <0.6, 0.55, 0.01> } finish { F_Shiny } }
triangle { P_Apex, P_B3, P_B4 pigment { color srgb <0.6, 0.55, 0.01> } finish { F_Shiny } }
triangle { P_Apex, P_B4, P_B1 pigment { color srgb <0.6, 0.55, 0.01> } finish { F_Shiny } }

// ------------------------------------------------------------------ table
// Top: quad at y = -4.9, x -12..12, z -90..-70.
polygon {
  5, <-12, -4.9, -70>, <12, -4.9, -70>, <12, -4.9, -90>, <-12, -4.9, -90>, <-12, -4.9, -70>
  pigment { color srgb <0.038, 0.248, 0.184> }
  finish { F_Shiny }
}

// Legs: capped cylinders, radius 0.5, height 10, base centres (+-10,-15,-73)
// and (+-10,-15,-89).
#macro Table_Leg(X, Z)
  cylinder {
    <X, -15, Z>, <X, -5, Z>, 0.5
    pigment { color srgb <0.3, 0.2, 0.1> }
    finish { F_Shiny }
  }
#end
Table_Leg( 10, -73)
Table_Leg(-10, -73)
Table_Leg( 10, -89)
Table_Leg(-10, -89)

// ------------------------------------------------------------------ red cone
// Base centre (-5,-14,-60), radius 2, height 15 (apex at y = 1).
cone {
  <-5, -14, -60>, 2, <-5, 1, -60>, 0
  pigment { color srgb <1, 0, 0> }
  finish { F_Shiny }
}
