/* view_frame.c - placing a camera so that a box fills a share of the
 * picture. The camera's orientation is given; what is left is where it
 * stands: how far back (so that the box fits) and how far to the side and
 * up (so that it is centred). Perspective makes the near corners project
 * larger than the far ones, so the box's centre is in general not the
 * picture's: each axis of the picture is centred on its own. */
#include <math.h>
#include "builtin/view_frame.h"

/* The corners in the camera's frame, relative to the box's centre: across
 * (x), up (y) and along the view (z). */
typedef struct corners {
    double x[8], y[8], z[8];
} corners;

/* How far back from the box's centre the camera must stand for every
 * corner's coordinate c (x or y) to be within k times its depth of the
 * picture's centre line, after the best sideways shift: the frustum's two
 * planes (c - shift = +-k (z + back)) each touch a corner. */
static double back_to_fit(const double *c, const double *z, double k)
{
    double right = -INFINITY, left = -INFINITY;
    for (int i = 0; i < 8; i++) {
        right = fmax(right, c[i] - k * z[i]);
        left = fmax(left, -c[i] - k * z[i]);
    }
    return (right + left) / (2 * k);
}

/* The sideways shift that centres the corners' projections c / (z + back)
 * along one axis of the picture: where the largest and the smallest meet
 * at equal distances from the centre. Their sum falls as the shift grows
 * (every depth is positive), so bisection finds it between the smallest and
 * the largest coordinate. */
static double shift_to_centre(const double *c, const double *z, double back)
{
    double lo = c[0], hi = c[0];
    for (int i = 1; i < 8; i++) {
        lo = fmin(lo, c[i]);
        hi = fmax(hi, c[i]);
    }
    for (int step = 0; step < 100 && lo < hi; step++) {
        double mid = 0.5 * (lo + hi), most = -INFINITY, least = INFINITY;
        for (int i = 0; i < 8; i++) {
            double p = (c[i] - mid) / (z[i] + back);
            most = fmax(most, p);
            least = fmin(least, p);
        }
        if (most + least > 0)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

glint_camera view_frame_box(vec3 lo, vec3 hi, vec3 forward, vec3 up, double vfov, double aspect, double share)
{
    vec3 f = v3_normalize(forward), r = v3_normalize(v3_cross(f, up)), u = v3_cross(r, f);
    vec3 centre = v3_scale(v3_add(lo, hi), 0.5);
    corners k;
    double nearest = 0;
    for (int i = 0; i < 8; i++) {
        vec3 p = v3_sub(v3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z), centre);
        k.x[i] = v3_dot(p, r);
        k.y[i] = v3_dot(p, u);
        k.z[i] = v3_dot(p, f);
        nearest = fmin(nearest, k.z[i]);
    }
    double ky = share * tan(vfov * M_PI / 360), kx = ky * aspect;
    /* A box flat in both directions across the view (a point) fits at any
     * distance: stand a little in front of it all the same. */
    double size = v3_length(v3_sub(hi, lo));
    double back = fmax(fmax(back_to_fit(k.x, k.z, kx), back_to_fit(k.y, k.z, ky)), -nearest + 1e-3 * size + 1e-9);
    double across = shift_to_centre(k.x, k.z, back), upward = shift_to_centre(k.y, k.z, back);
    vec3 position = v3_madd(v3_madd(v3_madd(centre, r, across), u, upward), f, -back);
    return (glint_camera){.position = position, .look_at = v3_madd(position, f, back), .up = up, .vfov_degrees = vfov};
}
