/* crease_normals.c - smooth normals that keep sharp edges sharp. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "core/vec.h"
#include "model/corner_angle.h"
#include "model/crease_normals.h"
#include "core/id_table.h"

/* The bits of a coordinate, with -0 taken as 0. */
static uint32_t coordinate_bits(float x)
{
    uint32_t b;
    memcpy(&b, &x, sizeof b);
    return b == 0x80000000u ? 0 : b;
}

static void position_key(const float *p, uint32_t key[3])
{
    for (int k = 0; k < 3; k++)
        key[k] = coordinate_bits(p[k]);
}

static bool position_equal(const void *keys, uint32_t id, const void *key)
{
    uint32_t stored[3];
    position_key((const float *)keys + 3 * (size_t)id, stored);
    return memcmp(stored, key, sizeof stored) == 0;
}

bool crease_weld(const float *positions, size_t count, uint32_t *weld)
{
    id_table t = {0};
    bool ok = id_table_reserve(&t, count);
    for (size_t i = 0; ok && i < count; i++) {
        uint32_t key[3];
        position_key(positions + 3 * i, key);
        ok = id_table_intern(&t, id_hash_words(key, 3), key, (uint32_t)i, position_equal, positions, &weld[i]);
    }
    id_table_free(&t);
    return ok;
}

static vec3 point(const float *positions, uint32_t i)
{
    const float *p = positions + 3 * (size_t)i;
    return v3(p[0], p[1], p[2]);
}

/* The unit normal of each triangle (zero without area), and its angle at
 * each corner: atan2 of its edges' cross product's length and their dot
 * product. Three edges serve the three corners, and the face's cross
 * product the first: p0 - p1 is exactly -(p1 - p0) in floating point, and
 * a cross or dot product of negated edges is exactly the negated or the
 * same one, so each corner gets the bits its own edges would give. */
static void faces(const float *positions, const uint32_t *at, size_t count, float *normal, float *angle)
{
    for (size_t t = 0; t < count; t++) {
        vec3 p0 = point(positions, at[3 * t]), p1 = point(positions, at[3 * t + 1]),
             p2 = point(positions, at[3 * t + 2]);
        vec3 e01 = v3_sub(p1, p0), e02 = v3_sub(p2, p0), e12 = v3_sub(p2, p1);
        vec3 n = v3_cross(e01, e02);
        double len = v3_length(n);
        angle[3 * t] = corner_angle(len, v3_dot(e01, e02));
        angle[3 * t + 1] = corner_angle(v3_length(v3_cross(e12, e01)), -v3_dot(e12, e01));
        angle[3 * t + 2] = corner_angle(v3_length(v3_cross(e02, e12)), v3_dot(e02, e12));
        n = len > 0 && isfinite(len) ? v3_scale(n, 1 / len) : v3(0, 0, 0);
        normal[3 * t] = (float)n.x;
        normal[3 * t + 1] = (float)n.y;
        normal[3 * t + 2] = (float)n.z;
    }
}

/* Lists the corners at each position: around[first[p] .. first[p + 1]]
 * are the corners (3t + k) at position p, in triangle order until
 * find_cores puts the outliers first. */
static void corners_around(const uint32_t *at, size_t count, size_t position_count, uint32_t *first,
                           uint32_t *around)
{
    for (size_t c = 0; c < 3 * count; c++)
        first[at[c] + 1]++;
    for (size_t p = 0; p < position_count; p++)
        first[p + 1] += first[p];
    for (size_t c = 0; c < 3 * count; c++)
        around[first[at[c]]++] = (uint32_t)c;
    for (size_t p = position_count; p > 0; p--)
        first[p] = first[p - 1];
    first[0] = 0;
}

/* What the corners' normals are computed from. */
typedef struct crease {
    float *normal;            /* each triangle's unit normal (zero without area) */
    float *angle;             /* each corner's angle */
    uint32_t *first, *around; /* the corners at each position (corners_around) */
    uint32_t *outliers;       /* per position: how many of its corners, listed first, are not in its core */
    double *core_sum;         /* per position: the angle-weighted sum of its core faces' normals */
    float *core_unit;         /* per position: that sum made unit, */
    bool *core_has_unit;      /* where it has a length */
    unsigned char *core;      /* per corner: its face is in the core of the faces at its position */
    double least;             /* the cosine of the crease angle */
    bool everything;          /* 180 degrees: every face counts */
} crease;

static const float *face_normal(const crease *k, uint32_t corner)
{
    return k->normal + 3 * (size_t)(corner / 3);
}

static bool is_flat(const float *n)
{
    return n[0] == 0 && n[1] == 0 && n[2] == 0;
}

static double dot(const float *a, const float *b)
{
    return (double)a[0] * b[0] + (double)a[1] * b[1] + (double)a[2] * b[2];
}

/* Adds the angle-weighted normals of the corners around[from .. to) whose
 * faces count for a corner of triangle t with normal own: its own face,
 * those within the crease angle, and those without area (which add
 * nothing). *all, when not NULL, tells whether every one counted. */
static vec3 add_around(const crease *k, vec3 sum, uint32_t from, uint32_t to, size_t t, const float *own,
                       bool *all)
{
    for (uint32_t j = from; j < to; j++) {
        uint32_t c = k->around[j];
        const float *n = face_normal(k, c);
        if (c / 3 == t || k->everything || is_flat(n) || dot(n, own) >= k->least)
            sum = v3_madd(sum, v3(n[0], n[1], n[2]), k->angle[c]);
        else if (all)
            *all = false;
    }
    return sum;
}

/* Sets out to sum made unit; false when sum has no length (or not a
 * finite one). */
static bool unit(vec3 sum, float *out)
{
    double len = v3_length(sum);
    if (!(len > 0 && isfinite(len)))
        return false;
    out[0] = (float)(sum.x / len);
    out[1] = (float)(sum.y / len);
    out[2] = (float)(sum.z / len);
    return true;
}

/* Puts the faces around[lo .. hi) at one position that are not within
 * `half` (a cosine) of their unweighted mean normal first, marking the
 * others as core; returns where the core starts. */
static uint32_t split_outliers(crease *k, uint32_t lo, uint32_t hi, double half)
{
    uint32_t split = lo;
    vec3 mean = v3(0, 0, 0);
    for (uint32_t j = lo; j < hi; j++) {
        const float *n = face_normal(k, k->around[j]);
        mean = v3_add(mean, v3(n[0], n[1], n[2]));
    }
    mean = v3_normalize(mean);
    float ref[3] = {(float)mean.x, (float)mean.y, (float)mean.z};
    for (uint32_t j = lo; j < hi; j++) {
        uint32_t c = k->around[j];
        const float *n = face_normal(k, c);
        k->core[c] = is_flat(n) || (!is_flat(ref) && dot(n, ref) >= half);
        if (!k->core[c]) {
            k->around[j] = k->around[split];
            k->around[split++] = c;
        }
    }
    return split;
}

/* Splits the faces around each position into a core, all within half the
 * crease angle (less a margin for rounding) of their unweighted mean
 * normal and so within the crease angle of each other, and the outliers,
 * listed first; at 180 degrees every face is in the core. The core's sum
 * is made once, and made unit once: a corner whose face is in the core
 * then adds only the outliers that count for it. So a point that
 * thousands of faces share (the centre of a fan, a cone's apex) costs
 * their count times its few outliers, not the square of their count. */
static void find_cores(crease *k, size_t position_count, size_t corners, double crease_degrees)
{
    double half = cos(fmax(crease_degrees / 2 - 0.01, 0) * M_PI / 180);
    if (k->everything)
        memset(k->core, 1, corners);
    for (uint32_t p = 0; p < position_count; p++) {
        uint32_t lo = k->first[p], hi = k->first[p + 1];
        uint32_t split = k->everything ? lo : split_outliers(k, lo, hi, half);
        vec3 sum = v3(0, 0, 0);
        for (uint32_t j = split; j < hi; j++) {
            const float *n = face_normal(k, k->around[j]);
            sum = v3_madd(sum, v3(n[0], n[1], n[2]), k->angle[k->around[j]]);
        }
        k->outliers[p] = split - lo;
        memcpy(k->core_sum + 3 * (size_t)p, &sum, 3 * sizeof(double));
        k->core_has_unit[p] = unit(sum, k->core_unit + 3 * (size_t)p);
    }
}

/* Outliers at one position past which its corners do not go through them:
 * each corner would cost their count, and a fan cut across a polygon of
 * 100,000 zigzag corners has 50,000 outliers at its centre (faces turned
 * the other way), which took minutes. */
#define MAX_OUTLIERS 64

/* The normal of corner c: the sum of the faces around its position that
 * count for it, the core's first, then the outliers. The core's sum made
 * once stands for its faces whenever they all count (always for a corner
 * whose face is in the core), so that corners that count the same faces
 * get the very same normal, and become one vertex. Where more than
 * MAX_OUTLIERS faces lie outside the core, a core corner takes the core's
 * sum alone and any other its own face's normal. */
static void corner_normal(const crease *k, const uint32_t *at, size_t c, float *out)
{
    size_t t = c / 3;
    uint32_t p = at[c], lo = k->first[p], mid = lo + k->outliers[p], hi = k->first[p + 1];
    const float *own = k->normal + 3 * t;
    /* Every face counts at 180 degrees, and with no outliers for a corner
     * whose face is in the core: the core's unit sum is its normal. */
    if (k->core_has_unit[p] && (k->everything || (lo == mid && k->core[c] && !is_flat(own)))) {
        memcpy(out, k->core_unit + 3 * (size_t)p, 3 * sizeof *out);
        return;
    }
    bool alone = !k->core[c] || is_flat(own); /* the core's sum may not stand for its faces */
    const double *core = k->core_sum + 3 * (size_t)p;
    vec3 sum = v3(core[0], core[1], core[2]);
    if (k->outliers[p] > MAX_OUTLIERS) {
        if (alone)
            sum = v3(own[0], own[1], own[2]);
    } else {
        if (alone) {
            bool all = true;
            vec3 part = add_around(k, v3(0, 0, 0), mid, hi, t, own, &all);
            if (!all)
                sum = part;
        }
        sum = add_around(k, sum, lo, mid, t, own, NULL);
    }
    if (!unit(sum, out))
        memcpy(out, own, 3 * sizeof *out);
}

glint_status crease_normals(const float *positions, size_t position_count, const uint32_t *at, size_t count,
                            double crease_degrees, crease_emit_fn emit, void *ctx, const char *file,
                            glint_error *err)
{
    size_t corners = 3 * count; /* count <= 2^30 triangles */
    crease k = {
        .normal = array_alloc(corners, sizeof(float)), .angle = array_alloc(corners, sizeof(float)),
        .around = array_alloc(corners, sizeof(uint32_t)), .core = array_alloc(corners, 1),
        .first = position_count < SIZE_MAX ? calloc(position_count + 1, sizeof(uint32_t)) : NULL,
        .outliers = array_alloc(position_count, sizeof(uint32_t)),
        .core_sum = array_alloc(position_count, 3 * sizeof(double)),
        .core_unit = array_alloc(position_count, 3 * sizeof(float)),
        .core_has_unit = array_alloc(position_count, sizeof(bool)),
        .least = cos(crease_degrees * M_PI / 180), .everything = crease_degrees >= 180,
    };
    glint_status s = GLINT_OK;
    if (!k.normal || !k.angle || !k.around || !k.core || !k.first || !k.outliers || !k.core_sum || !k.core_unit ||
        !k.core_has_unit)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    if (!s) {
        faces(positions, at, count, k.normal, k.angle);
        corners_around(at, count, position_count, k.first, k.around);
        find_cores(&k, position_count, corners, crease_degrees);
    }
    for (size_t c = 0; !s && c < corners; c++) {
        float out[3];
        corner_normal(&k, at, c, out);
        s = emit(ctx, c / 3, (int)(c % 3), out);
    }
    free(k.normal);
    free(k.angle);
    free(k.around);
    free(k.core);
    free(k.first);
    free(k.outliers);
    free(k.core_sum);
    free(k.core_unit);
    free(k.core_has_unit);
    return s;
}
