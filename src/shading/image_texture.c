/* image_texture.c - a PNG, JPEG or OpenEXR picture, bilinearly filtered,
 * repeated, clamped or mirrored past its edges along u and along v. */
#include <stddef.h>
#include "shading/texture.h"

static glint_status image_init(texture *t, const glint_texture *d, image_load_fn load, void *user, glint_error *err)
{
    return load(user, d->file, &t->image, err);
}

static color image_at(const texture *t, double u, double v, uv_extent covered)
{
    double level = t->desc.filter == GLINT_IMAGE_TRILINEAR ? image_level(&t->image, covered) : 0;
    return image_eval_level(&t->image, u, v, t->desc.wrap_u, t->desc.wrap_v, level);
}

static void image_at4(const texture *t, quad_f64 u, quad_f64 v, quad_f64 u2, quad_f64 v2, int lanes,
                      quad_f64 out[3])
{
    quad_f64 level = t->desc.filter == GLINT_IMAGE_TRILINEAR ? image_level4(&t->image, u2, v2) : quad_splat(0);
    image_eval_level4(&t->image, u, v, t->desc.wrap_u, t->desc.wrap_v, level, lanes, out);
}

static const char *const WRAPS[] = {"repeat", "clamp", "mirror"}; /* glint_wrap's order */
static const char *const FILTERS[] = {"trilinear", "bilinear"}; /* glint_image_filter's order */

static const param IMAGE_PARAMS[] = {
    {.key = "file", .type = PARAM_PATH, .offset = offsetof(glint_texture, file), .required = true,
     .meaning = "a PNG or JPEG file (sRGB), or an OpenEXR file (linear, high dynamic range), relative to the "
                "scene file"},
    {.key = "wrap_u", .type = PARAM_CHOICE, .offset = offsetof(glint_texture, wrap_u), .def = {GLINT_WRAP_REPEAT},
     .words = WRAPS, .word_count = 3, .meaning = "past its left and right edges: repeat, clamp (the edge goes on) or mirror"},
    {.key = "wrap_v", .type = PARAM_CHOICE, .offset = offsetof(glint_texture, wrap_v), .def = {GLINT_WRAP_CLAMP},
     .words = WRAPS, .word_count = 3, .meaning = "past its top and bottom edges: repeat, clamp or mirror"},
    {.key = "filter", .type = PARAM_CHOICE, .offset = offsetof(glint_texture, filter), .words = FILTERS,
     .word_count = 2,
     .meaning = "trilinear: where a sample covers more than a texel, the image's halved copies (mipmap levels) "
                "averaged over what it covers, so a far or tiled image does not shimmer; bilinear: the image "
                "alone, sharper far off but aliased"},
};

const texture_kind image_texture = {
    .name = "image", .id = GLINT_TEXTURE_IMAGE, .params = PARAM_TABLE(IMAGE_PARAMS), .init = image_init,
    .eval = image_at, .eval4 = image_at4,
};
