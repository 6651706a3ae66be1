/* transform.c - building and inverting affine transforms (public API part). */
#include <math.h>
#include <string.h>
#include "core/poses.h"
#include "core/transform.h"

glint_transform glint_transform_identity(void)
{
    transform t;
    memset(&t, 0, sizeof t);
    t.m[0][0] = t.m[1][1] = t.m[2][2] = 1.0;
    return t;
}

transform xf_mul(const transform *a, const transform *b)
{
    transform r;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            double s = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] + a->m[i][2] * b->m[2][j];
            r.m[i][j] = j == 3 ? s + a->m[i][3] : s;
        }
    }
    return r;
}

glint_transform glint_transform_translate(glint_transform t, double x, double y, double z)
{
    t.m[0][3] += x;
    t.m[1][3] += y;
    t.m[2][3] += z;
    return t;
}

glint_transform glint_transform_rotate(glint_transform t, glint_vec3 axis, double degrees)
{
    double len = v3_length(axis);
    if (!(len > 0 && isfinite(len))) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                t.m[i][j] = NAN;
        return t;
    }
    vec3 a = v3_scale(axis, 1.0 / len);
    double th = degrees * (M_PI / 180.0), c = cos(th), s = sin(th), k = 1.0 - c;
    transform r = glint_transform_identity();
    /* Rodrigues' rotation matrix. */
    r.m[0][0] = c + a.x * a.x * k;       r.m[0][1] = a.x * a.y * k - a.z * s; r.m[0][2] = a.x * a.z * k + a.y * s;
    r.m[1][0] = a.y * a.x * k + a.z * s; r.m[1][1] = c + a.y * a.y * k;       r.m[1][2] = a.y * a.z * k - a.x * s;
    r.m[2][0] = a.z * a.x * k - a.y * s; r.m[2][1] = a.z * a.y * k + a.x * s; r.m[2][2] = c + a.z * a.z * k;
    return xf_mul(&r, &t);
}

glint_transform glint_transform_scale(glint_transform t, double x, double y, double z)
{
    transform s = glint_transform_identity();
    s.m[0][0] = x;
    s.m[1][1] = y;
    s.m[2][2] = z;
    return xf_mul(&s, &t);
}

glint_vec3 glint_transform_point(const glint_transform *t, glint_vec3 p)
{
    return xf_point(t, p);
}

bool xf_invert(const transform *t, transform *inv)
{
    const double (*m)[4] = t->m;
    double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    double scale = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            scale = fmax(scale, fabs(m[i][j]));
    if (!isfinite(det) || scale == 0 || fabs(det) <= 1e-12 * scale * scale * scale)
        return false;
    double id = 1.0 / det;
    double (*r)[4] = inv->m;
    r[0][0] = c00 * id;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
    r[1][0] = c01 * id;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
    r[2][0] = c02 * id;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
    for (int i = 0; i < 3; i++)
        r[i][3] = -(r[i][0] * m[0][3] + r[i][1] * m[1][3] + r[i][2] * m[2][3]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(r[i][j]))
                return false;
    return true;
}

bool xf_is_identity(const transform *t)
{
    transform id = glint_transform_identity();
    return memcmp(t, &id, sizeof id) == 0;
}

void xf_between(const transform *poses, int count, double time, transform *to_world, transform *to_object)
{
    int k;
    double w;
    pose_stretch(time, count, &k, &w);
    const transform *a = &poses[k], *b = &poses[k + 1];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            to_world->m[i][j] = a->m[i][j] + (b->m[i][j] - a->m[i][j]) * w;
    if (!xf_invert(to_world, to_object)) {
        *to_world = w < 0.5 ? *a : *b;
        xf_invert(to_world, to_object);
    }
}
