/* settings.c - the image and integrator settings and the camera: their
 * keys, defaults and ranges in one table each, and the checks of the C API
 * (glint_scene_set_settings, glint_scene_set_camera), which the scene-file
 * loader reads the same tables for. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "core/error.h"
#include "core/hash.h"
#include "scene/scene.h"

static bool is_square(double v)
{
    double root = floor(sqrt(v) + 0.5);
    return root * root == v;
}

static const char *const SAMPLERS[] = {"regular", "jittered", "sobol"};

#define SETTING(name) .offset = offsetof(glint_settings, name)

static const param SETTINGS_PARAMS[] = {
    {.key = "width", .type = PARAM_INTEGER, SETTING(width), .def = {640}, .lo = 1, .hi = 65536,
     .meaning = "image width in pixels; width x height at most 268,435,456 (16384 x 16384)"},
    {.key = "height", .type = PARAM_INTEGER, SETTING(height), .def = {480}, .lo = 1, .hi = 65536,
     .meaning = "image height in pixels"},
    {.key = "samples", .type = PARAM_INTEGER, SETTING(samples_per_pixel), .def = {4}, .lo = 1, .hi = 4096,
     .meaning = "samples per pixel; the regular and jittered samplers take a square number, an N x N grid "
                "(4, the default, is 2 x 2); sobol takes any"},
    {.key = "sampler", .type = PARAM_CHOICE, SETTING(sampler), .words = SAMPLERS, .word_count = 3,
     .meaning = "regular: the centres of the N x N cells; jittered: one random point in each cell; sobol: "
                "scrambled Sobol points, well spread for any count and each pixel its own pattern"},
    {.key = "seed", .type = PARAM_UINT32, SETTING(seed), .lo = 0, .hi = 4294967295.0,
     .meaning = "changes every random choice: the jittered and sobol patterns, lens and light samples"},
    {.key = "depth", .type = PARAM_INTEGER, SETTING(max_depth), .def = {5}, .lo = 0, .hi = 64,
     .meaning = "recursion limit for reflected, refracted and see-through rays (0: none); fainter than 1/8192, or past 4096 a sample, they are not traced"},
    {.key = "background", .type = PARAM_COLOR, SETTING(background), .lo = 0, .hi = DBL_MAX,
     .meaning = "what rays that hit nothing show"},
    {.key = "ambient", .type = PARAM_COLOR, SETTING(ambient_light), .def = {1, 1, 1}, .lo = 0, .hi = DBL_MAX,
     .meaning = "ambient light; multiplies each material's ambient term"},
    {.key = "exposure", .type = PARAM_NUMBER, SETTING(exposure), .lo = -64, .hi = 64, .unit = "stops",
     .meaning = "every pixel's light times 2^exposure before it is written: 1 is twice as bright, -1 half"},
    {.key = "emission_samples", .type = PARAM_INTEGER, SETTING(emission_samples), .def = {16}, .lo = 1, .hi = 4096,
     .meaning = "shadow rays from each point lit towards each emissive shape or mesh: more is smoother"},
    {.key = "light_samples", .type = PARAM_INTEGER, SETTING(light_samples), .lo = 0, .hi = 4096,
     .meaning = "0: every area light and emissive surface sends its own samples; more: each point lit sends "
                "this many in all, each to one of them chosen by its power (many lamps cost what one does)"},
    {.key = "dispersion_bands", .type = PARAM_INTEGER, SETTING(dispersion_bands), .def = {16}, .lo = 3, .hi = 64,
     .meaning = "the bands of the spectrum (400 to 700 nm) light refracted into a dispersive material splits "
                "into, each a ray at a wavelength drawn within its band: more is smoother and slower"},
};

#define CAMERA(name) .offset = offsetof(glint_camera, name)

/* An aperture of 1 or 2 blades has no area. */
static bool no_two_blades(double v)
{
    return v == 0 || v >= 3;
}

static const char *const CAMERA_KINDS[] = {"pinhole", "thin_lens", "orthographic", "equirectangular", "fisheye"};

static const param CAMERA_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, CAMERA(position), .meaning = "where the eye is"},
    {.key = "look_at", .type = PARAM_VEC3, CAMERA(look_at), .def = {0, 0, -1},
     .meaning = "a point in the middle of the view; must differ from position"},
    {.key = "up", .type = PARAM_DIRECTION, CAMERA(up), .def = {0, 1, 0},
     .meaning = "which way is up in the image; must not be parallel to the view direction"},
    {.key = "fov", .type = PARAM_NUMBER, CAMERA(vfov_degrees), .def = {45}, .lo = 0, .hi = 360,
     .bounds = PARAM_OPEN_LOW, .unit = "degrees",
     .meaning = "vertical field of view, less than 180; fisheye: across the image's width; equirectangular: unused"},
    {.key = "type", .type = PARAM_CHOICE, CAMERA(kind), .words = CAMERA_KINDS, .word_count = 5,
     .meaning = "pinhole: every ray from position, all in focus; thin_lens: rays from a round lens "
                "about position, sharp at focus_distance only (depth of field); orthographic: parallel "
                "rays, view_width across; equirectangular: every direction, longitude across and latitude "
                "down (a 360-degree panorama); fisheye: the angle from the view grows evenly from the centre"},
    {.key = "aperture", .type = PARAM_NUMBER, CAMERA(aperture), .lo = 0, .hi = DBL_MAX, .unit = "scene units",
     .meaning = "thin_lens: the lens's radius (0: as sharp as the pinhole); larger blurs more"},
    {.key = "focus_distance", .type = PARAM_NUMBER, CAMERA(focus_distance), .lo = 0, .hi = DBL_MAX,
     .unit = "scene units",
     .meaning = "thin_lens: the distance along the view direction that is in focus (0: to look_at)"},
    {.key = "f_number", .type = PARAM_NUMBER, CAMERA(f_number), .lo = 0, .hi = DBL_MAX,
     .meaning = "thin_lens: the lens's size as a photographer's f-number N instead of aperture (0: aperture "
                "gives it): radius = focal length / (2 N), the focal length that of a sensor sensor_width "
                "wide seeing fov; smaller N blurs more"},
    {.key = "sensor_width", .type = PARAM_NUMBER, CAMERA(sensor_width), .lo = 0, .hi = DBL_MAX,
     .unit = "scene units",
     .meaning = "thin_lens with f_number: the sensor's width (0: 0.036, a 36 mm full-frame sensor with "
                "scene units in metres)"},
    {.key = "blades", .type = PARAM_INTEGER, CAMERA(blades), .lo = 0, .hi = 64, .rule = no_two_blades,
     .rule_text = "0 (round) or from 3 to 64",
     .meaning = "thin_lens: the aperture's blades: out-of-focus points blur into that regular polygon (0: a disk)"},
    {.key = "view_width", .type = PARAM_NUMBER, CAMERA(view_width), .lo = 0, .hi = DBL_MAX, .unit = "scene units",
     .meaning = "orthographic: the view's width (0: the pinhole's, with fov, at look_at's distance)"},
};

/* settings.ambient_occlusion, a map of its own in a scene file. */
static const param OCCLUSION_PARAMS[] = {
    {.key = "samples", .type = PARAM_INTEGER, SETTING(occlusion_samples), .def = {16}, .lo = 1, .hi = 4096,
     .meaning = "rays from each point shaded, spread over its hemisphere as the cosine: more is smoother"},
    {.key = "distance", .type = PARAM_NUMBER, SETTING(occlusion_distance), .lo = 0, .hi = DBL_MAX,
     .unit = "scene units", .meaning = "how far they look for what blocks the sky (0: as far as the scene goes)"},
};

static const char *const FILTERS[] = {"box", "tent", "gaussian", "mitchell", "lanczos"};

/* settings.filter, a map of its own in a scene file. */
static const param FILTER_PARAMS[] = {
    {.key = "type", .type = PARAM_CHOICE, SETTING(filter), .words = FILTERS, .word_count = 5,
     .meaning = "box: every sample alike; tent: falling linearly to the radius; gaussian: standard deviation "
                "a third of the radius; mitchell: Mitchell-Netravali (B = C = 1/3), sharper with slight "
                "ringing; lanczos: windowed sinc, sharpest with most ringing"},
    {.key = "radius", .type = PARAM_NUMBER, SETTING(filter_radius), .lo = 0, .hi = 16, .unit = "pixels",
     .meaning = "how far from a pixel's centre its samples reach (0: box 0.5, tent 1, gaussian 1.5, "
                "mitchell 2, lanczos 3); wider is smoother"},
};

param_table filter_params(void)
{
    return PARAM_TABLE(FILTER_PARAMS);
}

/* settings.adaptive, a map of its own in a scene file. */
static const param ADAPTIVE_PARAMS[] = {
    {.key = "threshold", .type = PARAM_NUMBER, SETTING(adaptive_threshold), .def = {0.05}, .lo = 0, .hi = 1,
     .meaning = "where a pixel's samples differ by more than this in any channel (0..1, as displayed), its "
                "block of 4 x 2 pixels takes more; lower is smoother and slower"},
    {.key = "max_samples", .type = PARAM_INTEGER, SETTING(adaptive_max_samples), .def = {64}, .lo = 1,
     .hi = 4096, .meaning = "the most samples a pixel takes, at least samples"},
};

/* The most frames a sequence's numbers reach: ten million, over four
 * days at 24 frames a second. */
#define MAX_FRAME 10000000

static const param FRAMES_PARAMS[] = {
    {.key = "start", .type = PARAM_INTEGER, SETTING(frame_start), .lo = 0, .hi = MAX_FRAME,
     .meaning = "the first frame"},
    {.key = "end", .type = PARAM_INTEGER, SETTING(frame_end), .lo = 0, .hi = MAX_FRAME,
     .meaning = "the last frame, at least start"},
    {.key = "fps", .type = PARAM_NUMBER, SETTING(fps), .def = {24}, .lo = 0, .hi = 1e6, .bounds = PARAM_OPEN_LOW,
     .constant = true, .meaning = "frames a second: frame f shows the scene at f / fps seconds"},
};

static const param SHUTTER_PARAMS[] = {
    {.key = "open", .type = PARAM_NUMBER, SETTING(shutter_open), .lo = -1, .hi = 1, .unit = "frames",
     .meaning = "when the shutter opens, from the frame's time"},
    {.key = "close", .type = PARAM_NUMBER, SETTING(shutter_close), .def = {0.5}, .lo = -1, .hi = 1, .unit = "frames",
     .meaning = "when it closes, at least open: 0.5 is a film camera's 180-degree shutter"},
    {.key = "steps", .type = PARAM_INTEGER, SETTING(shutter_steps), .def = {2}, .lo = 2, .hi = 64,
     .meaning = "poses a moving thing takes over the shutter, moving in straight lines between them; more "
                "follow a curved path closer"},
};

param_table shutter_params(void)
{
    return PARAM_TABLE(SHUTTER_PARAMS);
}

param_table frames_params(void)
{
    return PARAM_TABLE(FRAMES_PARAMS);
}

param_table adaptive_params(void)
{
    return PARAM_TABLE(ADAPTIVE_PARAMS);
}

param_table occlusion_params(void)
{
    return PARAM_TABLE(OCCLUSION_PARAMS);
}

#define IMPORT(name) .offset = offsetof(glint_import_options, name)

/* A scene file's mesh object reads its model's import options here. */
static const param IMPORT_PARAMS[] = {
    {.key = "crease_angle", .type = PARAM_NUMBER, IMPORT(crease_angle), .def = {80}, .lo = 0, .hi = 180,
     .unit = "degrees", .meaning = "where generated normals stay sharp"},
};

param_table import_params(void)
{
    return PARAM_TABLE(IMPORT_PARAMS);
}

param_table settings_params(void)
{
    return PARAM_TABLE(SETTINGS_PARAMS);
}

param_table camera_params(void)
{
    return PARAM_TABLE(CAMERA_PARAMS);
}

uint32_t glint_settings_random_seed(const glint_settings *s)
{
    return s->frame == 0 ? s->seed : s->seed ^ hash_u32((uint32_t)s->frame * 0x9e3779b9U ^ 0x46524d45U);
}

glint_settings glint_settings_default(void)
{
    glint_settings s;
    memset(&s, 0, sizeof s);
    params_defaults(settings_params(), &s);
    params_defaults(frames_params(), &s);
    params_defaults(shutter_params(), &s);
    s.shutter_close = 0; /* no motion blur until a shutter is given */
    return s;
}

glint_camera camera_default(void)
{
    glint_camera c;
    memset(&c, 0, sizeof c);
    params_defaults(camera_params(), &c);
    return c;
}

const char *sampling_rule_broken(const glint_settings *s, glint_error *err)
{
    const char *sampler = SAMPLERS[s->sampler];
    if (s->sampler != GLINT_SAMPLER_SOBOL && !is_square(s->samples_per_pixel)) {
        error_set(err, GLINT_ERR_INVALID,
                  "samples %d is not a square number: the %s sampler lays an N x N grid (1, 4, 9, 16, ...); "
                  "sampler sobol takes any count",
                  s->samples_per_pixel, sampler);
        return "samples";
    }
    if (s->adaptive_max_samples != 0 && s->sampler != GLINT_SAMPLER_SOBOL) {
        error_set(err, GLINT_ERR_INVALID,
                  "adaptive sampling needs sampler sobol, whose points stay well spread as a pixel takes more; "
                  "this scene's is %s",
                  sampler);
        return "adaptive";
    }
    if (s->adaptive_max_samples != 0 && s->adaptive_max_samples < s->samples_per_pixel) {
        error_set(err, GLINT_ERR_INVALID, "adaptive max_samples %d is fewer than samples %d",
                  s->adaptive_max_samples, s->samples_per_pixel);
        return "max_samples";
    }
    return NULL;
}

glint_status settings_validate(const glint_settings *s, glint_error *err)
{
    glint_status st = params_check(settings_params(), s, "settings", err);
    if (!st && s->occlusion_samples != 0)
        st = params_check(occlusion_params(), s, "ambient_occlusion", err);
    if (!st)
        st = params_check(filter_params(), s, "filter", err);
    if (!st && s->adaptive_max_samples != 0)
        st = params_check(adaptive_params(), s, "adaptive", err);
    if (!st)
        st = params_check(frames_params(), s, "frames", err);
    if (!st)
        st = params_check(shutter_params(), s, "shutter", err);
    if (!st && s->shutter_close < s->shutter_open)
        st = error_set(err, GLINT_ERR_INVALID, "shutter: 'close' (%g) comes before 'open' (%g)", s->shutter_close,
                       s->shutter_open);
    if (!st && (s->frame < 0 || s->frame > MAX_FRAME))
        st = error_set(err, GLINT_ERR_INVALID, "frame %d is not from 0 to %d", s->frame, MAX_FRAME);
    if (!st && s->frame_end < s->frame_start)
        st = error_set(err, GLINT_ERR_INVALID, "frames: 'end' (%d) comes before 'start' (%d)", s->frame_end,
                       s->frame_start);
    if (st)
        return st;
    if (sampling_rule_broken(s, err))
        return GLINT_ERR_INVALID;
    /* Refused before anything is allocated: the render's float image takes
     * 12 bytes a pixel (3 GiB at the limit), and a size the system only
     * pretends to have would be found out pages into the render. */
    long long pixels = (long long)s->width * s->height;
    if (pixels > GLINT_MAX_PIXELS)
        return error_set(err, GLINT_ERR_INVALID,
                         "image size %dx%d is %lld pixels, more than the limit of %lld (16384 x 16384)", s->width,
                         s->height, pixels, (long long)GLINT_MAX_PIXELS);
    return GLINT_OK;
}

/* "an" before a word that starts with a vowel, else "a". */
static const char *a_or_an(const char *word)
{
    return strchr("aeiou", word[0]) ? "an" : "a";
}

glint_status camera_validate(const glint_camera *c, glint_error *err)
{
    glint_status st = params_check(camera_params(), c, "camera", err);
    if (st)
        return st;
    vec3 view = v3_sub(c->look_at, c->position);
    /* Past about 1e154 the squares in a length overflow, so normalising
     * gives zero and the up test below would blame up. */
    if (!isfinite(v3_length(view)))
        return error_set(err, GLINT_ERR_INVALID,
                         "camera position [%g, %g, %g] and look_at [%g, %g, %g] are too far apart: the view "
                         "direction overflows",
                         c->position.x, c->position.y, c->position.z, c->look_at.x, c->look_at.y, c->look_at.z);
    if (!isfinite(v3_length(c->up)))
        return error_set(err, GLINT_ERR_INVALID, "camera up [%g, %g, %g] is too long: its length overflows",
                         c->up.x, c->up.y, c->up.z);
    if (v3_length(view) == 0)
        return error_set(err, GLINT_ERR_INVALID, "camera position and look_at must differ");
    if (v3_length(v3_cross(v3_normalize(view), v3_normalize(c->up))) < 1e-9)
        return error_set(err, GLINT_ERR_INVALID, "camera up must not be parallel to the view direction");
    /* A key of another kind is a forgotten type, not a wish for its default. */
    const char *kind = CAMERA_KINDS[c->kind];
    const char *lens_key = c->aperture != 0         ? "aperture"
                           : c->focus_distance != 0 ? "focus_distance"
                           : c->blades != 0         ? "blades"
                           : c->f_number != 0       ? "f_number"
                           : c->sensor_width != 0   ? "sensor_width"
                                                    : NULL;
    if (c->kind != GLINT_CAMERA_THIN_LENS && lens_key)
        return error_set(err, GLINT_ERR_INVALID, "camera %s is for type thin_lens, and this camera is %s %s",
                         lens_key, a_or_an(kind), kind);
    if (c->aperture != 0 && c->f_number != 0)
        return error_set(err, GLINT_ERR_INVALID, "camera takes aperture or f_number, not both (aperture is the "
                         "lens's radius, f_number the same size as a photographer gives it)");
    if (c->sensor_width != 0 && c->f_number == 0)
        return error_set(err, GLINT_ERR_INVALID, "camera sensor_width only sizes the lens of an f_number: give "
                         "f_number too, or leave sensor_width out");
    if (c->kind != GLINT_CAMERA_ORTHOGRAPHIC && c->view_width != 0)
        return error_set(err, GLINT_ERR_INVALID, "camera view_width is for type orthographic, and this camera is %s %s",
                         a_or_an(kind), kind);
    /* A perspective view of 180 degrees or more has no image plane. */
    if ((c->kind == GLINT_CAMERA_PINHOLE || c->kind == GLINT_CAMERA_THIN_LENS ||
         c->kind == GLINT_CAMERA_ORTHOGRAPHIC) && c->vfov_degrees >= 180)
        return error_set(err, GLINT_ERR_INVALID,
                         "camera fov must be less than 180 degrees for %s %s (got %g; a fisheye takes up to 360)",
                         a_or_an(kind), kind, c->vfov_degrees);
    return GLINT_OK;
}
