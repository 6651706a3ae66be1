/* read_spheres.c - runs of plain spheres in a scene file's objects,
 * gathered as they are read and added as one sphere set when the run is
 * long: a file of a million spheres loads in a fraction of the time and
 * memory a shape each takes, and renders the same bytes. A short run is
 * added a shape each, so small scenes keep one shape an object. Whether a
 * sphere is plain depends only on the text read before it, so every load
 * of an animated scene (one a pose) gathers alike. */
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "scene/scene.h"
#include "scenefile/loader.h"

/* The shortest run that becomes a sphere set. */
#define SPHERE_RUN 256

struct sphere_run {
    glint_vec3 *centers;
    double *radii;
    int *materials;
    size_t center_cap, radius_cap, material_cap;
    int count;
};

bool spheres_gather(loader *l, const glint_shape *s, const context *ctx)
{
    glint_transform identity = glint_transform_identity();
    if (s->kind != GLINT_SHAPE_SPHERE || ctx->csg >= 0 || l->keyed ||
        memcmp(&ctx->to_world, &identity, sizeof identity) != 0 ||
        rgb_max(material_emission(&l->scene->materials[ctx->material].m)) > 0)
        return false;
    if (!l->spheres && !(l->spheres = calloc(1, sizeof *l->spheres)))
        return false;
    struct sphere_run *run = l->spheres;
    size_t need = (size_t)run->count + 1;
    if (!array_reserve((void **)&run->centers, &run->center_cap, need, sizeof *run->centers) ||
        !array_reserve((void **)&run->radii, &run->radius_cap, need, sizeof *run->radii) ||
        !array_reserve((void **)&run->materials, &run->material_cap, need, sizeof *run->materials))
        return false;
    run->centers[run->count] = s->center;
    run->radii[run->count] = s->radius;
    run->materials[run->count++] = ctx->material;
    return true;
}

void spheres_flush(loader *l)
{
    struct sphere_run *run = l->spheres;
    if (!run || run->count == 0)
        return;
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

void spheres_free(loader *l)
{
    if (!l->spheres)
        return;
    free(l->spheres->centers);
    free(l->spheres->radii);
    free(l->spheres->materials);
    free(l->spheres);
    l->spheres = NULL;
}
