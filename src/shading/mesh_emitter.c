/* mesh_emitter.c - the emissive triangles of a placed mesh as one light
 * (light.h): a triangle chosen in proportion to its power (area times
 * brightness), then a point of it uniformly by area, glowing on the side
 * its winding makes the front. The Cornell box's ceiling lamp is one: a
 * quad the file splits into two triangles. Two such triangles, one after
 * the other, that make a parallelogram are sampled as one, by the
 * parallelogram's own coordinates: a stratified sample stays stratified
 * over the whole lamp, where split between two triangles (and through the
 * triangle's square root) it did not. The lamp's soft shadows at 64
 * samples had a third more noise than a rectangle light's. */
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

static void mesh_emitter_surface(const light *l, double u1, double u2, surface_point *out)
{
    int t = find_triangle(l, u1);
    double before = t > 0 ? l->cumulative[t - 1] : 0, share = l->cumulative[t] - before;
    /* One triangle (or parallelogram), as a lamp often is: u1 itself,
     * which the division would give, without its wait. */
    double u = l->triangle_count == 1 ? u1 : (u1 - before) / share;
    u = u < 1 ? u : 0.99999999999999989;
    const emitter_triangle *tri = &l->triangles[t];
    out->q = tri->parallelogram ? v3_add(tri->a, v3_add(v3_scale(v3_sub(tri->b, tri->a), u),
                                                       v3_scale(v3_sub(tri->c, tri->a), u2)))
                                : triangle_point(tri->a, tri->b, tri->c, u, u2);
    out->n = tri->normal;
    out->density = share / tri->area;
    out->radiance = tri->radiance;
}

/* A lamp of one parallelogram, as the Cornell box's: mesh_emitter_surface
 * for a quad of samples. Others go lane by lane. */
static bool mesh_emitter_surface_quad(const light *l, quad_f64 u1, quad_f64 u2, quad_f64 q[3], quad_f64 n[3],
                                      quad_f64 *density, quad_f64 glow[3])
{
    const emitter_triangle *tri = l->triangles;
    if (l->triangle_count != 1 || !tri->parallelogram)
        return false;
    quad_f64 u = quad_select(u1 < 1, u1, quad_splat(0.99999999999999989));
    light_parallelogram_quad(tri->a, v3_sub(tri->b, tri->a), v3_sub(tri->c, tri->a), u, u2, q);
    n[0] = quad_splat(tri->normal.x);
    n[1] = quad_splat(tri->normal.y);
    n[2] = quad_splat(tri->normal.z);
    *density = quad_splat(l->cumulative[0] / tri->area);
    glow[0] = quad_splat(tri->radiance.r);
    glow[1] = quad_splat(tri->radiance.g);
    glow[2] = quad_splat(tri->radiance.b);
    return true;
}

const light_kind mesh_emitter = {.name = "emissive mesh", .sample = light_surface_sample,
                                 .sample_lanes = light_surface_lanes, .surface = mesh_emitter_surface,
                                 .surface_quad = mesh_emitter_surface_quad, .in_scene = true};

static bool same_point(vec3 p, vec3 q)
{
    return p.x == q.x && p.y == q.y && p.z == q.z;
}

/* Whether triangle *next and the triangle *into (not yet joined) share an
 * edge across which they make a parallelogram of one brightness and one
 * facing; if so, *into becomes that parallelogram. The corner is *into's
 * vertex off the shared edge, the fourth vertex next's: the parallelogram
 * holds when the two off-edge vertices add up to the edge's ends. */
static bool join_parallelogram(emitter_triangle *into, const emitter_triangle *next)
{
    if (into->parallelogram || v3_dot(into->normal, next->normal) < 1 - 1e-9 ||
        into->radiance.r != next->radiance.r || into->radiance.g != next->radiance.g ||
        into->radiance.b != next->radiance.b)
        return false;
    const vec3 mine[3] = {into->a, into->b, into->c}, theirs[3] = {next->a, next->b, next->c};
    for (int off = 0; off < 3; off++) {
        vec3 s1 = mine[(off + 1) % 3], s2 = mine[(off + 2) % 3];
        for (int other = 0; other < 3; other++) {
            vec3 t1 = theirs[(other + 1) % 3], t2 = theirs[(other + 2) % 3];
            bool shared = (same_point(s1, t1) && same_point(s2, t2)) || (same_point(s1, t2) && same_point(s2, t1));
            if (!shared)
                continue;
            vec3 corner = mine[off], fourth = theirs[other];
            vec3 gap = v3_sub(v3_add(corner, fourth), v3_add(s1, s2));
            double size = v3_length(v3_sub(s1, corner)) + v3_length(v3_sub(s2, corner));
            if (!(v3_length(gap) <= 1e-6 * size))
                return false;
            /* The corner's neighbours in the order that keeps the winding. */
            bool turned = v3_dot(v3_cross(v3_sub(s1, corner), v3_sub(s2, corner)), into->normal) < 0;
            *into = (emitter_triangle){.a = corner, .b = turned ? s2 : s1, .c = turned ? s1 : s2,
                                       .normal = into->normal, .area = into->area + next->area,
                                       .radiance = into->radiance, .parallelogram = true};
            return true;
        }
    }
    return false;
}

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
        if (kept > 0 && join_parallelogram(&tris[kept - 1], &tris[kept]))
            cumulative[kept - 1] = total;
        else
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
