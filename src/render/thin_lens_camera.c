/* thin_lens_camera.c - the thin lens: depth of field. The pinhole's ray
 * through an image position crosses the plane of focus (focus_distance
 * along the view direction) at one point; the thin lens's ray for a lens
 * sample starts at that sample's point on a disk of radius `aperture`
 * (or the radius an f-number gives) about the camera's position, across the view, and goes to that point.
 * Points on the plane of focus are sharp; a point at depth d blurs into a
 * disk 2 * aperture * |1/focus - 1/d| across on the image plane at
 * distance 1. The lens sample is spread over the disk by the concentric
 * map (Shirley and Chiu 1997), which keeps a stratified sample stratified,
 * or with `blades` over a regular polygon of that radius, one vertex up:
 * the shape out-of-focus highlights take (bokeh). */
#include <math.h>
#include "core/square_maps.h"
#include "render/camera_kind.h"

/* The width of a full-frame (35 mm film) sensor, 36 mm, in metres: what an
 * f-number is relative to when the scene gives no sensor_width. */
#define FULL_FRAME_WIDTH 0.036

/* The lens's radius for an f-number: the focal length over twice N, the
 * focal length being the distance at which a sensor sensor_width wide
 * spans the horizontal field of view (fov is the vertical one). */
static double f_number_radius(const glint_camera *d, int width, int height)
{
    double sensor = d->sensor_width > 0 ? d->sensor_width : FULL_FRAME_WIDTH;
    double half_width = tan(d->vfov_degrees * M_PI / 360) * width / height;
    return sensor / (2 * half_width) / (2 * d->f_number);
}

static void thin_lens_init(camera *c, const glint_camera *d, int width, int height)
{
    camera_frame_init(c, d, width, height);
    c->lens_radius = d->f_number > 0 ? f_number_radius(d, width, height) : d->aperture;
    c->blades = d->blades;
    /* 0: focused on look_at, at its depth along the view. */
    c->focus_distance = d->focus_distance > 0 ? d->focus_distance : v3_length(v3_sub(d->look_at, d->position));
}

/* The point of the regular polygon of `blades` sides inscribed in the unit
 * circle, one vertex up, for (u, v) in [0, 1)^2, uniform over its area: u
 * picks the triangle between the centre and one side (and, rescaled, the
 * distance from the centre), v the place along the side. */
static void polygon_point(int blades, double u, double v, double *x, double *y)
{
    double side = floor(u * blades), t = u * blades - side;
    double a0 = M_PI / 2 + 2 * M_PI * side / blades, a1 = a0 + 2 * M_PI / blades, r = sqrt(t);
    *x = r * ((1 - v) * cos(a0) + v * cos(a1));
    *y = r * ((1 - v) * sin(a0) + v * sin(a1));
}

/* Each lane's ray, four lanes at a time: everything (but a polygon's
 * points, one by one) as v3_* would work it out but for four lanes at
 * once, so that each square root and division overlaps three others
 * instead of waiting for the last (the same bytes). The packet's two
 * quads go through each step together: one quad's chain of square roots
 * and divisions is long enough that the processor would otherwise wait
 * on it before it reached the other's. */
static void thin_lens_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                            const double time[RAY8], ray8 *out)
{
    (void)time;
    enum { QUADS = RAY8 / QUAD };
    quad_f64 fx[QUADS], fy[QUADS], fz[QUADS], lx[QUADS], ly[QUADS];
#pragma GCC unroll 2
    for (int q = 0; q < QUADS; q++) {
        quad_f64 dx, dy, dz;
        camera_plane_directions(c, quad_load(x + q * QUAD), quad_load(y + q * QUAD), &dx, &dy, &dz);
        /* Where the pinhole's ray crosses the plane of focus. */
        quad_f64 along = quad_splat(c->focus_distance) /
                         quad_dot(dx, dy, dz, quad_splat(c->forward.x), quad_splat(c->forward.y),
                                  quad_splat(c->forward.z));
        fx[q] = c->position.x + dx * along;
        fy[q] = c->position.y + dy * along;
        fz[q] = c->position.z + dz * along;
    }
    if (c->blades) {
        for (int q = 0; q < QUADS; q++) {
            double px[QUAD], py[QUAD];
            for (int k = 0; k < QUAD; k++)
                polygon_point(c->blades, lens->u[q * QUAD + k], lens->v[q * QUAD + k], &px[k], &py[k]);
            lx[q] = quad_load(px);
            ly[q] = quad_load(py);
        }
    } else {
#pragma GCC unroll 2
        for (int q = 0; q < QUADS; q++)
            concentric_disk_quad(quad_load(lens->u + q * QUAD), quad_load(lens->v + q * QUAD), &lx[q], &ly[q]);
    }
#pragma GCC unroll 2
    for (int q = 0; q < QUADS; q++) {
        quad_f64 rx = c->lens_radius * lx[q], ry = c->lens_radius * ly[q];
        quad_f64 ox = c->position.x + (c->right.x * rx + c->up.x * ry);
        quad_f64 oy = c->position.y + (c->right.y * rx + c->up.y * ry);
        quad_f64 oz = c->position.z + (c->right.z * rx + c->up.z * ry);
        quad_f64 wx = fx[q] - ox, wy = fy[q] - oy, wz = fz[q] - oz;
        quad_f64 length = quad_sqrt(quad_dot(wx, wy, wz, wx, wy, wz));
        quad_mask positive = length > 0;
        quad_f64 inverse = 1.0 / length;
        int i = q * QUAD;
        quad_store(out->ox + i, ox);
        quad_store(out->oy + i, oy);
        quad_store(out->oz + i, oz);
        quad_store(out->dx + i, quad_select(positive, wx * inverse, wx));
        quad_store(out->dy + i, quad_select(positive, wy * inverse, wy));
        quad_store(out->dz + i, quad_select(positive, wz * inverse, wz));
    }
}

const camera_kind thin_lens_camera = {
    .name = "thin_lens",
    .id = GLINT_CAMERA_THIN_LENS,
    .uses_lens = true,
    .init = thin_lens_init,
    .rays8 = thin_lens_rays8,
};
