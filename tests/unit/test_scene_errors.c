/* test_scene_errors.c - the YAML scene loader's broken scenes: a table of
 * them, each with its exact first message and number of problems, and the
 * limits (includes, nesting, aliases, max_errors) with their reports. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#define SCENE_TEST_NAME "glint-scene-errors"
#include "scene_file_test_util.h"

/* ------------------------------------------------------ broken scenes */

/* A broken scene, loaded from memory as "bad.yaml" with the default
 * max_errors: its first message and how many problems it has. "@TMP@"
 * stands for the test's temporary folder in both texts. */
typedef struct bad_scene {
    const char *name;
    const char *yaml;
    const char *first;
    int problems;
} bad_scene;

static const bad_scene BAD[] = {
    {"syntax_unclosed_bracket",
     "objects: [1, 2\n",
     "bad.yaml:2:1: syntax error: did not find expected ',' or ']' while parsing a flow sequence", 1},
    {"syntax_bad_indentation",
     "settings:\n"
     "  width: 10\n"
     "   height: 20\n",
     "bad.yaml:3:10: syntax error: mapping values are not allowed in this context", 1},
    {"syntax_tab_indent",
     "settings:\n"
     "\twidth: 10\n",
     "bad.yaml:2:1: YAML forbids tabs for indentation: indent with spaces", 1},
    {"syntax_unclosed_quote",
     "settings:\n"
     "  output: \"a.png\n",
     "bad.yaml:3:1: syntax error: found unexpected end of stream while scanning a quoted scalar", 1},
    {"syntax_unknown_alias",
     "settings: *nope\n",
     "bad.yaml:1:11: unknown anchor 'nope': no '&nope' comes before it", 1},
    {"two_documents",
     "glint: 1\n"
     "---\n"
     "glint: 1\n",
     "bad.yaml:2:1: only one YAML document per file", 1},
    {"top_level_list",
     "- glint: 1\n",
     "bad.yaml:1:1: a scene file must be a map, got a list", 1},
    {"top_level_text",
     "hello\n",
     "bad.yaml:1:1: a scene file must be a map, got text", 1},
    {"unknown_root_key_hint",
     "glint: 1\n"
     "setings:\n"
     "  width: 10\n",
     "bad.yaml:2:1: unknown key 'setings' in the scene (did you mean 'settings'?)", 1},
    {"unknown_root_key",
     "glint: 1\n"
     "frobnicate: 1\n",
     "bad.yaml:2:1: unknown key 'frobnicate' in the scene", 1},
    {"unknown_settings_key_hint",
     "settings:\n"
     "  widht: 10\n",
     "bad.yaml:2:3: unknown key 'widht' in settings (did you mean 'width'?)", 1},
    {"unknown_camera_key_hint",
     "camera:\n"
     "  lookat: [0, 0, 0]\n",
     "bad.yaml:2:3: unknown key 'lookat' in camera (did you mean 'look_at'?)", 1},
    {"unknown_fog_key_hint",
     "fog:\n"
     "  type: exponential\n"
     "  densty: 0.5\n",
     "bad.yaml:3:3: unknown key 'densty' in exponential fog (did you mean 'density'?)", 1},
    {"unknown_texture_key_hint",
     "textures:\n"
     "  t: {type: checker, colours: [[0, 0, 0], [1, 1, 1]]}\n",
     "bad.yaml:2:22: unknown key 'colours' in texture 't' (did you mean 'colors'?)", 1},
    {"unknown_material_key_hint",
     "materials:\n"
     "  m: {colour: [1, 1, 1]}\n",
     "bad.yaml:2:7: unknown key 'colour' in material 'm' (did you mean 'color'?)", 1},
    {"unknown_light_key_hint",
     "lights:\n"
     "  - {type: point, position: [0, 0, 0], intensty: 2}\n",
     "bad.yaml:2:40: unknown key 'intensty' in a point light (did you mean 'intensity'?)", 1},
    {"unknown_object_key",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [0, 0, 0], max: [1, 1, 1], radius: 1}\n",
     "bad.yaml:4:62: unknown key 'radius' in box", 1},
    {"unknown_rotate_key_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - type: sphere\n"
     "    material: m\n"
     "    radius: 1\n"
     "    transform:\n"
     "      - rotate: {axis: [0, 1, 0], angel: 30}\n",
     "bad.yaml:8:35: unknown key 'angel' in rotate (did you mean 'angle'?)", 2},
    {"unknown_mapping_key_hint",
     "textures:\n"
     "  t: {type: checker, mapping: {type: planar, scael: 2}}\n",
     "bad.yaml:2:46: unknown key 'scael' in a planar mapping (did you mean 'scale'?)", 1},
    {"sphere_needs_radius",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - type: sphere\n"
     "    material: m\n"
     "    center: [0, 1, 0]\n",
     "bad.yaml:4:5: sphere needs 'radius'", 1},
    {"plane_needs_normal",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: plane, material: m, point: [0, 0, 0]}\n",
     "bad.yaml:4:5: plane needs 'normal'", 1},
    {"polygon_needs_points",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m}\n",
     "bad.yaml:4:5: polygon needs 'points'", 1},
    {"box_needs_min",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, max: [1, 1, 1]}\n",
     "bad.yaml:4:5: box needs 'min'", 1},
    {"box_needs_max",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [0, 0, 0]}\n",
     "bad.yaml:4:5: box needs 'max'", 1},
    {"cylinder_needs_radius",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, height: 2}\n",
     "bad.yaml:4:5: cylinder needs 'radius'", 1},
    {"cylinder_needs_height",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 1}\n",
     "bad.yaml:4:5: cylinder needs 'height'", 1},
    {"cone_needs_height",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cone, material: m, radius: 1, capped: false}\n",
     "bad.yaml:4:5: cone needs 'height'", 1},
    {"object_needs_type",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {material: m, radius: 1}\n",
     "bad.yaml:4:5: an object needs 'type'", 1},
    {"object_needs_material",
     "objects:\n"
     "  - {type: sphere, radius: 1}\n",
     "bad.yaml:2:5: sphere needs 'material'", 1},
    {"group_needs_objects",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: group, material: m}\n",
     "bad.yaml:4:5: group needs 'objects'", 1},
    {"light_needs_type",
     "lights:\n"
     "  - {position: [0, 0, 0]}\n",
     "bad.yaml:2:5: a light needs 'type'", 1},
    {"point_light_needs_position",
     "lights:\n"
     "  - {type: point, color: [1, 1, 1]}\n",
     "bad.yaml:2:5: a point light needs 'position'", 1},
    {"spot_light_needs_three_keys",
     "lights:\n"
     "  - type: spot\n"
     "    color: [1, 1, 1]\n",
     "bad.yaml:2:5: a spot light needs 'position'", 3},
    {"spot_light_needs_angle",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0]}\n",
     "bad.yaml:2:5: a spot light needs 'angle'", 1},
    {"directional_light_needs_direction",
     "lights:\n"
     "  - {type: directional, intensity: 2}\n",
     "bad.yaml:2:5: a directional light needs 'direction'", 1},
    {"texture_needs_type",
     "textures:\n"
     "  t: {colors: [[0, 0, 0], [1, 1, 1]]}\n",
     "bad.yaml:2:6: texture 't' needs 'type'", 1},
    {"image_texture_needs_file",
     "textures:\n"
     "  t: {type: image, mapping: spherical}\n",
     "bad.yaml:2:6: texture 't' needs 'file'", 1},
    {"mapping_needs_type",
     "textures:\n"
     "  t: {type: checker, mapping: {scale: 2}}\n",
     "bad.yaml:2:31: mapping needs 'type'", 1},
    {"rotate_needs_angle",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{rotate: {axis: [0, 1, 0]}}]}\n",
     "bad.yaml:4:65: rotate needs 'angle'", 1},
    {"text_for_integer",
     "settings:\n"
     "  width: ten\n",
     "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got 'ten'", 1},
    {"text_for_number",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: big}\n",
     "bad.yaml:4:41: 'radius' must be a number, got 'big'", 1},
    {"fraction_for_integer",
     "settings:\n"
     "  height: 10.5\n",
     "bad.yaml:2:11: 'height' must be a whole number from 1 to 65536, got '10.5'", 1},
    {"list_for_map",
     "settings: [640, 480]\n",
     "bad.yaml:1:11: settings must be a map, got a list", 1},
    {"list_for_material_map",
     "materials:\n"
     "  m: [1, 1, 1]\n",
     "bad.yaml:2:6: material 'm' must be a map, got a list", 1},
    {"map_for_list",
     "objects: {type: sphere}\n",
     "bad.yaml:1:10: 'objects' must be a list, got a map", 1},
    {"map_for_lights_list",
     "lights: {type: point}\n",
     "bad.yaml:1:9: 'lights' must be a list, got a map", 1},
    {"map_for_transform_list",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: {translate: [1, 2, 3]}}\n",
     "bad.yaml:4:55: 'transform' must be a list, got a map", 1},
    {"map_for_vector",
     "camera:\n"
     "  position: {x: 1, y: 2, z: 3}\n",
     "bad.yaml:2:13: 'position' must be a list of 3 finite numbers [x, y, z]", 1},
    {"vector_of_two",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, center: [1, 2]}\n",
     "bad.yaml:4:52: 'center' must be a list of 3 finite numbers [x, y, z]", 1},
    {"polygon_point_not_vector",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], 7]}\n",
     "bad.yaml:4:65: 'points' must be a list of 3 finite numbers [x, y, z]", 1},
    {"bool_yes",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 1, height: 1, capped: yes}\n",
     "bad.yaml:4:65: 'capped' must be true or false, got 'yes'", 1},
    {"bool_number",
     "materials:\n"
     "  glass: {fresnel: 1}\n",
     "bad.yaml:2:20: 'fresnel' must be true or false, got '1'", 1},
    {"colour_two_channels",
     "settings:\n"
     "  background: [1, 0.5]\n",
     "bad.yaml:2:15: 'background' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"colour_bad_hex",
     "settings:\n"
     "  background: \"#12345g\"\n",
     "bad.yaml:2:15: 'background' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"colour_negative",
     "materials:\n"
     "  m: {color: [0.5, -0.1, 0]}\n",
     "bad.yaml:2:14: 'color' must not have negative channels", 1},
    {"colour_linear_wrong",
     "settings:\n"
     "  ambient: {linear: [1, 1]}\n",
     "bad.yaml:2:12: 'ambient' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"radius_negative",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: -1}\n",
     "bad.yaml:4:41: 'radius' must be positive, got -1", 1},
    {"radius_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 0}\n",
     "bad.yaml:4:41: 'radius' must be positive, got 0", 1},
    {"cylinder_radius_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 0, height: 1}\n",
     "bad.yaml:4:43: 'radius' must be positive, got 0", 1},
    {"cylinder_height_negative",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 1, height: -2}\n",
     "bad.yaml:4:54: 'height' must be positive, got -2", 1},
    {"cone_height_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cone, material: m, radius: 1, height: 0}\n",
     "bad.yaml:4:50: 'height' must be positive, got 0", 1},
    {"checker_size_zero",
     "textures:\n"
     "  t: {type: checker, size: 0}\n",
     "bad.yaml:2:28: 'size' must be positive, got 0", 1},
    {"image_zero_size",
     "textures:\n"
     "  t: {type: image, file: @TMP@/zero.png}\n"
     "materials:\n"
     "  m: {texture: t}\n",
     "bad.yaml:4:16: texture '@TMP@/zero.png' is corrupt: Invalid IHDR data", 1},
    {"image_empty_file",
     "textures:\n"
     "  t: {type: image, file: @TMP@/empty.png}\n",
     "bad.yaml:2:26: texture '@TMP@/empty.png' is not a PNG, JPEG or OpenEXR file", 1},
    {"width_zero",
     "settings:\n"
     "  width: 0\n",
     "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'", 1},
    {"samples_not_square",
     "settings:\n"
     "  samples: 8\n",
     "bad.yaml:2:12: samples 8 is not a square number: the regular sampler lays an N x N grid (1, 4, 9, 16, "
     "...); sampler sobol takes any count", 1},
    {"samples_not_square_jittered",
     "settings:\n"
     "  sampler: jittered\n"
     "  samples: 12\n",
     "bad.yaml:3:12: samples 12 is not a square number: the jittered sampler lays an N x N grid (1, 4, 9, 16, "
     "...); sampler sobol takes any count", 1},
    {"adaptive_needs_sobol",
     "settings:\n"
     "  adaptive: {max_samples: 16}\n",
     "bad.yaml:2:13: adaptive sampling needs sampler sobol, whose points stay well spread as a pixel takes more; "
     "this scene's is regular", 1},
    {"adaptive_max_below_samples",
     "settings:\n"
     "  sampler: sobol\n"
     "  samples: 32\n"
     "  adaptive: {threshold: 0.1, max_samples: 16}\n",
     "bad.yaml:4:43: adaptive max_samples 16 is fewer than samples 32", 1},
    {"adaptive_threshold_range",
     "settings:\n"
     "  sampler: sobol\n"
     "  adaptive: {threshold: 2}\n",
     "bad.yaml:3:25: 'threshold' must be from 0 to 1, got 2", 1},
    {"filter_type",
     "settings:\n"
     "  filter: {type: gauss}\n",
     "bad.yaml:2:18: 'type' must be box, tent, gaussian, mitchell or lanczos, got 'gauss' (did you mean "
     "'gaussian'?)", 1},
    {"filter_radius",
     "settings:\n"
     "  filter: {type: tent, radius: -1}\n",
     "bad.yaml:2:32: 'radius' must be from 0 to 16 pixels, got -1", 1},
    {"filter_key",
     "settings:\n"
     "  filter: {type: tent, width: 2}\n",
     "bad.yaml:2:24: unknown key 'width' in filter", 1},
    {"samples_too_many",
     "settings:\n"
     "  samples: 4225\n",
     "bad.yaml:2:12: 'samples' must be a whole number from 1 to 4096, got '4225'", 1},
    {"depth_65",
     "settings:\n"
     "  depth: 65\n",
     "bad.yaml:2:10: 'depth' must be a whole number from 0 to 64, got '65'", 1},
    {"seed_negative",
     "settings:\n"
     "  seed: -1\n",
     "bad.yaml:2:9: 'seed' must be a whole number from 0 to 4294967295, got '-1'", 1},
    {"fov_0",
     "camera:\n"
     "  fov: 0\n",
     "bad.yaml:2:8: 'fov' must be more than 0 and at most 360 degrees, got 0", 1},
    {"fov_180",
     "camera:\n"
     "  fov: 180\n",
     "bad.yaml:2:3: camera fov must be less than 180 degrees for a pinhole (got 180; a fisheye takes up to 360)", 1},
    {"camera_looks_at_itself",
     "camera:\n"
     "  position: [1, 2, 3]\n"
     "  look_at: [1, 2, 3]\n",
     "bad.yaml:2:3: camera position and look_at must differ", 1},
    {"camera_too_far",
     "camera:\n"
     "  position: [5e300, 0, 0]\n"
     "  look_at: [0, 0, 0]\n",
     "bad.yaml:2:3: camera position [5e+300, 0, 0] and look_at [0, 0, 0] are too far apart: the view direction "
     "overflows",
     1},
    {"camera_up_too_long",
     "camera:\n"
     "  up: [0, 1e200, 0]\n",
     "bad.yaml:2:3: camera up [0, 1e+200, 0] is too long: its length overflows", 1},
    {"ior_0",
     "materials:\n"
     "  glass: {refraction: 1, ior: 0}\n",
     "bad.yaml:2:31: 'ior' must be positive, got 0", 1},
    {"ambient_2",
     "materials:\n"
     "  m: {ambient: 2}\n",
     "bad.yaml:2:16: 'ambient' must be from 0 to 1, got 2", 1},
    {"reflectivity_negative",
     "materials:\n"
     "  m: {reflectivity: -0.5}\n",
     "bad.yaml:2:21: 'reflectivity' must be from 0 to 1, got -0.5", 1},
    {"transparency_plus_refraction",
     "materials:\n"
     "  m: {transparency: 0.5, refraction: 0.75}\n",
     "bad.yaml:2:6: material transparency + refraction must not exceed 1, got 1.25", 1},
    {"spot_angle_0",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0], angle: 0}\n",
     "bad.yaml:2:69: 'angle' must be more than 0 and at most 90 degrees, got 0", 1},
    {"spot_angle_95",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0], angle: 95}\n",
     "bad.yaml:2:69: 'angle' must be more than 0 and at most 90 degrees, got 95", 1},
    {"spot_falloff_above_angle",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0], angle: 20, falloff: 25}\n",
     "bad.yaml:2:5: spot light falloff must not exceed its angle 20, got 25", 1},
    {"light_intensity_negative",
     "lights:\n"
     "  - {type: point, position: [0, 5, 0], intensity: -1}\n",
     "bad.yaml:2:51: 'intensity' must be from 0 to 1e300, got -1", 1},
    {"light_direction_zero",
     "lights:\n"
     "  - {type: directional, direction: [0, 0, 0]}\n",
     "bad.yaml:2:36: 'direction' must not be zero", 1},
    {"fog_density_zero",
     "fog:\n"
     "  type: exponential\n"
     "  density: 0\n",
     "bad.yaml:3:12: 'density' must be positive, got 0", 1},
    {"fog_start_after_end",
     "fog: {type: linear, start: 10, end: 5}\n",
     "bad.yaml:1:6: linear fog needs start < end, got 10 and 5", 1},
    {"fog_type_hint",
     "fog:\n"
     "  type: linera\n",
     "bad.yaml:2:9: 'type' must be none, linear or exponential, got 'linera' (did you mean 'linear'?)", 1},
    {"sampler_hint",
     "settings:\n"
     "  sampler: jitterd\n",
     "bad.yaml:2:12: 'sampler' must be regular, jittered or sobol, got 'jitterd' (did you mean 'jittered'?)", 1},
    {"sampler_no_hint",
     "settings:\n"
     "  sampler: random\n",
     "bad.yaml:2:12: 'sampler' must be regular, jittered or sobol, got 'random'", 1},
    {"object_type_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphear, material: m, radius: 1}\n",
     "bad.yaml:4:12: 'type' must be sphere, plane, polygon, box, cylinder, cone, disk, torus, quadric, union, intersection, difference, group, mesh or heightfield, got 'sphear' (did you mean 'sphere'?)", 1},
    {"object_type_no_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: superellipsoid, material: m, radius: 1}\n",
     "bad.yaml:4:12: 'type' must be sphere, plane, polygon, box, cylinder, cone, disk, torus, quadric, union, intersection, difference, group, mesh or heightfield, got "
     "'superellipsoid'", 1},
    {"inline_face_vertex_past_end",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: mesh, material: m, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 3]]}\n",
     "bad.yaml:3:91: 'faces' must be a whole number from 0 to 2, got '3'", 1},
    {"inline_face_too_short",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: mesh, material: m, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1]]}\n",
     "bad.yaml:3:84: each face is a list of 3 or more vertex numbers", 1},
    {"inline_normals_count",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: mesh, material: m, vertices: [[0, 0, 0]], normals: [[0, 0, 1], [0, 0, 1]], faces: [[0, 0, 0]]}\n",
     "bad.yaml:3:63: 'normals' must hold one normal a vertex: 1, got 2", 1},
    {"inline_and_file",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: mesh, material: m, file: a.obj, vertices: [[0, 0, 0]], faces: [[0, 0, 0]]}\n",
     "bad.yaml:3:5: a mesh takes a 'file' or its 'vertices' and 'faces', not both", 1},
    {"many_point_polygon_off_plane",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.5, 1.5, 0.5], [0, 1, 0]]}\n",
     "bad.yaml:3:5: polygon is not planar", 1},
    {"quadric_coefficients_count",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: quadric, material: m, coefficients: [1, 2, 3], min: [-1, -1, -1], max: [1, 1, 1]}\n",
     "bad.yaml:3:48: 'coefficients' must be a list of 10 numbers", 1},
    {"heightfield_ragged_rows",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: heightfield, material: m, heights: [[0, 1], [0.5]], min: [0, 0, 0], max: [1, 1, 1]}\n",
     "bad.yaml:3:56: each row of 'heights' must hold 2 numbers, as the first does", 1},
    {"heightfield_height_range",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: heightfield, material: m, heights: [[0, 1], [0.5, 2]], min: [0, 0, 0], max: [1, 1, 1]}\n",
     "bad.yaml:3:62: 'heights' must be from 0 to 1, got 2", 1},
    {"heightfield_file_and_heights",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: heightfield, material: m, file: x.png, heights: [[0, 1], [0, 1]], min: [0, 0, 0], max: [1, 1, 1]}\n",
     "bad.yaml:3:5: a heightfield takes a 'file' or its 'heights', one of them", 1},
    {"csg_needs_objects",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: union, material: m}\n",
     "bad.yaml:4:5: union needs 'objects'", 1},
    {"csg_empty",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: difference, material: m, objects: []}\n",
     "bad.yaml:4:46: a difference needs at least one object", 1},
    {"csg_part_not_closed",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: intersection, material: m, objects: [{type: disk, radius: 1}]}\n",
     "bad.yaml:4:49: a disk is not closed, so it cannot be a part of an intersection (a cylinder or cone needs its "
     "caps)", 1},
    {"csg_heightfield_part",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: union, objects: [{type: heightfield, material: m, heights: [[0, 1], [1, 0]], min: [0, 0, 0], "
     "max: [1, 1, 1]}]}\n",
     "bad.yaml:4:29: a heightfield is open at its sides, so it cannot be a part of a union, intersection or "
     "difference", 1},
    {"csg_open_mesh_part",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: union, objects: [{type: mesh, material: m, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],"
     " faces: [[0, 2, 1], [0, 1, 3], [0, 3, 2]]}]}\n",
     "bad.yaml:4:29: mesh 0 is not closed, so it cannot be a part of a combination: its edge from (0, 0, 1) to "
     "(0, 1, 0) has a triangle on one side only", 1},
    {"csg_part_needs_material",
     "objects:\n"
     "  - {type: union, objects: [{type: sphere, radius: 1}]}\n",
     "bad.yaml:2:29: sphere needs 'material'", 1},
    {"rectangle_light_flat",
     "lights:\n"
     "  - {type: rectangle, corner: [0, 1, 0], edge1: [1, 0, 0], edge2: [2, 0, 0]}\n",
     "bad.yaml:2:5: rectangle light edge1 and edge2 must be of finite length and not parallel", 1},
    {"sphere_light_no_falloff",
     "lights:\n"
     "  - {type: sphere, position: [0, 1, 0], radius: 1, falloff_mode: inverse_square}\n",
     "bad.yaml:2:52: unknown key 'falloff_mode' in a sphere light", 1},
    {"disk_light_samples",
     "lights:\n"
     "  - {type: disk, position: [0, 1, 0], direction: [0, -1, 0], radius: 1, samples: 0.5}\n",
     "bad.yaml:2:82: 'samples' must be a whole number from 1 to 4096, got '0.5'", 1},
    {"occlusion_key",
     "settings:\n"
     "  ambient_occlusion: {sample: 3}\n",
     "bad.yaml:2:23: unknown key 'sample' in ambient_occlusion (did you mean 'samples'?)", 1},
    {"occlusion_not_a_map",
     "settings:\n"
     "  ambient_occlusion: 16\n",
     "bad.yaml:2:22: 'ambient_occlusion' must be a map, got a number", 1},
    {"environment_unknown_texture",
     "textures: {sky: {type: checker}}\n"
     "environment: {texture: skye}\n",
     "bad.yaml:2:24: unknown texture 'skye' (did you mean 'sky'?)", 1},
    {"environment_no_texture",
     "environment: {intensity: 2}\n",
     "bad.yaml:1:14: environment needs 'texture'", 1},
    {"focus_on_pinhole",
     "camera: {position: [0, 1, 6], focus_on: [0, 0, 0]}\n",
     "bad.yaml:1:41: camera focus_on is for type thin_lens", 1},
    {"focus_on_and_distance",
     "camera: {type: thin_lens, position: [0, 0, 6], focus_on: [0, 0, 0], focus_distance: 2}\n",
     "bad.yaml:1:58: camera takes focus_on or focus_distance, not both", 1},
    {"aperture_and_f_number",
     "camera: {type: thin_lens, position: [0, 0, 6], aperture: 0.1, f_number: 2.8}\n",
     "bad.yaml:1:9: camera takes aperture or f_number, not both (aperture is the lens's radius, f_number the same "
     "size as a photographer gives it)", 1},
    {"sensor_width_alone",
     "camera: {type: thin_lens, position: [0, 0, 6], sensor_width: 0.024}\n",
     "bad.yaml:1:9: camera sensor_width only sizes the lens of an f_number: give f_number too, or leave "
     "sensor_width out", 1},
    {"f_number_pinhole",
     "camera: {position: [0, 0, 6], f_number: 2}\n",
     "bad.yaml:1:9: camera f_number is for type thin_lens, and this camera is a pinhole", 1},
    {"focus_on_behind",
     "camera: {type: thin_lens, position: [0, 0, 6], look_at: [0, 0, 0], focus_on: [0, 0, 9]}\n",
     "bad.yaml:1:78: camera focus_on must lie in front of the camera (its depth along the view is -3)", 1},
    {"light_type_no_hint",
     "lights:\n"
     "  - {type: area}\n",
     "bad.yaml:2:12: 'type' must be point, spot, directional, sphere, rectangle or disk, got 'area'", 1},
    {"texture_type_no_hint",
     "textures:\n"
     "  t: {type: clouds}\n",
     "bad.yaml:2:13: 'type' must be checker, image, checker_3d, noise, marble, wood or granite, got 'clouds'", 1},
    {"absorption_needs_color",
     "materials:\n"
     "  a: {refraction: 1, absorption: {distance: 2}}\n",
     "bad.yaml:2:34: absorption needs 'color'", 1},
    {"absorption_distance_zero",
     "materials:\n"
     "  b: {refraction: 1, absorption: {color: [1, 1, 1], distance: 0}}\n",
     "bad.yaml:2:63: 'distance' must be positive, got 0", 1},
    {"bump_needs_texture",
     "materials:\n"
     "  a: {bump: {strength: 2}}\n",
     "bad.yaml:2:13: bump needs 'texture'", 1},
    {"bump_strength_range",
     "textures:\n"
     "  n: {type: noise}\n"
     "materials:\n"
     "  d: {bump: {texture: n, strength: 2000}}\n",
     "bad.yaml:4:36: 'strength' must be from -1000 to 1000, got 2000", 1},
    {"normal_map_solid",
     "textures:\n"
     "  n: {type: noise}\n"
     "materials:\n"
     "  c: {normal_map: n}\n",
     "bad.yaml:4:6: a normal map needs a texture of (u, v), not a solid noise texture", 1},
    {"stops_not_pairs",
     "textures:\n"
     "  t: {type: marble, colors: [[0, [1, 1, 1]], [1]]}\n",
     "bad.yaml:2:29: 'colors' must be a list of 2 to 16 stops, each [value, colour]", 1},
    {"stops_out_of_order",
     "textures:\n"
     "  t: {type: wood, colors: [[0.5, [1, 1, 1]], [0.25, [0, 0, 0]]]}\n",
     "bad.yaml:2:47: 'colors' stop values must go from 0 to 1 in order, got 0.25 after 0.5", 1},
    {"stop_colour_bad",
     "textures:\n"
     "  t: {type: noise, colors: [[0, [1, 1, 1]], [1, red]]}\n",
     "bad.yaml:2:49: 'colors' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"octaves_too_many",
     "textures:\n"
     "  t: {type: granite, octaves: 17}\n",
     "bad.yaml:2:31: 'octaves' must be a whole number from 1 to 16, got '17'", 1},
    {"texture_transform_singular",
     "textures:\n"
     "  t: {type: marble, transform: [{matrix: [[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0]]}]}\n",
     "bad.yaml:2:6: marble texture transform is singular or not finite", 1},
    {"mapping_hint",
     "textures:\n"
     "  t: {type: checker, mapping: sphericl}\n",
     "bad.yaml:2:31: 'mapping' must be uv, planar, spherical or cylindrical, got 'sphericl' (did you mean 'spherical'?)", 1},
    {"version_2",
     "glint: 2\n",
     "bad.yaml:1:8: format version 2 is not supported (this glint reads version 1)", 1},
    {"version_text",
     "glint: one\n",
     "bad.yaml:1:8: 'glint' must be a number, got 'one'", 1},
    {"output_not_image",
     "settings:\n"
     "  output: render.bmp\n",
     "bad.yaml:2:11: 'output' must name a .png, .ppm or .exr file, got 'render.bmp'", 1},
    {"radius_nan",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: .nan}\n",
     "bad.yaml:4:41: 'radius' must be a finite number, got '.nan'", 1},
    {"radius_inf",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: .inf}\n",
     "bad.yaml:4:41: 'radius' must be a finite number, got '.inf'", 1},
    {"fov_negative_inf",
     "camera:\n"
     "  fov: -.inf\n",
     "bad.yaml:2:8: 'fov' must be a finite number, got '-.inf'", 1},
    {"ambient_NaN",
     "materials:\n"
     "  m: {ambient: .NaN}\n",
     "bad.yaml:2:16: 'ambient' must be a finite number, got '.NaN'", 1},
    {"vector_with_inf",
     "camera:\n"
     "  position: [0, .inf, 0]\n",
     "bad.yaml:2:13: 'position' must be a list of 3 finite numbers [x, y, z]", 1},
    {"unknown_material_hint",
     "materials:\n"
     "  marble: {}\n"
     "objects:\n"
     "  - {type: sphere, material: marbel, radius: 1}\n",
     "bad.yaml:4:30: unknown material 'marbel' (did you mean 'marble'?)", 1},
    {"unknown_material",
     "materials:\n"
     "  marble: {}\n"
     "objects:\n"
     "  - {type: sphere, material: granite, radius: 1}\n",
     "bad.yaml:4:30: unknown material 'granite'", 1},
    {"unknown_texture_hint",
     "textures:\n"
     "  checks: {type: checker}\n"
     "materials:\n"
     "  m: {texture: chekcs}\n",
     "bad.yaml:4:16: unknown texture 'chekcs' (did you mean 'checks'?)", 1},
    {"unknown_texture",
     "materials:\n"
     "  m: {texture: wood}\n",
     "bad.yaml:2:16: unknown texture 'wood'", 1},
    {"texture_file_missing",
     "textures:\n"
     "  moon: {type: image, file: no-such-moon.png}\n",
     "bad.yaml:2:29: cannot open texture 'no-such-moon.png': No such file or directory", 1},
    {"include_missing",
     "include: no-such-part.yaml\n",
     "bad.yaml:1:10: cannot include 'no-such-part.yaml': No such file or directory", 1},
    {"include_not_text",
     "include: [{file: a.yaml}]\n",
     "bad.yaml:1:11: 'include' must name files, got a map", 1},
    {"duplicate_material",
     "materials:\n"
     "  m: {}\n"
     "  m: {ambient: 0.5}\n",
     "bad.yaml:3:6: material 'm' is defined twice", 1},
    {"duplicate_texture",
     "textures:\n"
     "  t: {type: checker}\n"
     "  t: {type: checker, size: 2}\n",
     "bad.yaml:3:6: texture 't' is defined twice", 1},
    {"polygon_collinear",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 1, 1], [2, 2, 2]]}\n",
     "bad.yaml:4:5: polygon points are collinear", 1},
    {"polygon_non_planar",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]]}\n",
     "bad.yaml:4:5: polygon is not planar", 1},
    {"polygon_crosses_into_a_line",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0], [4, 0, 0]]}\n",
     "bad.yaml:4:5: polygon points are collinear", 1},
    {"polygon_two_points",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0]]}\n",
     "bad.yaml:4:42: 'points' must hold 3 or 4 points, got 2", 1},
    {"polygon_points_coincide",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [0, 0, 0], [1, 1, 0]]}\n",
     "bad.yaml:4:5: polygon points 0 and 1 coincide", 1},
    {"box_min_equals_max",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [0, 0, 0], max: [1, 0, 1]}\n",
     "bad.yaml:4:5: box min must be below max on every axis", 1},
    {"box_min_above_max",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [2, 2, 2], max: [1, 1, 1]}\n",
     "bad.yaml:4:5: box min must be below max on every axis", 1},
    {"disk_hole_too_big",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: disk, material: m, radius: 1, inner_radius: 1.5}\n",
     "bad.yaml:4:5: disk inner_radius must be below its radius 1, got 1.5", 1},
    {"image_wrap_unknown",
     "textures: {t: {type: image, file: x.png, wrap_u: tile}}\n",
     "bad.yaml:1:50: 'wrap_u' must be repeat, clamp or mirror, got 'tile'", 1},
    {"cone_top_as_wide_as_base",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cone, material: m, radius: 1, height: 2, top_radius: 1}\n",
     "bad.yaml:4:5: cone top_radius must differ from its radius 1 (one radius all the way up is a cylinder)", 1},
    {"torus_tube_too_thick",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: torus, material: m, major_radius: 1, minor_radius: 1}\n",
     "bad.yaml:4:5: torus minor_radius must be below its major_radius 1, got 1", 1},
    {"disk_every_problem",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: disk, material: m, radius: -1, inner_radius: -2, normal: [0, 0, 0]}\n",
     "bad.yaml:4:69: 'normal' must not be zero", 3},
    {"plane_normal_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: plane, material: m, normal: [0, 0, 0]}\n",
     "bad.yaml:4:40: 'normal' must not be zero", 1},
    {"scale_zero_vector",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{scale: [1, 0, 1]}]}\n",
     "bad.yaml:4:64: 'scale' must not be zero", 1},
    {"scale_zero_number",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{scale: 0}]}\n",
     "bad.yaml:4:64: 'scale' must not be zero", 1},
    {"rotate_axis_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{rotate: {axis: [0, 0, 0], angle: 45}}]}\n",
     "bad.yaml:4:72: 'axis' must not be zero", 1},
    {"transform_step_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{translat: [1, 2, 3]}]}\n",
     "bad.yaml:4:57: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'translat' (did you mean 'translate'?)", 1},
    {"transform_step_two_keys",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{translate: [1, 2, 3], scale: 2}]}\n",
     "bad.yaml:4:56: each transform step is a map with one key: translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix", 1},
    {"planar_mapping_one_axis",
     "textures:\n"
     "  t: {type: checker, mapping: {type: planar, u_axis: [1, 0, 0]}}\n",
     "bad.yaml:2:31: a planar mapping needs both 'u_axis' and 'v_axis', or neither", 1},
    {"merge_key_not_map",
     "materials:\n"
     "  m: {<<: 5, ambient: 0.5}\n",
     "bad.yaml:2:11: a merge key (<<) needs a map or a list of maps", 1},
    {"material_name_not_word",
     "materials:\n"
     "  [a, b]: {}\n",
     "bad.yaml:2:3: a name in 'materials' must be a word, got a list", 1},
    {"three_problems",
     "settings:\n"
     "  width: 0\n"
     "  height: -1\n"
     "  samples: 3\n",
     "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'", 3},
    {"problems_in_three_sections",
     "settings:\n"
     "  depth: 100\n"
     "camera:\n"
     "  fov: 400\n"
     "materials:\n"
     "  m: {ambient: 7}\n",
     "bad.yaml:2:10: 'depth' must be a whole number from 0 to 64, got '100'", 3},
    {"duplicate_key_in_object",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, radius: 2}\n",
     "bad.yaml:4:44: duplicate key 'radius' in sphere", 1},
    {"duplicate_root_key",
     "settings:\n"
     "  width: 10\n"
     "settings:\n"
     "  width: 20\n",
     "bad.yaml:3:1: duplicate key 'settings' in the scene", 1},
    {"duplicate_key_in_settings",
     "settings:\n"
     "  width: 10\n"
     "  height: 10\n"
     "  width: 20\n",
     "bad.yaml:4:3: duplicate key 'width' in settings", 1},
    {"directional_light_with_position",
     "lights:\n"
     "  - {type: directional, direction: [0, -1, 0], position: [1, 2, 3]}\n",
     "bad.yaml:2:48: unknown key 'position' in a directional light", 1},
    {"point_light_with_angle",
     "lights:\n"
     "  - {type: point, position: [0, 1, 0], angle: 30}\n",
     "bad.yaml:2:40: unknown key 'angle' in a point light", 1},
    {"point_light_with_direction_hint",
     "lights:\n"
     "  - {type: point, position: [0, 1, 0], direction: [0, -1, 0]}\n",
     "bad.yaml:2:40: unknown key 'direction' in a point light", 1},
    {"checker_with_file",
     "textures:\n"
     "  t: {type: checker, file: checks.png}\n",
     "bad.yaml:2:22: unknown key 'file' in texture 't'", 1},
    {"image_with_colors",
     "textures:\n"
     "  t: {type: image, colors: [[0, 0, 0], [1, 1, 1]], file: @TMP@/one.png}\n",
     "bad.yaml:2:20: unknown key 'colors' in texture 't'", 1},
    {"spherical_mapping_with_scale",
     "textures:\n"
     "  t: {type: checker, mapping: {type: spherical, scale: 2}}\n",
     "bad.yaml:2:49: unknown key 'scale' in a spherical mapping", 1},
    {"cylindrical_mapping_with_axis",
     "textures:\n"
     "  t: {type: checker, mapping: {type: cylindrical, u_axis: [1, 0, 0]}}\n",
     "bad.yaml:2:51: unknown key 'u_axis' in a cylindrical mapping", 1},
    {"fog_needs_type",
     "fog:\n"
     "  color: [1, 1, 1]\n"
     "  density: 0.5\n",
     "bad.yaml:2:3: fog needs 'type'", 1},
    {"linear_fog_needs_start_and_end",
     "fog:\n"
     "  type: linear\n"
     "  end: 10\n",
     "bad.yaml:2:3: linear fog needs 'start' and 'end'", 1},
    {"exponential_fog_needs_density",
     "fog:\n"
     "  type: exponential\n"
     "  color: [1, 1, 1]\n",
     "bad.yaml:2:3: exponential fog needs 'density'", 1},
    {"display_colour_above_1",
     "materials:\n"
     "  m: {color: [1.5, 0, 0]}\n",
     "bad.yaml:2:14: 'color' channels must be from 0 to 1 (a light's 'intensity' makes it brighter)", 1},
    {"light_colour_above_1",
     "lights:\n"
     "  - {type: point, position: [0, 1, 0], color: [2, 2, 2]}\n",
     "bad.yaml:2:47: 'color' channels must be from 0 to 1 (a light's 'intensity' makes it brighter)", 1},
    {"planar_mapping_parallel_axes",
     "textures:\n"
     "  t: {type: checker, mapping: {type: planar, u_axis: [1, 0, 0], v_axis: [2, 0, 0]}}\n",
     "bad.yaml:2:6: planar mapping axes must not be parallel", 1},
    {"misspelt_required_key",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, raduis: 1}\n",
     "bad.yaml:4:33: unknown key 'raduis' in sphere (did you mean 'radius'?)", 2},
    /* "Did you mean": another spelling, a word cut short, another ending;
     * nothing when the start fits several words. */
    {"hint_other_spelling",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, radius: 1, material: m, transform: [{rotateY: 30}]}\n",
     "bad.yaml:3:57: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'rotateY' (did you mean 'rotate_y'?)", 1},
    {"hint_cut_short",
     "camera: {pos: [0, 1, 5]}\n",
     "bad.yaml:1:10: unknown key 'pos' in camera (did you mean 'position'?)", 1},
    {"hint_other_ending",
     "textures:\n"
     "  t: {type: checker, mapping: cylinder}\n",
     "bad.yaml:2:31: 'mapping' must be uv, planar, spherical or cylindrical, got 'cylinder' (did you mean 'cylindrical'?)", 1},
    {"hint_none_for_several",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, radius: 1, material: m, transform: [{rot: 30}]}\n",
     "bad.yaml:3:57: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'rot'", 1},
    /* A value in quotes is text; when it would be right without them, the
     * message says so. */
    {"quoted_number",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, radius: \"2\", material: m}\n",
     "bad.yaml:3:28: 'radius' must be a number, got '2' in quotes, which is text: write 2 without quotes", 1},
    {"quoted_whole_number",
     "settings: {width: \"320\"}\n",
     "bad.yaml:1:19: 'width' must be a whole number from 1 to 65536, got '320' in quotes, which is text: write 320 without quotes", 1},
    {"quoted_whole_number_out_of_range",
     "settings: {width: \"0\"}\n",
     "bad.yaml:1:19: 'width' must be a whole number from 1 to 65536, got '0' in quotes, which is text", 1},
    {"quoted_text_for_a_bool",
     "materials: {m: {fresnel: \"yes\"}}\n",
     "bad.yaml:1:26: 'fresnel' must be true or false, got 'yes' in quotes, which is text", 1},
    /* '#' starts a comment: a colour without quotes, in a flow map (libyaml
     * stumbles on a later line) or a block one (the value is empty). */
    {"hash_colour_in_flow_map",
     "materials:\n"
     "  m: {ambient: 0.1, color: #0000ff}\n",
     "bad.yaml:2:28: '#' starts a comment in YAML: write the colour in quotes, color: \"#0000ff\"", 1},
    {"hash_colour_in_flow_list",
     "textures:\n"
     "  t: {type: checker, colors: [\"#ffffff\", #000]}\n",
     "bad.yaml:2:42: '#' starts a comment in YAML: write the colour in quotes, \"#000\"", 1},
    {"hash_colour_in_block_map",
     "materials:\n"
     "  m:\n"
     "    color:   #ff8800   \n"
     "    ambient: 0.1\n",
     "bad.yaml:3:14: '#' starts a comment in YAML: write the colour in quotes, color: \"#ff8800\"", 1},
    /* A '#' in quotes is no comment; a comment that is no colour leaves
     * libyaml's words. */
    {"hash_in_quotes_then_syntax_error",
     "materials:\n"
     "  m: {color: \"#0000ff\", ambient: 0.1 ]\n",
     "bad.yaml:2:38: syntax error: did not find expected ',' or '}' while parsing a flow mapping", 1},
    {"hash_comment_then_syntax_error",
     "materials:\n"
     "  m: {color: [1, 1, 1],  # red\n"
     "      ambient: 0.1 ]\n",
     "bad.yaml:3:20: syntax error: did not find expected ',' or '}' while parsing a flow mapping", 1},
    {"hash_comment_empty_value",
     "camera:\n"
     "  fov: # later\n",
     "bad.yaml:2:7: 'fov' must be a number, got nothing", 1},
    /* A tab in the indentation, nested deeper; a tab after a value is fine
     * and only the bad key is reported. */
    {"tab_indent_nested",
     "materials:\n"
     "  m:\n"
     "  \tcolor: [1, 1, 1]\n",
     "bad.yaml:3:3: YAML forbids tabs for indentation: indent with spaces", 1},
    {"tab_after_value",
     "settings:\n"
     "  widht:\t10\n",
     "bad.yaml:2:3: unknown key 'widht' in settings (did you mean 'width'?)", 1},
    /* An alias before its anchor, each named once in the file. */
    {"alias_before_its_anchor",
     "materials:\n"
     "  a: *shiny\n"
     "  b: &shiny {specular: 1}\n",
     "bad.yaml:2:6: unknown anchor 'shiny': '&shiny' comes later, at line 3, and an anchor must come before its aliases", 1},
    /* Keyed values (docs/animation.md): each bad key told where it is. */
    {"keys_unsorted",
     "camera:\n"
     "  fov: {keys: [[0, 40], [2, 50], [1, 60]]}\n",
     "bad.yaml:2:35: key times must increase: 1 s comes after 2 s", 1},
    {"keys_same_time",
     "camera:\n"
     "  fov: {keys: [[1, 40], [1, 50]]}\n",
     "bad.yaml:2:26: key times must increase: 1 s comes after 1 s", 1},
    {"keys_vector_for_number",
     "camera:\n"
     "  fov: {keys: [[0, 40], [1, [1, 2, 3]]]}\n",
     "bad.yaml:2:29: 'fov' must be a number, got a list", 1},
    {"keys_mixed_in_translate",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{translate: {keys: [[0, [0, 0, 0]], [1, 4]]}}]}\n",
     "bad.yaml:3:96: 'translate' must be a list of 3 finite numbers [x, y, z]", 1},
    {"keys_value_out_of_range",
     "materials:\n"
     "  glass: {transparency: {keys: [[0, 0.5], [1, 1.5]]}}\n",
     "bad.yaml:2:47: 'transparency' must be from 0 to 1, got 1.5", 1},
    {"keys_not_a_pair",
     "camera:\n"
     "  fov: {keys: [[0, 40, 1]]}\n",
     "bad.yaml:2:16: each of 'fov''s keys is [time in seconds, value], got a list", 1},
    {"keys_empty",
     "camera:\n"
     "  fov: {keys: []}\n",
     "bad.yaml:2:15: 'keys' needs at least one [time, value]", 1},
    {"keys_unknown_interpolation",
     "camera:\n"
     "  fov: {keys: [[0, 40]], interpolate: cubic}\n",
     "bad.yaml:2:39: 'interpolate' must be linear, smooth or step, got 'cubic'", 1},
    {"keys_unknown_key",
     "camera:\n"
     "  fov: {keys: [[0, 40]], interpolation: step}\n",
     "bad.yaml:2:26: unknown key 'interpolation' in fov", 1},
    {"keys_on_a_whole_number",
     "settings:\n"
     "  width: {keys: [[0, 40]]}\n",
     "bad.yaml:2:10: 'width' cannot change with time", 1},
    {"keys_on_the_frame_rate",
     "settings:\n"
     "  frames: {end: 10, fps: {keys: [[0, 24]]}}\n",
     "bad.yaml:2:26: 'fps' cannot change with time", 1},
    {"keys_on_a_matrix",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{matrix: {keys: [[0, 1]]}}]}\n",
     "bad.yaml:3:65: 'matrix' cannot change with time: key its steps (translate, rotate, scale)", 1},
    {"frames_end_before_start",
     "settings:\n"
     "  frames: {start: 5, end: 2}\n",
     "bad.yaml:2:11: frames: 'end' (2) comes before 'start' (5)", 1},
};

static void test_bad_scene(void **state)
{
    const bad_scene *b = *state;
    char yaml[4096], want[1024];
    with_tmp(b->yaml, yaml, sizeof yaml);
    with_tmp(b->first, want, sizeof want);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    if (strcmp(log.first, want) != 0 || log.count != b->problems)
        fail_msg("%s:\n%s\nexpected %d problem(s), first:\n  %s\ngot %d:\n%s", b->name, yaml, b->problems, want,
                 log.count, log.all);
}

/* Without a report callback, or without options at all, err still gets the
 * first problem; with no err the load still fails cleanly. */
static void test_problems_without_a_report(void **state)
{
    const char *yaml = "settings:\n  width: 0\n  depth: 99\n";
    glint_error err = {0};
    glint_load_options o = {0};
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", &o, &err));
    assert_string_equal(err.message, "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'");
    memset(&err, 0, sizeof err);
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", NULL, &err));
    assert_string_equal(err.message, "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'");
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", NULL, NULL));
    /* A NULL name stands as "<memory>". */
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), NULL, NULL, &err));
    assert_string_equal(err.message, "<memory>:2:10: 'width' must be a whole number from 1 to 65536, got '0'");
}

/* Every problem is reported, in the order of the file. */
static void test_every_problem_in_order(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad("settings:\n"
             "  width: 0\n"
             "  sampler: jitterd\n"
             "camera: {fov: 0}\n"
             "materials:\n"
             "  m: {ambient: 2, colour: [1, 1, 1]}\n"
             "lights:\n"
             "  - {type: spot}\n"
             "objects:\n"
             "  - {type: sphere, material: m, radius: -1}\n"
             "  - {type: box, material: m, min: [1, 1, 1], max: [0, 0, 0]}\n",
             0, &log, &err);
    assert_string_equal(log.all, "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'\n"
                                 "bad.yaml:3:12: 'sampler' must be regular, jittered or sobol, got 'jitterd' (did you mean 'jittered'?)\n"
                                 "bad.yaml:4:15: 'fov' must be more than 0 and at most 360 degrees, got 0\n"
                                 "bad.yaml:6:19: unknown key 'colour' in material 'm' (did you mean 'color'?)\n"
                                 "bad.yaml:6:16: 'ambient' must be from 0 to 1, got 2\n"
                                 "bad.yaml:8:5: a spot light needs 'position'\n"
                                 "bad.yaml:8:5: a spot light needs 'direction'\n"
                                 "bad.yaml:8:5: a spot light needs 'angle'\n"
                                 "bad.yaml:10:41: 'radius' must be positive, got -1\n"
                                 "bad.yaml:11:5: box min must be below max on every axis\n");
    assert_int_equal(log.count, 10);
}

/* One bad value does not hide another of the same object: each key's,
 * each transform step's and the material's problem is reported, and the
 * object is not added. A group's bad material is not reported again at
 * each object inside it, nor a bad crease angle hides a missing model. */
static void test_every_problem_of_an_object(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad("materials:\n"
             "  steel: {}\n"
             "textures:\n"
             "  t: {type: checker, mapping: spherica, size: -1}\n"
             "objects:\n"
             "  - {type: cylinder, radius: -1, height: -1, capped: \"false\", material: stell,\n"
             "     transform: [{rotatey: 30}, {scale: 0}, {rotate: {}}]}\n"
             "  - type: group\n"
             "    material: nothing\n"
             "    transform: [{spin: 1}]\n"
             "    objects:\n"
             "      - {type: sphere, radius: 0}\n"
             "      - {type: sphere, radius: 1}\n"
             "  - {type: mesh, file: missing.obj, crease_angle: 200, transform: [{scale: [1, 0, 1]}]}\n",
             0, &log, &err);
    assert_string_equal(log.all,
                        "bad.yaml:4:31: 'mapping' must be uv, planar, spherical or cylindrical, got 'spherica' (did you mean 'spherical'?)\n"
                        "bad.yaml:4:47: 'size' must be positive, got -1\n"
                        "bad.yaml:7:19: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'rotatey' (did you mean 'rotate_y'?)\n"
                        "bad.yaml:7:41: 'scale' must not be zero\n"
                        "bad.yaml:7:54: rotate needs 'axis'\n"
                        "bad.yaml:7:54: rotate needs 'angle'\n"
                        "bad.yaml:6:73: unknown material 'stell' (did you mean 'steel'?)\n"
                        "bad.yaml:6:30: 'radius' must be positive, got -1\n"
                        "bad.yaml:6:42: 'height' must be positive, got -1\n"
                        "bad.yaml:6:54: 'capped' must be true or false, got 'false' in quotes, which is text: write false without quotes\n"
                        "bad.yaml:10:18: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'spin'\n"
                        "bad.yaml:9:15: unknown material 'nothing'\n"
                        "bad.yaml:12:32: 'radius' must be positive, got 0\n"
                        "bad.yaml:14:76: 'scale' must not be zero\n"
                        "bad.yaml:14:51: 'crease_angle' must be from 0 to 180 degrees, got 200\n"
                        "bad.yaml:14:24: cannot read model 'missing.obj': No such file or directory\n");
    assert_int_equal(log.count, 16);
}

/* 25 problems: the default stops at 20 reported, max_errors at its own. */
static void test_max_errors(void **state)
{
    char yaml[2048] = "glint: 1\n";
    for (int i = 1; i <= 25; i++)
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "unknown%d: %d\n", i, i);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    assert_int_equal(log.count, 20);
    assert_string_equal(log.first, "bad.yaml:2:1: unknown key 'unknown1' in the scene");
    assert_non_null(strstr(log.all, "bad.yaml:21:1: unknown key 'unknown20' in the scene\n"));
    assert_null(strstr(log.all, "unknown21"));

    int limits[] = {1, 3, 25, 100};
    int want[] = {1, 3, 25, 25};
    for (size_t i = 0; i < COUNT(limits); i++) {
        report_log l = {0};
        load_bad(yaml, limits[i], &l, &err);
        assert_int_equal(l.count, want[i]);
        assert_string_equal(l.first, "bad.yaml:2:1: unknown key 'unknown1' in the scene");
    }
    /* Problems found anywhere count towards the limit, not only one kind. */
    report_log l = {0};
    load_bad("settings: {width: 0, height: 0}\ncamera: {fov: 0}\nfog: {type: foggy}\n", 2, &l, &err);
    assert_int_equal(l.count, 2);
    assert_string_equal(l.all, "bad.yaml:1:19: 'width' must be a whole number from 1 to 65536, got '0'\n"
                               "bad.yaml:1:30: 'height' must be a whole number from 1 to 65536, got '0'\n");
}

static void load_bad_file(const char *name, report_log *log, glint_error *err)
{
    char path[PATH_SIZE];
    tmp_path(path, name);
    glint_load_options o = {.report = log_report, .report_user = log};
    glint_scene *s = glint_scene_load_file(path, &o, err);
    if (s) {
        glint_scene_free(s);
        fail_msg("%s loaded", path);
    }
    assert_string_equal(err->message, log->first);
}

/* An alias names only an anchor of its own file: one in another file, in
 * either direction of an include, is named in the message. */
static void test_anchors_do_not_cross_files(void **state)
{
    write_tmp("anchors/main.yaml", "include: parts/wood.yaml\n"
                                   "materials:\n"
                                   "  steel: &steel {specular: 1}\n"
                                   "objects:\n"
                                   "  - {type: sphere, radius: 1, material: *wood}\n"
                                   "  - {type: sphere, radius: 1, material: *glass}\n");
    write_tmp("anchors/parts/wood.yaml", "materials:\n"
                                         "  wood: &wood {color: [0.5, 0.3, 0.1]}\n"
                                         "  bolt: *steel\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("anchors/main.yaml", &log, &err);
    char want[5 * PATH_SIZE + 400];
    snprintf(want, sizeof want,
             "%s/anchors/parts/wood.yaml:3:9: unknown anchor 'steel': anchors do not cross files (it is defined "
             "in %s/anchors/main.yaml)\n"
             "%s/anchors/main.yaml:5:41: unknown anchor 'wood': anchors do not cross files (it is defined in "
             "%s/anchors/parts/wood.yaml)\n"
             "%s/anchors/main.yaml:6:41: unknown anchor 'glass': no '&glass' comes before it in this file (anchors "
             "do not cross files)\n",
             tmp_dir, tmp_dir, tmp_dir, tmp_dir, tmp_dir);
    assert_string_equal(log.all, want);
    assert_int_equal(log.count, 3);
}

static void test_include_cycle(void **state)
{
    write_tmp("cycle/a.yaml", "glint: 1\ninclude: b.yaml\n");
    write_tmp("cycle/b.yaml", "include: [a.yaml]\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("cycle/a.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/cycle/b.yaml:1:11: include cycle: a.yaml -> b.yaml -> a.yaml", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);

    write_tmp("cycle/self.yaml", "include: self.yaml\n");
    report_log self = {0};
    load_bad_file("cycle/self.yaml", &self, &err);
    snprintf(want, sizeof want, "%s/cycle/self.yaml:1:10: include cycle: self.yaml -> self.yaml", tmp_dir);
    assert_string_equal(self.first, want);
    assert_int_equal(self.count, 1);
}

/* Includes that fan out (each file a list of files) are bounded as a whole:
 * 40 x 40 empty includes would be 1600 files. */
static void test_include_fan_out_is_bounded(void **state)
{
    char list[40 * 12 + 32] = "include: [";
    for (int i = 0; i < 40; i++)
        strcat(list, i ? ", e.yaml" : "e.yaml");
    strcat(list, "]\n");
    write_tmp("fan/e.yaml", "");
    write_tmp("fan/f.yaml", list);
    strcpy(list, "include: [");
    for (int i = 0; i < 40; i++)
        strcat(list, i ? ", f.yaml" : "f.yaml");
    strcat(list, "]\n");
    write_tmp("fan/g.yaml", list);
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("fan/g.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/fan/f.yaml:1:", tmp_dir);
    assert_true(strncmp(log.first, want, strlen(want)) == 0);
    assert_non_null(strstr(log.first, ": too many included files (limit 1000)"));
    assert_int_equal(log.count, 1);
}

/* Including one file twice side by side is no cycle, but it defines its
 * names twice. */
static void test_include_twice(void **state)
{
    write_tmp("twice/main.yaml", "include: [mats.yaml, mats.yaml]\n");
    write_tmp("twice/mats.yaml", "materials:\n  m: {}\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("twice/main.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/twice/mats.yaml:2:6: material 'm' is defined twice", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);
}

static void test_includes_nested_too_deep(void **state)
{
    for (int i = 0; i < 20; i++) {
        char name[64], text[64];
        snprintf(name, sizeof name, "deep/f%d.yaml", i);
        snprintf(text, sizeof text, "include: f%d.yaml\n", i + 1);
        write_tmp(name, text);
    }
    write_tmp("deep/f20.yaml", "glint: 1\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("deep/f0.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/deep/f15.yaml:1:10: includes nested too deep (limit 16)", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);
}

static void test_missing_scene_file(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("no-such-scene.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "cannot read scene '%s/no-such-scene.yaml': No such file or directory", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);
    /* The error carries the kind of failure too: the file could not be read. */
    assert_int_equal(err.status, GLINT_ERR_IO);
}

/* A refused scene's error says what kind of failure its first problem was,
 * as the CLI needs to tell bad input from memory running out. */
static void test_error_status_of_first_problem(void **state)
{
    glint_error err = {0};
    glint_load_options lo = {0};
    assert_null(glint_scene_load_memory("objects: [", 10, "bad.yaml", &lo, &err));
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    err.status = GLINT_OK;
    glint_scene *s = glint_scene_new();
    assert_int_equal(glint_scene_add_shape(s, &(glint_shape){.kind = GLINT_SHAPE_SPHERE, .radius = 1}, 3, NULL, &err),
                     -1);
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material 3 does not exist");
    glint_scene_free(s);
    /* A call the loader makes keeps its own status: a texture file that is
     * not there is an I/O problem, reported where the file is named. */
    const char *missing = "textures: {t: {type: image, file: no-such-picture.png}}\n";
    assert_null(glint_scene_load_memory(missing, strlen(missing), "bad.yaml", &lo, &err));
    assert_int_equal(err.status, GLINT_ERR_IO);
    assert_non_null(strstr(err.message, "bad.yaml:1:35: cannot open texture"));
}

/* Groups nest through aliases without nesting in the text. */
static void test_groups_nested_too_deep(void **state)
{
    char yaml[4096] = "materials: {m: {}}\nobjects:\n  - &g0 {type: sphere, material: m, radius: 1}\n";
    for (int i = 1; i <= 33; i++)
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "  - &g%d {type: group, objects: [*g%d]}\n", i,
                 i - 1);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    assert_string_equal(log.first, "bad.yaml:4:5: groups nested too deep (limit 32)");
    assert_int_equal(log.count, 1);
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static long peak_kib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

/* A billion-laughs file: ten aliases of ten aliases ... nine levels deep
 * names 10^9 objects or lights. The parser must stop at the first alias
 * that takes what aliases add past the limit, with one problem, quickly
 * and in little memory. */
static void check_alias_bomb(const char *yaml, const char *first)
{
    report_log log = {0};
    glint_error err = {0};
    long before = peak_kib();
    double start = seconds_now();
    load_bad(yaml, 0, &log, &err);
    double seconds = seconds_now() - start;
    long grown = peak_kib() - before;
    if (seconds > 20 || grown > 512 * 1024)
        fail_msg("alias bomb took %.1f s and %ld KiB", seconds, grown);
    if (strcmp(log.first, first) != 0 || log.count != 1)
        fail_msg("expected 1 problem:\n  %s\ngot %d:\n%s", first, log.count, log.all);
}

/* Appends levels &l1 to &l9 to yaml (of `size` bytes), each `opener`
 * (which takes the level's number) and ten aliases of the level below. */
static void append_alias_levels(char *yaml, size_t size, const char *opener)
{
    for (int i = 1; i <= 9; i++) {
        snprintf(yaml + strlen(yaml), size - strlen(yaml), opener, i);
        for (int k = 0; k < 10; k++)
            snprintf(yaml + strlen(yaml), size - strlen(yaml), "%s*l%d", k ? ", " : "", i - 1);
        snprintf(yaml + strlen(yaml), size - strlen(yaml), "]}\n");
    }
}

static void test_alias_bomb_of_objects(void **state)
{
    char yaml[4096] = "materials: {m: {}}\nobjects:\n  - &l0 {type: sphere, material: m, radius: 1}\n";
    append_alias_levels(yaml, sizeof yaml, "  - &l%d {type: group, objects: [");
    /* Level k adds ten copies of 5 + 10 * (level k-1) nodes (l0: 7), 839,470
     * nodes by l5: the first alias of l6 passes the limit. */
    check_alias_bomb(yaml, "bad.yaml:9:33: scene too large after alias expansion (limit 1000000 nodes)");
}

/* Lights are a flat list, so the bomb goes through merge keys instead. */
static void test_alias_bomb_of_lights(void **state)
{
    char yaml[4096] = "lights:\n  - &l0 {type: point, position: [0, 0, 0]}\n";
    append_alias_levels(yaml, sizeof yaml, "  - &l%d {<<: [");
    check_alias_bomb(yaml, "bad.yaml:8:15: scene too large after alias expansion (limit 1000000 nodes)");
}

/* The limit counts what aliases add, exactly: one alias of a list of a
 * million nodes (the list and 999,999 items) is within it, of one node more
 * is not. The file's own nodes do not count: the list itself is allowed. */
static void test_alias_limit_counts_what_aliases_add(void **state)
{
    for (int more = 0; more <= 1; more++) {
        long items = 999999 + more;
        char *yaml = malloc((size_t)items * 2 + 64);
        assert_non_null(yaml);
        char *p = yaml + sprintf(yaml, "a: &big [");
        for (long i = 0; i < items; i++) {
            memcpy(p, i ? ",1" : "1", i ? 2 : 1);
            p += i ? 2 : 1;
        }
        sprintf(p, "]\nb: *big\n");
        report_log log = {0};
        glint_error err = {0};
        load_bad(yaml, 0, &log, &err);
        assert_string_equal(log.first, more ? "bad.yaml:2:4: scene too large after alias expansion (limit 1000000 nodes)"
                                            : "bad.yaml:1:1: unknown key 'a' in the scene");
        free(yaml);
    }
}

/* ------------------------------------- one report each, in the right words */

/* A texture that fails keeps its name known, as a material does: the
 * materials that use it get no second report. */
static void test_failed_texture_is_reported_once(void **state)
{
    const char *yamls[] = {
        "textures:\n  wood: {type: image, file: no-such-wood.png}\nmaterials:\n  m: {texture: wood}\n",
        "textures:\n  wood: {type: checker, size: -1}\nmaterials:\n  m: {texture: wood}\n",
    };
    const char *firsts[] = {
        "bad.yaml:2:29: cannot open texture 'no-such-wood.png': No such file or directory",
        "bad.yaml:2:31: 'size' must be positive, got -1",
    };
    for (size_t i = 0; i < COUNT(yamls); i++) {
        report_log log = {0};
        glint_error err = {0};
        load_bad(yamls[i], 0, &log, &err);
        assert_string_equal(log.first, firsts[i]);
        if (log.count != 1)
            fail_msg("expected 1 problem, got %d:\n%s", log.count, log.all);
    }
}

/* Every item of a merge list must be a map, not only the last. */
static void test_merge_list_of_non_maps(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad("materials:\n  b: &b {color: [1, 0, 0]}\n  m: {<<: [3, *b]}\n", 0, &log, &err);
    assert_string_equal(log.first, "bad.yaml:3:12: a merge key (<<) needs a map or a list of maps");
    assert_int_equal(log.count, 1);
}

/* Merges nested past the limit say so, not that a map is not a map. */
static void test_merge_too_deep_says_so(void **state)
{
    char yaml[4096] = "materials:\n  m0: &m0 {color: [1, 0, 0]}\n";
    for (int i = 1; i <= 18; i++)
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "  m%d: &m%d {<<: *m%d}\n", i, i, i - 1);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    if (strstr(log.all, "needs a map") || !strstr(log.first, "deep"))
        fail_msg("expected a message about depth, got %d:\n%s", log.count, log.all);
}

/* ------------------------------------------------------------------ main */

int main(void)
{
    static const struct CMUnitTest fixed[] = {
        cmocka_unit_test(test_problems_without_a_report),
        cmocka_unit_test(test_every_problem_in_order),
        cmocka_unit_test(test_every_problem_of_an_object),
        cmocka_unit_test(test_anchors_do_not_cross_files),
        cmocka_unit_test(test_max_errors),
        cmocka_unit_test(test_include_cycle),
        cmocka_unit_test(test_include_fan_out_is_bounded),
        cmocka_unit_test(test_include_twice),
        cmocka_unit_test(test_includes_nested_too_deep),
        cmocka_unit_test(test_missing_scene_file),
        cmocka_unit_test(test_error_status_of_first_problem),
        cmocka_unit_test(test_groups_nested_too_deep),
        cmocka_unit_test(test_alias_bomb_of_objects),
        cmocka_unit_test(test_alias_bomb_of_lights),
        cmocka_unit_test(test_alias_limit_counts_what_aliases_add),
        cmocka_unit_test(test_failed_texture_is_reported_once),
        cmocka_unit_test(test_merge_list_of_non_maps),
        cmocka_unit_test(test_merge_too_deep_says_so),
    };
    /* One test per row of the table, named after it. */
    static struct CMUnitTest tests[COUNT(fixed) + COUNT(BAD)];
    static char names[COUNT(BAD)][64];
    size_t n = 0;
    for (size_t i = 0; i < COUNT(fixed); i++)
        tests[n++] = fixed[i];
    for (size_t i = 0; i < COUNT(BAD); i++) {
        snprintf(names[i], sizeof names[i], "bad_%s", BAD[i].name);
        tests[n++] = (struct CMUnitTest){names[i], test_bad_scene, NULL, NULL, (void *)&BAD[i]};
    }
    return _cmocka_run_group_tests("test_scene_errors", tests, n, setup_dir, teardown_dir);
}
