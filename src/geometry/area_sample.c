/* area_sample.c - what the shape kinds share to pick points on their
 * surfaces uniformly by area, for emissive shapes that light a scene:
 * choosing a part (a face, a cap) by its area, and a point of a triangle. */
#include <math.h>
#include "geometry/shape_math.h"

int pick_by_area(const double *area, int n, double *u, double *total)
{
    *total = 0;
    for (int i = 0; i < n; i++)
        *total += area[i];
    double at = *u * *total;
    for (int i = 0; i < n; i++) {
        if (at < area[i] || i == n - 1) {
            double stretched = area[i] > 0 ? at / area[i] : 0;
            *u = stretched < 1 ? stretched : nextafter(1.0, 0.0);
            return i;
        }
        at -= area[i];
    }
    return 0;
}

vec3 triangle_point(vec3 a, vec3 b, vec3 c, double u1, double u2)
{
    double s = sqrt(u1);
    return v3_add(a, v3_add(v3_scale(v3_sub(b, a), s * (1 - u2)), v3_scale(v3_sub(c, a), s * u2)));
}
