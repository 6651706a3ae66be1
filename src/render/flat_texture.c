/* flat_texture.c - a texture read at four hits on one flat shape at once.
 * On a flat shape without a transform, a planar mapping's coordinates and
 * the footprint a sample covers are a few products of the hit, its ray and
 * the shape's normal, the same for every lane but the numbers: lane by
 * lane (hit_texture_where) their chains of dependent products were 12% of
 * a tiled floor's time, and each lane's read went through a gather
 * (texture_read_colors8). Here they run a quad of lanes at a time, the same
 * operations in the same order (lanes.h), and the quad goes straight to
 * the image's four-lane look-up. */
#include "render/flat_texture.h"

bool flat_texture_on_quads(const texture *t)
{
    if (t->kind->solid)
        return t->kind->solid4 && !t->placed;
    return t->mapping.kind == GLINT_MAP_PLANAR;
}

/* copysign(x, of) in every lane, x positive: x's bits with of's sign. */
static quad_f64 quad_with_sign(double x, quad_f64 of)
{
    quad_mask bits, sign;
    quad_f64 magnitude = quad_splat(x);
    memcpy(&sign, &of, sizeof sign);
    memcpy(&bits, &magnitude, sizeof bits);
    bits |= sign & (quad_mask){INT64_MIN, INT64_MIN, INT64_MIN, INT64_MIN};
    memcpy(&magnitude, &bits, sizeof magnitude);
    return magnitude;
}

/* surface_coords.c's linear_reach2 in every lane: how far the linear
 * function of gradient g reaches over a footprint of radius 1, squared. */
static quad_f64 linear_reach2_4(vec3 g, const quad_f64 n[3], const quad_f64 d[3], quad_f64 inv_cos)
{
    quad_f64 along = -(g.x * d[0] + g.y * d[1] + g.z * d[2]) * inv_cos;
    quad_f64 h[3] = {g.x + n[0] * along, g.y + n[1] * along, g.z + n[2] * along};
    quad_f64 off = -quad_dot(h[0], h[1], h[2], d[0], d[1], d[2]);
    quad_f64 square[3] = {h[0] + d[0] * off, h[1] + d[1] * off, h[2] + d[2] * off};
    return quad_dot(square[0], square[1], square[2], square[0], square[1], square[2]);
}

/* Gathers lanes lane[0] to lane[count - 1] (count under QUAD) of each of
 * the `quads` quads in[] into the first lanes of out[]: a kind's four-lane
 * look-ups read their first lanes. */
static void quads_gather(const quad_f64 in[], quad_f64 out[], int quads, const int lane[QUAD], int count)
{
    for (int q = 0; q < quads; q++) {
        out[q] = quad_splat(0);
        for (int l = 0; l < count; l++)
            out[q][l] = in[q][lane[l]];
    }
}

/* Texture t's colours at the first `count` lanes of p (a solid texture's
 * points) or of read (where a texture of (u, v) reads, and the footprint's
 * squared extents along u and v), channel c of lane l into got[c][l]. */
static void read_lanes(const texture *t, const quad_f64 p[3], const quad_f64 read[4], int count, quad_f64 got[3])
{
    if (t->kind->solid) {
        color c[QUAD];
        t->kind->solid4(t, p, count, c);
        for (int l = 0; l < count; l++) {
            got[0][l] = c[l].r;
            got[1][l] = c[l].g;
            got[2][l] = c[l].b;
        }
    } else if (t->kind->eval4) {
        t->kind->eval4(t, read[0], read[1], read[2], read[3], count, got);
    } else {
        for (int l = 0; l < count; l++) {
            color c = texture_at_placed(t, read[0][l], read[1][l], (uv_extent){read[2][l], read[3][l]});
            got[0][l] = c.r;
            got[1][l] = c.g;
            got[2][l] = c.b;
        }
    }
}

void flat_texture_colors4(const texture *t, const quad_f64 p[3], const quad_f64 n[3], const quad_f64 d[3],
                          quad_f64 width, quad_mask wanted, quad_f64 out[3])
{
    int lane[QUAD], count = 0;
    for (int k = 0; k < QUAD; k++)
        if (wanted[k])
            lane[count++] = k;
    if (!count)
        return;
    /* Zeroed a quad at a time: as an initialiser GCC clears the array with
     * rep stos, which takes longer to start than the planar arithmetic. */
    quad_f64 read[4];
    for (int q = 0; q < 4; q++)
        read[q] = quad_splat(0);
    if (!t->kind->solid) {
        /* planar_map_apply, and coord_footprint with the planar mapping's
         * gradients, for each lane. */
        const planar_map *map = &t->planar;
        read[0] = map->g_u.x * p[0] + map->g_u.y * p[1] + map->g_u.z * p[2] + map->u0;
        read[1] = map->g_v.x * p[0] + map->g_v.y * p[1] + map->g_v.z * p[2] + map->v0;
        if (texture_filters(t)) {
            /* A ray nearly along the surface stretches the footprint a
             * million times at most. */
            quad_f64 cos_t = quad_dot(d[0], d[1], d[2], n[0], n[1], n[2]);
            quad_f64 inv_cos = 1 / quad_select(quad_abs(cos_t) > 1e-6, cos_t, quad_with_sign(1e-6, cos_t));
            quad_f64 width2 = width * width;
            quad_mask measured = width > 0;
            read[2] = quad_select(measured, width2 * linear_reach2_4(map->g_u, n, d, inv_cos), quad_splat(0));
            read[3] = quad_select(measured, width2 * linear_reach2_4(map->g_v, n, d, inv_cos), quad_splat(0));
        }
    }
    if (count == QUAD) {
        /* Every lane, in order: the quads as they are, never copied (a
         * copy's loads of 32 bytes from stores of 16, or of 8 a lane, wait
         * for the stores: 14% of a tiled floor's packet time). */
        read_lanes(t, p, read, QUAD, out);
        return;
    }
    quad_f64 at[3], in[4], got[3];
    quads_gather(p, at, 3, lane, count);
    quads_gather(read, in, 4, lane, count);
    read_lanes(t, at, in, count, got);
    for (int c = 0; c < 3; c++)
        for (int l = 0; l < count; l++)
            out[c][lane[l]] = got[c][l];
}
