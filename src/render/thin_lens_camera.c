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

static void thin_lens_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                            const double time[RAY8], ray8 *out)
{
    (void)time;
    for (int i = 0; i < RAY8; i += QUAD) {
        quad_f64 dx, dy, dz;
        camera_plane_directions(c, quad_load(x + i), quad_load(y + i), &dx, &dy, &dz);
        double ex[QUAD], ey[QUAD], ez[QUAD];
        quad_store(ex, dx);
        quad_store(ey, dy);
        quad_store(ez, dz);
        for (int k = 0; k < QUAD; k++) {
            vec3 d = {ex[k], ey[k], ez[k]};
            vec3 focus = v3_add(c->position, v3_scale(d, c->focus_distance / v3_dot(d, c->forward)));
            double lx, ly;
            if (c->blades)
                polygon_point(c->blades, lens->u[i + k], lens->v[i + k], &lx, &ly);
            else
                concentric_disk(lens->u[i + k], lens->v[i + k], &lx, &ly);
            vec3 from = v3_add(c->position, v3_add(v3_scale(c->right, c->lens_radius * lx),
                                                   v3_scale(c->up, c->lens_radius * ly)));
            vec3 dir = v3_normalize(v3_sub(focus, from));
            camera_ray_put(out, i + k, from, dir);
        }
    }
}

const camera_kind thin_lens_camera = {
    .name = "thin_lens",
    .id = GLINT_CAMERA_THIN_LENS,
    .uses_lens = true,
    .init = thin_lens_init,
    .rays8 = thin_lens_rays8,
};
