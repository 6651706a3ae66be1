/* camera_kind.h - one record per kind of camera, and the registry that
 * lists them.
 *
 * A kind is one file (pinhole_camera.c, ...) that exports one camera_kind:
 * its name and its two operations. Adding a kind: write its file, add a
 * line to camera.c's list, and a glint_camera_kind for it in glint.h. */
#ifndef GLINT_RENDER_CAMERA_KIND_H
#define GLINT_RENDER_CAMERA_KIND_H

#include "core/lanes.h"
#include "render/camera.h"

struct camera_kind {
    const char *name;
    glint_camera_kind id;
    bool uses_lens;           /* its rays depend on the lens sample: the renderer makes them */
    /* Fills c's values (all but c->kind) from the scene's camera, which
     * has passed camera_validate, for an image of width x height pixels. */
    void (*init)(camera *c, const glint_camera *desc, int width, int height);
    /* camera_rays8: called for every packet of camera rays, so it works
     * on the lanes side by side. */
    void (*rays8)(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                  const double time[RAY8], ray8 *out);
};

/* A pinhole: every ray starts at the camera's position; the lens sample
 * and the time are ignored. */
extern const camera_kind pinhole_camera;

/* A thin lens: rays start on a disk of radius desc->aperture about the
 * camera's position, across the view, and meet where the pinhole's ray
 * through the same image position crosses the plane of focus. */
extern const camera_kind thin_lens_camera;

/* Parallel rays from a rectangle across the view (orthographic_camera.c),
 * every direction as a panorama (equirectangular_camera.c), and the
 * equidistant fisheye (fisheye_camera.c); none uses the lens sample. */
extern const camera_kind orthographic_camera, equirectangular_camera, fisheye_camera;

/* Puts the ray from `from` along unit `dir` into lane i of *out. */
static inline void camera_ray_put(ray8 *out, int i, vec3 from, vec3 dir)
{
    out->ox[i] = from.x;
    out->oy[i] = from.y;
    out->oz[i] = from.z;
    out->dx[i] = dir.x;
    out->dy[i] = dir.y;
    out->dz[i] = dir.z;
}

/* What every kind that looks through an image plane shares: c's frame
 * (forward, right, up), size and per_x, per_y from the scene's camera,
 * and a pixel's footprint through the plane (cone_width, cone_spread). */
void camera_frame_init(camera *c, const glint_camera *desc, int width, int height);

/* The unit directions through the image positions (x[k], y[k]) of four
 * rays from the camera's position: no division but the normalisation's,
 * and the image centre and every pixel edge there map exactly onto the
 * view axis. Each lane is what the same steps in scalar code would give. */
static inline void camera_plane_directions(const camera *c, quad_f64 x, quad_f64 y, quad_f64 *dx, quad_f64 *dy,
                                           quad_f64 *dz)
{
    vec3 f = c->forward, r = c->right, u = c->up;
    quad_f64 sx = (quad_splat(2) * x - quad_splat(c->width)) * quad_splat(c->per_x);
    quad_f64 sy = (quad_splat(c->height) - quad_splat(2) * y) * quad_splat(c->per_y);
    quad_f64 ex = quad_splat(f.x) + (quad_splat(r.x) * sx + quad_splat(u.x) * sy);
    quad_f64 ey = quad_splat(f.y) + (quad_splat(r.y) * sx + quad_splat(u.y) * sy);
    quad_f64 ez = quad_splat(f.z) + (quad_splat(r.z) * sx + quad_splat(u.z) * sy);
    quad_f64 l = quad_sqrt(ex * ex + ey * ey + ez * ez);
    quad_f64 inv = quad_select(l > 0, quad_splat(1) / l, quad_splat(1));
    *dx = ex * inv;
    *dy = ey * inv;
    *dz = ez * inv;
}

/* The kind with that name, or NULL. */
const camera_kind *camera_kind_named(const char *name);

/* The kind the scene's camera asks for (desc->kind). */
const camera_kind *camera_kind_for(const glint_camera *desc);

#endif
