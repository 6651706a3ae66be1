/* rectangle_light.c - a glowing parallelogram (a ceiling panel, a
 * window): an area light (light.h) from a corner and two edges, lit on the
 * side of edge1 x edge2, sampled uniformly over its area. */
#include <math.h>
#include <stddef.h>
#include "core/error.h"
#include "shading/light.h"

static glint_status rectangle_light_init(light *l, glint_error *err)
{
    const glint_light *d = &l->desc;
    vec3 cross = v3_cross(d->edge1, d->edge2);
    double area = v3_length(cross);
    if (!(area > 0) || !isfinite(area))
        return error_set(err, GLINT_ERR_INVALID, "rectangle light edge1 and edge2 must be of finite length and "
                         "not parallel");
    l->normal = v3_scale(cross, 1 / area);
    glint_shape panel = glint_shape_default(GLINT_SHAPE_POLYGON);
    panel.point_count = 4;
    panel.points[0] = d->position;
    panel.points[1] = v3_add(d->position, d->edge1);
    panel.points[2] = v3_add(panel.points[1], d->edge2);
    panel.points[3] = v3_add(d->position, d->edge2);
    return light_area_init(l, &panel, area, err);
}

static void rectangle_light_surface(const light *l, double u1, double u2, surface_point *out)
{
    const glint_light *d = &l->desc;
    light_area_point(l, v3_add(d->position, v3_add(v3_scale(d->edge1, u1), v3_scale(d->edge2, u2))), out);
}

static bool rectangle_light_surface_quad(const light *l, quad_f64 u1, quad_f64 u2, quad_f64 q[3], quad_f64 n[3],
                                         quad_f64 *density, quad_f64 glow[3])
{
    const glint_light *d = &l->desc;
    light_parallelogram_quad(d->position, d->edge1, d->edge2, u1, u2, q);
    light_area_quad(l, n, density, glow);
    return true;
}

static const param RECTANGLE_LIGHT_PARAMS[] = {
    {.key = "corner", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "one corner"},
    {.key = "edge1", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.edge1), .required = true,
     .meaning = "one side, from the corner"},
    {.key = "edge2", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.edge2), .required = true,
     .meaning = "the other side, from the corner; it glows towards edge1 x edge2 (x then z: down)"},
    AREA_LIGHT_PARAMS,
};

const light_kind rectangle_light = {
    .name = "rectangle", .id = GLINT_LIGHT_RECTANGLE, .params = PARAM_TABLE(RECTANGLE_LIGHT_PARAMS),
    .init = rectangle_light_init, .one_sided = true, .sample = light_surface_sample,
    .sample_lanes = light_surface_lanes, .surface = rectangle_light_surface,
    .surface_quad = rectangle_light_surface_quad,
};
