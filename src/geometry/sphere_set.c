/* sphere_set.c - many plain spheres as one shape (glint_scene_add_spheres):
 * a centre, a radius and a material each, about 36 bytes a sphere where a
 * shape record of its own takes hundreds. The accelerator gives each sphere
 * a primitive of its own and tests it with the arithmetic sphere shapes use
 * (sphere_math.h), so a set renders the bits its spheres would as shapes;
 * here is its kind, whose normal and (u, v) are the sphere kind's. */
#include <limits.h>
#include "geometry/shape_kind.h"
#include "geometry/sphere_math.h"

const shape_kind sphere_set_kind = {
    .name = "sphere set",
    .id = GLINT_SHAPE_SPHERE,
    /* A line may cross any number of its spheres, so a ray leaving one is
     * never taken to have left the set behind (shape_left_behind_rule). */
    .max_crossings = INT_MAX,
    /* A sphere's own, about the sphere hit (shape_center). */
    .surface = sphere_surface,
    .uv = sphere_uv,
    /* No bounds of its own: the accelerator bounds each sphere. */
};
