/* mesh_emitter.c - the emissive triangles of a placed mesh as one light
 * (light.h): a triangle chosen in proportion to its power (area times
 * brightness), then a point of it uniformly by area, glowing on the side
 * its winding makes the front. The Cornell box's ceiling lamp is one. */
#include <stdlib.h>
#include "geometry/shape_math.h"
#include "shading/light.h"

/* The first triangle whose cumulative power exceeds u. */
static int find_triangle(const light *l, double u)
{
    int lo = 0, hi = l->triangle_count - 1;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (l->cumulative[mid] > u)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

static bool mesh_emitter_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    int t = find_triangle(l, u1);
    double before = t > 0 ? l->cumulative[t - 1] : 0, share = l->cumulative[t] - before;
    double u = (u1 - before) / share;
    u = u < 1 ? u : 0.99999999999999989;
    const emitter_triangle *tri = &l->triangles[t];
    vec3 q = triangle_point(tri->a, tri->b, tri->c, u, u2);
    return light_surface_point(p, q, tri->normal, share / tri->area, tri->radiance, true, out);
}

const light_kind mesh_emitter = {.name = "emissive mesh", .sample = mesh_emitter_sample};

bool emitter_for_instance(light *l, const mesh *m, const instance *inst, const material *materials,
                          bool *out_of_memory)
{
    *out_of_memory = false;
    int count = 0;
    for (int t = 0; t < m->triangle_count; t++)
        count += rgb_mean(material_emission(&materials[mesh_material(m, inst, (unsigned)t)].m)) > 0;
    if (count == 0)
        return false;
    emitter_triangle *tris = malloc(sizeof *tris * (size_t)count);
    double *cumulative = malloc(sizeof *cumulative * (size_t)count);
    if (!tris || !cumulative) {
        free(tris);
        free(cumulative);
        *out_of_memory = true;
        return false;
    }
    int kept = 0;
    double total = 0;
    for (int t = 0; t < m->triangle_count; t++) {
        color e = material_emission(&materials[mesh_material(m, inst, (unsigned)t)].m);
        if (!(rgb_mean(e) > 0))
            continue;
        vec3 v[3];
        for (int k = 0; k < 3; k++) {
            const float *f = m->positions + 3 * (size_t)m->indices[3 * (size_t)t + k];
            v[k] = v3(f[0], f[1], f[2]);
            if (inst->has_transform)
                v[k] = xf_point(&inst->to_world, v[k]);
        }
        vec3 cross = v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0]));
        double twice_area = v3_length(cross);
        if (!(twice_area > 0) || !isfinite(twice_area))
            continue; /* degenerate: never hit, never lit from */
        tris[kept] = (emitter_triangle){.a = v[0], .b = v[1], .c = v[2], .normal = v3_scale(cross, 1 / twice_area),
                                        .area = twice_area / 2, .radiance = e};
        total += tris[kept].area * rgb_mean(e);
        cumulative[kept++] = total;
    }
    if (kept == 0 || !isfinite(total)) {
        free(tris);
        free(cumulative);
        return false;
    }
    for (int t = 0; t < kept; t++)
        cumulative[t] /= total;
    cumulative[kept - 1] = 1;
    *l = (light){.kind = &mesh_emitter, .triangles = tris, .cumulative = cumulative, .triangle_count = kept,
                 .power = total};
    return true;
}
