/* crease_normals.c - smooth normals that keep sharp edges sharp. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "core/vec.h"
#include "io/crease_normals.h"
#include "io/id_table.h"

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

static uint32_t position_hash(const void *keys, uint32_t id)
{
    uint32_t key[3];
    position_key((const float *)keys + 3 * (size_t)id, key);
    return id_hash_words(key, 3);
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
    bool ok = id_table_reserve(&t, count, position_hash, positions);
    for (size_t i = 0; ok && i < count; i++) {
        uint32_t key[3];
        position_key(positions + 3 * i, key);
        ok = id_table_intern(&t, id_hash_words(key, 3), key, (uint32_t)i, position_hash, position_equal, positions,
                             &weld[i]);
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
 * each corner. */
static void faces(const float *positions, const uint32_t *at, size_t count, float *normal, float *angle)
{
    for (size_t t = 0; t < count; t++) {
        vec3 p[3] = {point(positions, at[3 * t]), point(positions, at[3 * t + 1]), point(positions, at[3 * t + 2])};
        vec3 n = v3_cross(v3_sub(p[1], p[0]), v3_sub(p[2], p[0]));
        double len = v3_length(n);
        n = len > 0 && isfinite(len) ? v3_scale(n, 1 / len) : v3(0, 0, 0);
        normal[3 * t] = (float)n.x;
        normal[3 * t + 1] = (float)n.y;
        normal[3 * t + 2] = (float)n.z;
        for (int k = 0; k < 3; k++) {
            vec3 a = v3_sub(p[(k + 1) % 3], p[k]), b = v3_sub(p[(k + 2) % 3], p[k]);
            double cross = v3_length(v3_cross(a, b)), dot = v3_dot(a, b);
            angle[3 * t + k] = isfinite(cross) && isfinite(dot) ? (float)atan2(cross, dot) : 0.0f;
        }
    }
}

/* Lists the corners at each position: around[first[p] .. first[p + 1]]
 * are the corners (3t + k) at position p, in triangle order. */
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

glint_status crease_normals(const float *positions, size_t position_count, const uint32_t *at, size_t count,
                            double crease_degrees, crease_emit_fn emit, void *ctx, const char *file,
                            glint_error *err)
{
    size_t corners = 3 * count; /* count <= 2^30 triangles */
    float *normal = array_alloc(corners, sizeof *normal), *angle = array_alloc(corners, sizeof *angle);
    uint32_t *around = array_alloc(corners, sizeof *around);
    uint32_t *first = position_count < SIZE_MAX ? calloc(position_count + 1, sizeof *first) : NULL;
    glint_status s = GLINT_OK;
    if (!normal || !angle || !around || !first)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    if (!s) {
        faces(positions, at, count, normal, angle);
        corners_around(at, count, position_count, first, around);
    }
    bool everything = crease_degrees >= 180;
    double least = cos(crease_degrees * M_PI / 180);
    for (size_t c = 0; !s && c < corners; c++) {
        size_t t = c / 3;
        const float *own = normal + 3 * t;
        vec3 sum = v3(0, 0, 0);
        for (uint32_t j = first[at[c]]; j < first[at[c] + 1]; j++) {
            size_t u = around[j] / 3;
            const float *n = normal + 3 * u;
            double cosine = (double)n[0] * own[0] + (double)n[1] * own[1] + (double)n[2] * own[2];
            if (u == t || everything || cosine >= least)
                sum = v3_madd(sum, v3(n[0], n[1], n[2]), angle[around[j]]);
        }
        double len = v3_length(sum);
        float out[3] = {own[0], own[1], own[2]};
        if (len > 0 && isfinite(len)) {
            out[0] = (float)(sum.x / len);
            out[1] = (float)(sum.y / len);
            out[2] = (float)(sum.z / len);
        }
        s = emit(ctx, t, (int)(c % 3), out);
    }
    free(normal);
    free(angle);
    free(first);
    free(around);
    return s;
}
