/* accel_build.c - building the Embree device and scenes, and releasing them:
 * the shapes' user geometry (planes set aside for the queries), each sphere
 * set's own, each mesh
 * placed once as world-space triangles of the top scene, and a mesh placed
 * more often as one triangle scene placed by Embree instances. Building
 * stops when the caller's cancel flag is set. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include "accel/accel_internal.h"
#include "core/error.h"

static void error_fn(void *user, enum RTCError code, const char *str)
{
    glint_error *err = user;
    if (!err || err->message[0] != '\0')
        return;
    if (code == RTC_ERROR_CANCELLED)
        error_set(err, GLINT_ERR_CANCELLED, "render cancelled");
    else if (code == RTC_ERROR_OUT_OF_MEMORY)
        error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    else
        error_set(err, GLINT_ERR_EMBREE, "embree error %d: %s", (int)code, str ? str : "");
}

/* Embree's build progress: false (stop building) once the caller's cancel
 * flag is set, so an interrupted render does not wait for a large mesh's
 * BVH. */
static bool build_progress(void *user, double done)
{
    (void)done;
    const accel *a = user;
    return !(a->cancel && *a->cancel);
}

/* Sorts the shapes into planes, which the queries test themselves (an
 * unbounded plane would be a candidate for every ray, through a callback),
 * and the rest, one user-geometry primitive for each piece of their bounds
 * (shape_pieces: a long shape at a slant is more than one box); the parts
 * of combinations are met only through them. False when memory runs out. */
static bool sort_shapes(accel *a)
{
    unsigned char *pieces = malloc((size_t)a->shape_count + 1);
    a->planes = malloc(((size_t)a->shape_count + 1) * sizeof *a->planes);
    if (!pieces || !a->planes) {
        free(pieces);
        return false;
    }
    size_t prims = 0;
    for (int i = 0; i < a->shape_count; i++) {
        const shape *s = &a->shapes[i];
        pieces[i] = 0;
        /* Sphere sets are geometries of their own (add_sphere_sets). */
        if (s->part_of >= 0 || s->set)
            continue;
        if (!shape_is_bounded(s))
            a->planes[a->plane_count++] = i;
        else
            prims += pieces[i] = (unsigned char)shape_pieces(s);
    }
    a->prim_shape = malloc((prims + 1) * sizeof *a->prim_shape);
    a->prim_piece = malloc(prims + 1);
    a->prim_pieces = malloc(prims + 1);
    bool ok = a->prim_shape && a->prim_piece && a->prim_pieces && prims <= INT_MAX;
    for (int i = 0; ok && i < a->shape_count; i++)
        for (int k = 0; k < pieces[i]; k++) {
            a->prim_piece[a->prim_count] = (unsigned char)k;
            a->prim_pieces[a->prim_count] = pieces[i];
            a->prim_shape[a->prim_count++] = i;
        }
    free(pieces);
    return ok;
}

static void add_shapes(accel *a)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, (unsigned)a->prim_count);
    rtcSetGeometryUserData(g, a);
    rtcSetGeometryBoundsFunction(g, accel_shape_bounds, a);
    rtcSetGeometryIntersectFunction(g, accel_shape_intersect);
    rtcSetGeometryOccludedFunction(g, accel_shape_occluded);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->scene, g, SHAPES_ID);
    rtcReleaseGeometry(g);
}

/* Each sphere set as a user geometry of its own, one primitive per
 * sphere, after the instances' IDs. */
static void add_sphere_sets(accel *a)
{
    unsigned id = 1u + (unsigned)a->instance_count;
    for (int i = 0; i < a->shape_count; i++) {
        const shape *s = &a->shapes[i];
        if (!s->set)
            continue;
        RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, (unsigned)s->set->count);
        rtcSetGeometryUserData(g, (void *)s);
        rtcSetGeometryBoundsFunction(g, accel_spheres_bounds, (void *)s);
        rtcSetGeometryIntersectFunction(g, accel_spheres_intersect);
        rtcSetGeometryOccludedFunction(g, accel_spheres_occluded);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(a->scene, g, id++);
        rtcReleaseGeometry(g);
    }
}

/* A triangle geometry over the mesh's indices, with the given vertices and,
 * unless every placement of it is opaque, the shadow filter. */
static RTCGeometry triangles(accel *a, const mesh *m, const float *positions, bool opaque)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions, 0, 3 * sizeof(float),
                               (size_t)m->vertex_count);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m->indices, 0, 3 * sizeof(uint32_t),
                               (size_t)m->triangle_count);
    if (!opaque)
        rtcSetGeometryOccludedFilterFunction(g, accel_triangle_occluded);
    rtcSetGeometryBuildQuality(g, a->quality);
    rtcCommitGeometry(g);
    return g;
}

/* A triangle scene over the mesh's own arrays: shared, not copied. */
static RTCScene mesh_scene(accel *a, const mesh *m, bool opaque)
{
    RTCScene s = rtcNewScene(a->device);
    rtcSetSceneBuildQuality(s, a->quality);
    rtcSetSceneProgressMonitorFunction(s, build_progress, a);
    RTCGeometry g = triangles(a, m, m->positions, opaque);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    return s;
}

/* An Embree instance of the mesh's scene; a moving placement with one
 * time step a pose, which Embree blends as instance_at does. */
static void add_instance(accel *a, const instance *inst, unsigned id)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, a->mesh_scenes[inst->mesh]);
    int steps = inst->pose_count ? inst->pose_count : 1;
    rtcSetGeometryTimeStepCount(g, (unsigned)steps);
    for (int k = 0; k < steps; k++) {
        const transform *xf = inst->pose_count ? &inst->poses[k] : &inst->to_world;
        float m[12];
        for (int row = 0; row < 3; row++)
            for (int col = 0; col < 4; col++)
                m[row * 4 + col] = (float)xf->m[row][col];
        rtcSetGeometryTransform(g, (unsigned)k, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->scene, g, id);
    rtcReleaseGeometry(g);
}

/* A mesh placed once goes straight into the top scene, in world space:
 * Embree traces a flat scene about twice as fast as one instance (measured
 * with bench_ceiling on the bunny, 8-wide packets). Its arrays are shared
 * when the placement is the identity; otherwise the vertices are moved into
 * a copy (12 bytes a vertex, padded as Embree reads). False when memory
 * runs out. */
static bool add_flat(accel *a, const mesh *m, const instance *inst, int index, bool opaque)
{
    const float *positions = m->positions;
    if (inst->has_transform) {
        float *v = malloc((3 * (size_t)m->vertex_count + 1) * sizeof *v);
        if (!v)
            return false;
        for (int k = 0; k < m->vertex_count; k++) {
            const float *p = m->positions + 3 * (size_t)k;
            vec3 w = xf_point(&inst->to_world, v3(p[0], p[1], p[2]));
            v[3 * k] = (float)w.x;
            v[3 * k + 1] = (float)w.y;
            v[3 * k + 2] = (float)w.z;
        }
        v[3 * (size_t)m->vertex_count] = 0;
        a->flat_vertices[index] = v;
        positions = v;
    }
    RTCGeometry g = triangles(a, m, positions, opaque);
    rtcAttachGeometryByID(a->scene, g, 1u + (unsigned)index);
    rtcReleaseGeometry(g);
    return true;
}

/* Adds the meshes: each placed once flat, the others as instances of one
 * triangle scene per mesh, which is opaque when every placement is. False
 * when memory runs out. */
static bool add_meshes(accel *a, const accel_geometry *geo)
{
    int *uses = calloc((size_t)geo->mesh_count + 1, sizeof *uses);
    bool *see_through = calloc((size_t)geo->mesh_count + 1, sizeof *see_through);
    bool ok = uses && see_through;
    for (int i = 0; ok && i < geo->instance_count; i++) {
        /* A moving placement is an instance, whose transform Embree moves. */
        uses[geo->instances[i].mesh] += geo->instances[i].pose_count ? 2 : 1;
        see_through[geo->instances[i].mesh] |= !(geo->instance_opaque && geo->instance_opaque[i]);
    }
    for (; ok && a->mesh_count < geo->mesh_count; a->mesh_count++)
        if (uses[a->mesh_count] > 1)
            a->mesh_scenes[a->mesh_count] = mesh_scene(a, &geo->meshes[a->mesh_count], !see_through[a->mesh_count]);
    for (int i = 0; ok && i < geo->instance_count; i++) {
        const instance *inst = &geo->instances[i];
        if (uses[inst->mesh] == 1 && !inst->pose_count) {
            ok = add_flat(a, &geo->meshes[inst->mesh], inst, i, !see_through[inst->mesh]);
        } else {
            add_instance(a, inst, 1u + (unsigned)i);
            a->instanced = true;
        }
    }
    free(uses);
    free(see_through);
    return ok;
}

/* Below this many camera samples a triangle, Embree's quick build (LOW: a
 * Morton-code BVH) beats its standard one (MEDIUM: SAH). Measured on the
 * Stanford bunny (callgrind, bench/README.md): LOW builds it in 30M
 * instructions against 161M, and each camera sample then costs 1% more
 * (about 12 instructions), even at about 160 samples a triangle. Rays that
 * bounce are not neighbours, and a looser BVH costs them far more: each
 * bounce a sample may take counts as a sample (SPD mount, 8,192 triangles
 * under glass balls, depth 5, 32 camera samples a triangle: 19% faster
 * for the whole process with MEDIUM). The choice depends on the scene and
 * its settings alone, never on threads, tiles or ranks: a triangle hit
 * exactly on an edge it shares is one triangle or the other by the BVH's
 * order, so each render must build the same one for the same bytes. */
#define QUICK_BUILD_SAMPLES_PER_TRIANGLE 100.0

/* The triangles of the scene's meshes, each mesh once. */
static double mesh_triangles(const accel_geometry *geo)
{
    double triangles = 0;
    for (int i = 0; i < geo->mesh_count; i++)
        triangles += geo->meshes[i].triangle_count;
    return triangles;
}

static enum RTCBuildQuality build_quality(const accel_geometry *geo)
{
    double triangles = mesh_triangles(geo);
    double samples = geo->camera_samples * (1.0 + geo->bounces);
    return samples < QUICK_BUILD_SAMPLES_PER_TRIANGLE * triangles ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM;
}

/* Incoherent rays (reflections, refractions and the shadow segments from
 * their hits) are traced one at a time where the tree is mostly analytic
 * shapes, and large: an incoherent packet's lanes part near the root, and
 * every user primitive any lane reaches then costs a callback over the
 * packet. Measured, 2 threads, depth 5, the same bytes: SPD rings (8,400
 * shapes) 20% faster, balls (7,382 spheres) 6%; random reflective spheres
 * 5% faster at 1,000 and 20% at 3,000, but 0-10% slower at 30 to 300, as
 * the seed room (22 shapes) is 5% slower; SPD mount (8,192 triangles, 4
 * spheres) 18% slower, Embree meeting a packet's triangles together. Like
 * the build quality, this depends on the scene alone. */
#define APART_MIN_PRIMITIVES 1000.0

static bool rays_apart(const accel *a, const accel_geometry *geo)
{
    double primitives = a->prim_count;
    for (int i = 0; i < a->shape_count; i++)
        if (a->shapes[i].set)
            primitives += a->shapes[i].set->count;
    return primitives >= APART_MIN_PRIMITIVES && primitives >= mesh_triangles(geo);
}

glint_status accel_build(accel **out, const accel_geometry *geo, glint_error *err)
{
    *out = NULL;
    accel *a = calloc(1, sizeof *a);
    if (!a || !(a->mesh_scenes = calloc((size_t)geo->mesh_count + 1, sizeof(RTCScene))) ||
        !(a->flat_vertices = calloc((size_t)geo->instance_count + 1, sizeof(float *)))) {
        if (a)
            free(a->mesh_scenes);
        free(a);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    }
    a->instance_count = geo->instance_count;
    a->shapes = geo->shapes;
    a->shape_count = geo->shape_count;
    a->shape_opaque = geo->shape_opaque;
    a->all_opaque = true;
    for (int i = 0; i < geo->shape_count; i++)
        a->all_opaque &= geo->shape_opaque && geo->shape_opaque[i];
    for (int i = 0; i < geo->instance_count; i++)
        a->all_opaque &= geo->instance_opaque && geo->instance_opaque[i];
    a->cancel = geo->cancel;
    a->quality = build_quality(geo);
    /* Embree's threads start with the device (start_threads), not lazily in
     * the build or, worse, as the scene is released: there, TBB failing to
     * start one (memory running short) throws from a destructor and ends
     * the process; here, the device reports it. Measured: no slower. */
    char config[48] = "start_threads=1";
    if (geo->threads > 0)
        snprintf(config, sizeof config, "threads=%d,start_threads=1", geo->threads);
    a->device = rtcNewDevice(config);
    if (!a->device) {
        free(a->mesh_scenes);
        free(a->flat_vertices);
        free(a);
        enum RTCError code = rtcGetDeviceError(NULL);
        if (code == RTC_ERROR_OUT_OF_MEMORY)
            return error_set(err, GLINT_ERR_NOMEM, "cannot create the Embree device: out of memory");
        /* Embree says no more when its threads cannot start, which in
         * practice is memory (their stacks) running short. */
        if (code == RTC_ERROR_UNKNOWN)
            return error_set(err, GLINT_ERR_NOMEM,
                             "cannot create the Embree device: its threads could not start (out of memory?)");
        return error_set(err, GLINT_ERR_EMBREE, "cannot create the Embree device: error %d", (int)code);
    }
    glint_error embree_err = {0};
    rtcSetDeviceErrorFunction(a->device, error_fn, &embree_err);
    a->scene = rtcNewScene(a->device);
    if (a->scene) {
        rtcSetSceneBuildQuality(a->scene, a->quality);
        rtcSetSceneProgressMonitorFunction(a->scene, build_progress, a);
        if (!sort_shapes(a) || !add_meshes(a, geo)) {
            rtcSetDeviceErrorFunction(a->device, NULL, NULL);
            accel_free(a);
            return error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
        }
        a->apart = rays_apart(a, geo);
        if (a->prim_count > 0)
            add_shapes(a);
        add_sphere_sets(a);
        rtcCommitScene(a->scene);
    }
    rtcSetDeviceErrorFunction(a->device, NULL, NULL);
    if (!a->scene || embree_err.message[0]) {
        accel_free(a);
        if (!embree_err.message[0])
            error_set(&embree_err, GLINT_ERR_EMBREE, "cannot create the Embree scene");
        return error_set(err, embree_err.status, "%s", embree_err.message);
    }
    *out = a;
    return GLINT_OK;
}

void accel_free(accel *a)
{
    if (!a)
        return;
    if (a->scene)
        rtcReleaseScene(a->scene);
    for (int i = 0; i < a->mesh_count; i++)
        if (a->mesh_scenes[i])
            rtcReleaseScene(a->mesh_scenes[i]);
    free(a->mesh_scenes);
    for (int i = 0; i < a->instance_count; i++)
        free(a->flat_vertices[i]);
    free(a->flat_vertices);
    free(a->prim_shape);
    free(a->prim_piece);
    free(a->prim_pieces);
    free(a->planes);
    if (a->device)
        rtcReleaseDevice(a->device);
    free(a);
}
