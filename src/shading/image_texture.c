/* image_texture.c - a PNG, JPEG or OpenEXR picture, bilinearly filtered. */
#include <stddef.h>
#include "shading/texture.h"

static glint_status image_init(texture *t, const glint_texture *d, image_load_fn load, void *user, glint_error *err)
{
    return load(user, d->file, &t->image, err);
}

static color image_at(const texture *t, double u, double v)
{
    return image_eval(&t->image, u, v);
}

static const param IMAGE_PARAMS[] = {
    {.key = "file", .type = PARAM_PATH, .offset = offsetof(glint_texture, file), .required = true,
     .meaning = "a PNG or JPEG file (sRGB), or an OpenEXR file (linear, high dynamic range), relative to the "
                "scene file"},
};

const texture_kind image_texture = {
    .name = "image", .id = GLINT_TEXTURE_IMAGE, .params = PARAM_TABLE(IMAGE_PARAMS), .init = image_init,
    .eval = image_at,
};
