/* shape.c - the shape interface: checks a description against its kind's
 * parameter table and rules, then sends rays and results between world
 * space and the object space where each kind works. */
#include <limits.h>
#include <string.h>
#include "geometry/mesh.h"
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

glint_shape glint_shape_default(glint_shape_kind kind)
{
    glint_shape d;
    memset(&d, 0, sizeof d);
    d.kind = kind;
    const shape_kind *k = shape_kind_of(kind);
    if (k)
        params_defaults(k->params, &d);
    return d;
}

/* shape_init for a shape of kind k, with the solid of a mesh part. */
static glint_status init_as(shape *s, const shape_kind *k, const glint_shape *desc,
                            const struct mesh_solid *solid, const glint_transform *to_world, int material,
                            glint_error *err)
{
    memset(s, 0, sizeof *s);
    s->part_of = -1;
    s->csg = k && k->csg;
    if (!k)
        return error_set(err, GLINT_ERR_INVALID, "unknown shape kind %d", (int)desc->kind);
    s->kind = k;
    s->solid = solid;
    s->convex = k->span != NULL;
    s->desc = *desc;
    s->material = material;
    s->to_world = to_world ? *to_world : glint_transform_identity();
    if (!xf_invert(&s->to_world, &s->to_object))
        return error_set(err, GLINT_ERR_INVALID, "transform is singular or not finite");
    s->has_transform = !xf_is_identity(&s->to_world);
    /* A combination's is decided as its parts come (shape_parts_changed). */
    s->quad = k->intersect4 && !s->csg;
    glint_status st = params_check(k->params, &s->desc, k->name, err);
    if (st == GLINT_OK && k->init)
        st = k->init(s, err);
    if (st == GLINT_OK)
        s->center = k->center ? k->center(s) : s->desc.center;
    if (st == GLINT_OK && !s->has_transform && k->flat) {
        /* What shape_surface would compute at every hit, computed once:
         * the same bits. */
        surface one = {.p_obj = s->desc.center};
        k->surface(s, 0, &one);
        s->flat = true;
        s->flat_n = v3_normalize(one.n);
    }
    return st;
}

glint_status shape_init(shape *s, const glint_shape *desc, const glint_transform *to_world, int material,
                        glint_error *err)
{
    return init_as(s, shape_kind_of(desc->kind), desc, NULL, to_world, material, err);
}

void shape_init_sphere_set(shape *s, sphere_set *set)
{
    glint_shape desc = {.kind = GLINT_SHAPE_SPHERE};
    init_as(s, &sphere_set_kind, &desc, NULL, NULL, -1, NULL);
    s->set = set;
}

glint_status shape_init_mesh_part(shape *s, const struct mesh_solid *solid, const glint_transform *to_world,
                                  int material, glint_error *err)
{
    glint_shape desc = {.kind = GLINT_SHAPE_MESH};
    return init_as(s, &mesh_part_kind, &desc, solid, to_world, material, err);
}

void shape_move(shape *s, transform *poses, int count)
{
    s->poses = poses;
    s->pose_count = count;
    s->to_world = poses[0];
    xf_invert(&s->to_world, &s->to_object);
    s->has_transform = true;
    s->quad = s->flat = false;
    s->transform_id = 0;
}

const shape *shape_moved(const shape *s, double time, shape *out)
{
    *out = *s;
    out->time = time;
    if (s->poses)
        xf_between(s->poses, s->pose_count, time, &out->to_world, &out->to_object);
    return out;
}

bool shape_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    /* Most shapes have no transform: their rays need no copy. */
    if (!s->has_transform)
        return s->kind->intersect(s, r, tmin, tmax, hit);
    ray o = shape_object_ray(s, r);
    return s->kind->intersect(s, &o, tmin, tmax, hit);
}

bool shape_span_of(const shape *s, const ray *r, shape_span *span)
{
    if (!s->has_transform)
        return s->kind->span(s, r, span);
    ray o = shape_object_ray(s, r);
    return s->kind->span(s, &o, span);
}

quad_mask shape_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    /* A plain kind's hits are all on its main surface; a combination's
     * kind names the part and leaf of each. */
    for (int k = 0; k < QUAD; k++) {
        hit->part[k] = 0;
        hit->leaf[k] = -1;
    }
    if (!s->has_transform)
        return s->kind->intersect4(s, r, first, tmax, hit);
    /* The four lanes in object space, where the kind tests them, in a
     * packet of their own at the same lanes. */
    quad_ray world = quad_ray_of(r, first), o = quad_object_ray(&s->to_object, &world);
    ray8 local;
    quad_store(local.ox + first, o.ox);
    quad_store(local.oy + first, o.oy);
    quad_store(local.oz + first, o.oz);
    quad_store(local.dx + first, o.dx);
    quad_store(local.dy + first, o.dy);
    quad_store(local.dz + first, o.dz);
    return s->kind->intersect4(s, &local, first, tmax, hit);
}

/* Sets out->shading_n to the kind's own shading normal, when it has one,
 * turned to the side of out->n. */
static void smooth_shading(const shape *s, int part, surface *out)
{
    vec3 n;
    if (!s->kind->shading(s, part, out, &n))
        return;
    if (s->has_transform)
        n = xf_normal(&s->to_object, n);
    /* Normals that cancel out leave the surface's. */
    double length = v3_length(n);
    if (length > 0)
        out->shading_n = v3_scale(n, v3_dot(n, out->n) < 0 ? -1 / length : 1 / length);
}

void shape_surface(const shape *s, const ray *r, const shape_hit *hit, surface *out)
{
    /* p from a local, not read back from out: a 16-byte load of what was
     * just stored 8 bytes at a time waits for the stores (4-6% of a depth
     * of field's time). */
    vec3 p = ray_at(r, hit->t);
    out->p = p;
    if (s->has_transform) {
        ray o = shape_object_ray(s, r);
        out->p_obj = ray_at(&o, hit->t);
    } else {
        out->p_obj = p;
    }
    int part = hit->part & ~SHAPE_PART_FLIPPED;
    out->part = part;
    out->u = out->v = 0;
    if (s->flat) {
        /* The bits the lines below would give, computed once by
         * shape_init instead of a square root and a division a hit. */
        out->n = out->shading_n = s->flat_n;
    } else {
        s->kind->surface(s, part, out);
        if (s->has_transform)
            out->n = xf_normal(&s->to_object, out->n);
        out->n = out->shading_n = v3_normalize(out->n);
        if (s->kind->shading)
            smooth_shading(s, part, out);
    }
    if (hit->part & SHAPE_PART_FLIPPED) {
        out->n = v3_neg(out->n);
        out->shading_n = v3_neg(out->shading_n);
    }
}

bool shape_hit_enters(const shape *s, const ray *r, const shape_hit *hit)
{
    if (s->flat)
        return v3_dot(r->d, s->flat_n) < 0;
    /* The sign of d . n is the same in object space, where the normal
     * needs neither mapping nor normalising. */
    ray o = s->has_transform ? shape_object_ray(s, r) : *r;
    surface at = {.p_obj = ray_at(&o, hit->t)};
    s->kind->surface(s, hit->part & ~SHAPE_PART_FLIPPED, &at);
    return v3_dot(o.d, at.n) < 0;
}

void shape_surface_uv(const shape *s, surface *out)
{
    s->kind->uv(s, out->part, out);
}

bool shape_is_bounded(const shape *s)
{
    return s->kind->bounds != NULL;
}

/* The world box of the object box with centre c and half extents h under
 * s's transform: the image's centre, and along each world axis the sum of
 * the half extents' reach (|M| h), the eight corners' extremes. */
static void mapped_box(const shape *s, vec3 c, vec3 h, vec3 *lo, vec3 *hi)
{
    const double(*m)[4] = s->to_world.m;
    vec3 mid = xf_point(&s->to_world, c);
    vec3 e = v3(fabs(m[0][0]) * h.x + fabs(m[0][1]) * h.y + fabs(m[0][2]) * h.z,
                fabs(m[1][0]) * h.x + fabs(m[1][1]) * h.y + fabs(m[1][2]) * h.z,
                fabs(m[2][0]) * h.x + fabs(m[2][1]) * h.y + fabs(m[2][2]) * h.z);
    *lo = v3_sub(mid, e);
    *hi = v3_add(mid, e);
}

/* Along which object axis s's box a..b reaches furthest in the world. */
static int long_axis(const shape *s, vec3 a, vec3 b)
{
    vec3 e = v3_sub(b, a);
    double len[3] = {v3_length(xf_vector(&s->to_world, v3(e.x, 0, 0))),
                     v3_length(xf_vector(&s->to_world, v3(0, e.y, 0))),
                     v3_length(xf_vector(&s->to_world, v3(0, 0, e.z)))};
    return len[0] >= len[1] && len[0] >= len[2] ? 0 : len[1] >= len[2] ? 1 : 2;
}

/* Slice `piece` of `pieces` of the object box a..b, cut across axis k:
 * its centre and half extents. */
static void slice(vec3 a, vec3 b, int k, int piece, int pieces, vec3 *c, vec3 *h)
{
    double *pa = k == 0 ? &a.x : k == 1 ? &a.y : &a.z, *pb = k == 0 ? &b.x : k == 1 ? &b.y : &b.z;
    double from = *pa, span = *pb - *pa;
    *pa = from + span * piece / pieces;
    *pb = piece + 1 == pieces ? *pb : from + span * (piece + 1) / pieces;
    *c = v3_scale(v3_add(a, b), 0.5);
    *h = v3_scale(v3_sub(b, a), 0.5);
}

int shape_pieces(const shape *s)
{
    if (!shape_is_bounded(s) || !s->has_transform || s->pose_count)
        return 1;
    vec3 a, b;
    s->kind->bounds(s, &a, &b);
    int k = long_axis(s, a, b), best = 1;
    double best_area = INFINITY;
    for (int n = 1; n <= SHAPE_MAX_PIECES; n++) {
        /* Every slice's box has the same size. */
        vec3 c, h, lo, hi;
        slice(a, b, k, 0, n, &c, &h);
        mapped_box(s, c, h, &lo, &hi);
        vec3 e = v3_sub(hi, lo);
        double area = n * (e.x * e.y + e.y * e.z + e.z * e.x);
        if (area < 0.9 * best_area) {
            best_area = area;
            best = n;
        }
    }
    return best;
}

void shape_piece_bounds(const shape *s, int piece, int pieces, vec3 *lo, vec3 *hi)
{
    if (!shape_is_bounded(s)) {
        *lo = v3(-SHAPE_PLANE_EXTENT, -SHAPE_PLANE_EXTENT, -SHAPE_PLANE_EXTENT);
        *hi = v3(SHAPE_PLANE_EXTENT, SHAPE_PLANE_EXTENT, SHAPE_PLANE_EXTENT);
        return;
    }
    vec3 a, b;
    s->kind->bounds(s, &a, &b);
    if (!s->has_transform) {
        *lo = a;
        *hi = b;
        return;
    }
    if (!s->pose_count) {
        vec3 c, h;
        slice(a, b, pieces > 1 ? long_axis(s, a, b) : 0, piece, pieces, &c, &h);
        mapped_box(s, c, h, lo, hi);
        return;
    }
    /* An affine map sends the object box to a parallelepiped whose extremes
     * are among the images of its eight corners. Between two poses each
     * corner moves in a straight line, so the poses' boxes hold it. */
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (int k = 0; k < s->pose_count; k++)
        for (int i = 0; i < 8; i++) {
            vec3 c = xf_point(&s->poses[k], v3(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z));
            *lo = min3(*lo, c);
            *hi = max3(*hi, c);
        }
}

void shape_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    shape_piece_bounds(s, 0, 1, lo, hi);
}

int shape_max_crossings(const shape *s)
{
    if (s->solid)
        return s->solid->view.triangle_count;
    if (!s->kind->csg)
        return s->kind->max_crossings;
    int sum = 0;
    for (int i = 0; i < s->part_count; i++) {
        int more = shape_max_crossings(&s->family[s->parts[i]]);
        sum = more > INT_MAX - sum ? INT_MAX : sum + more;
    }
    return sum;
}

bool shape_always_closed(const shape *s)
{
    return true;
}

void shape_left_behind_rule(const shape *s, bool *always, bool *when_leaving)
{
    *always = s->kind->flat;
    *when_leaving = s->kind->max_crossings <= 2 && !s->kind->saddle;
}

int shape_left_behind_by(const shape *family, int k, bool *always, bool *when_leaving)
{
    const shape *s = &family[k];
    if (s->part_of < 0) {
        shape_left_behind_rule(s, always, when_leaving);
        return k;
    }
    *always = *when_leaving = false;
    if (!s->convex)
        return -1;
    int top = k;
    for (int child = k, up = s->part_of; up >= 0; child = up, up = family[up].part_of) {
        const shape *c = &family[up];
        bool within = c->desc.kind == GLINT_SHAPE_INTERSECTION ||
                      (c->desc.kind == GLINT_SHAPE_DIFFERENCE && c->part_count > 0 && c->parts[0] == child);
        if (!within)
            return -1;
        top = up;
    }
    *when_leaving = true;
    return top;
}

bool shape_is_left_behind(const shape *s, vec3 n, vec3 d)
{
    bool always, when_leaving;
    shape_left_behind_rule(s, &always, &when_leaving);
    return always || (when_leaving && v3_dot(n, d) > 0);
}

double shape_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    if (!s->kind->sample)
        return 0;
    vec3 p_obj, n_obj;
    double area = s->kind->sample(s, u1, u2, &p_obj, &n_obj);
    if (!s->has_transform) {
        *p = p_obj;
        *n = n_obj;
        return 1 / area;
    }
    /* An affine map M stretches area at a point of unit normal n by
     * |det M| |M^-T n|, which xf_normal's length is. */
    const double (*m)[4] = s->to_world.m;
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    vec3 world_n = xf_normal(&s->to_object, n_obj);
    double stretch = v3_length(world_n);
    *p = xf_point(&s->to_world, p_obj);
    *n = v3_scale(world_n, 1 / stretch);
    return 1 / (area * fabs(det) * stretch);
}

vec3 shape_bounds_middle(const shape *s)
{
    vec3 lo, hi;
    s->kind->bounds(s, &lo, &hi);
    return v3_scale(v3_add(lo, hi), 0.5);
}

__attribute__((noinline)) void shape_surface_moved(const shape *s, double time, const ray *r, const shape_hit *hit,
                                                   surface *out)
{
    shape moved;
    shape_surface(shape_moved(s, time, &moved), r, hit, out);
}
