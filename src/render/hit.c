/* hit.c - which shapes and mesh placements block all light: the opacity
 * lists the accelerator is built with, once a render. The per-hit calls
 * are in hit.h (which says why); where a textured hit reads its texture,
 * which may measure the footprint it covers. */
#include <stdlib.h>
#include <string.h>
#include "render/hit.h"
#include "render/surface_coords.h"

/* Whether every surface of s blocks all light: its material's, every
 * part's of a combination, or each sphere's or triangle's of a set or
 * mesh part without one. */
static bool shape_blocks(const glint_scene *scene, const shape *s)
{
    if (s->material < 0 && !s->csg) {
        int parts = s->set ? s->set->count : s->solid->view.triangle_count;
        for (int k = 0; k < parts; k++)
            if (!material_is_opaque(&scene->materials[shape_material(s, k)].m))
                return false;
        return true;
    }
    if (!s->csg)
        return material_is_opaque(&scene->materials[s->material].m);
    for (int i = 0; i < s->part_count; i++)
        if (!shape_blocks(scene, &scene->shapes[s->parts[i]]))
            return false;
    return true;
}

void hit_texture_where(const glint_scene *scene, const accel_hit *h, const glint_material *m, surface *s, vec3 d,
                       double width, texture_read *out)
{
    const texture *t = out->t = &scene->textures[m->texture];
    out->covered = (uv_extent){0, 0};
    if (t->kind->solid) {
        out->at = texture_place(t, s->p_obj);
        return;
    }
    /* The shape or mesh hit and its centre, found once for the look-up and
     * for the footprint. */
    coord_spot at;
    coord_spot_init(scene, h, s, &at);
    /* Meshes carry their uv already; shapes compute it only when a
     * texture of (u, v) asks. */
    if (at.sh && t->mapping.kind == GLINT_MAP_UV)
        shape_surface_uv(at.sh, s);
    out->at.z = 0;
    texture_uv(t, s, at.center, &out->at.x, &out->at.y);
    if (width > 0 && texture_filters(t))
        out->covered = coord_footprint(&at, t, s->n, d, width, out->at.x, out->at.y);
}

void texture_read_colors8(const texture_read reads[ACCEL_PACKET], const bool wanted[ACCEL_PACKET],
                          color out[ACCEL_PACKET])
{
    bool left[ACCEL_PACKET];
    memcpy(left, wanted, sizeof left);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        const texture *t = reads[i].t;
        if (!left[i] || (!t->kind->solid4 && !t->kind->eval4))
            continue;
        int lane[QUAD], n = 0;
        vec3 points[QUAD];
        for (int j = i; j < ACCEL_PACKET && n < QUAD; j++)
            if (left[j] && reads[j].t == t) {
                points[n] = reads[j].at;
                lane[n++] = j;
            }
        color c[QUAD];
        if (t->kind->solid4) {
            texture_solid_points(t, points, n, c);
        } else {
            /* Padding lanes read (0, 0) at no footprint; nothing keeps them. */
            quad_f64 u = {0}, v = {0}, u2 = {0}, v2 = {0}, channels[3];
            for (int l = 0; l < n; l++) {
                u[l] = points[l].x;
                v[l] = points[l].y;
                u2[l] = reads[lane[l]].covered.u2;
                v2[l] = reads[lane[l]].covered.v2;
            }
            t->kind->eval4(t, u, v, u2, v2, n, channels);
            for (int l = 0; l < n; l++)
                c[l] = rgb(channels[0][l], channels[1][l], channels[2][l]);
        }
        for (int l = 0; l < n; l++) {
            out[lane[l]] = c[l];
            left[lane[l]] = false;
        }
    }
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (left[i])
            out[i] = texture_read_color(&reads[i]);
}

bool hit_opacity(const glint_scene *scene, bool **shapes, bool **instances)
{
    const material *mats = scene->materials;
    *shapes = malloc(((size_t)scene->shape_count + 1) * sizeof **shapes);
    *instances = malloc(((size_t)scene->instance_count + 1) * sizeof **instances);
    bool *mesh_opaque = malloc(((size_t)scene->mesh_count + 1) * sizeof *mesh_opaque);
    bool ok = *shapes && *instances && mesh_opaque;
    for (int i = 0; ok && i < scene->shape_count; i++)
        (*shapes)[i] = shape_blocks(scene, &scene->shapes[i]);
    for (int i = 0; ok && i < scene->mesh_count; i++) {
        const mesh *m = &scene->meshes[i];
        mesh_opaque[i] = material_is_opaque(&mats[m->material].m);
        for (int k = 0; m->materials && k < m->triangle_count && mesh_opaque[i]; k++)
            mesh_opaque[i] = material_is_opaque(&mats[m->materials[k]].m);
    }
    for (int i = 0; ok && i < scene->instance_count; i++) {
        const instance *inst = &scene->instances[i];
        (*instances)[i] = inst->material >= 0 ? material_is_opaque(&mats[inst->material].m) : mesh_opaque[inst->mesh];
    }
    free(mesh_opaque);
    return ok;
}
