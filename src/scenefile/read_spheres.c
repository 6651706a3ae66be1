/* read_spheres.c - runs of plain spheres in a scene file's objects,
 * gathered as they are read and added as one sphere set when the run is
 * long: a file of a million spheres loads in a fraction of the time and
 * memory a shape each takes, and renders the same bytes. A short run is
 * added a shape each, so small scenes keep one shape an object. Whether a
 * sphere is plain depends only on the text read before it, so every load
 * of an animated scene (one a pose) gathers alike. */
#include <string.h>
#include "scene/scene.h"
#include "scenefile/loader.h"

/* The shortest run that becomes a sphere set. */
#define SPHERE_RUN 256

bool spheres_gather(loader *l, const glint_shape *s, const context *ctx)
{
    glint_transform identity = glint_transform_identity();
    return s->kind == GLINT_SHAPE_SPHERE && ctx->csg < 0 && !l->keyed &&
           memcmp(&ctx->to_world, &identity, sizeof identity) == 0 &&
           !(rgb_max(material_emission(&l->scene->materials[ctx->material].m)) > 0) &&
           sphere_list_add(&l->spheres, s->center, s->radius, ctx->material);
}

void spheres_flush(loader *l)
{
    sphere_list *run = &l->spheres;
    glint_error err;
    bool added = true;
    if (run->count >= SPHERE_RUN) {
        added = glint_scene_add_spheres(l->scene, run->count, run->centers, run->radii, run->materials, &err) >= 0;
    } else {
        for (int i = 0; added && i < run->count; i++) {
            glint_shape ball = glint_shape_default(GLINT_SHAPE_SPHERE);
            ball.center = run->centers[i];
            ball.radius = run->radii[i];
            added = glint_scene_add_shape(l->scene, &ball, run->materials[i], NULL, &err) >= 0;
        }
    }
    run->count = 0;
    /* Every value was checked as it was read: only memory can run out. */
    if (!added)
        diag_raw(&l->d, err.status, err.message);
}
