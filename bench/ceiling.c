/* ceiling.c - the throughput ceiling for bench/run's mesh rows: a bare
 * Embree loop tracing the same rays glint traces for a scene of meshes, with
 * no shading at all. It loads the scene with glint (same file, same camera,
 * same lights), puts every placed mesh (and each plane, as two large
 * triangles) into one flat Embree scene of world-space triangles (no
 * instances, no callbacks, no filters), and then, per
 * pixel, traces the camera ray through the pixel's centre and, from its hit,
 * one shadow ray to each light the hit faces: exactly the rays of a 1-sample
 * glint render of an opaque scene. Spheres are Embree's own (sphere
 * points), as the SPD balls need, and open cylinders and cones Embree's cone
 * curves, as the SPD rings and tree need. It reports the trace time (after the
 * build) and the rays per second, for single rays and for packets of 8
 * (4 x 2 pixels), which is what Embree can do at best on this machine.
 *
 *   bench_ceiling SCENE.yaml|SCENE.nff [--threads N] [--packet 1|8] [--runs N]
 *
 * Prints one line: `ceiling: WxH, T threads, packet P: build B s, trace S s
 * (median of N), R rays, M Mrays/s`. */
#include <embree3/rtcore.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "glint.h"
#include "render/camera.h"
#include "scene/scene.h"

#define TILE 32
#define MAX_THREADS 256

typedef struct bench {
    const glint_scene *scene;
    RTCScene rtc;
    camera cam;
    int width, height, packet, tiles_x, tiles;
    atomic_int next;
    unsigned char *mask;      /* --mask: per pixel, light 0's shadow ray; else NULL */
} bench;

/* Mask values: no shadow ray (no hit, or the hit faces away), blocked, lit. */
enum { MASK_NONE = 128, MASK_BLOCKED = 0, MASK_LIT = 255 };

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void die(const char *msg)
{
    fprintf(stderr, "bench_ceiling: %s\n", msg);
    exit(1);
}

/* A plane as two triangles to SHAPE_PLANE_EXTENT from its point, as far as
 * glint's BVH bounds it, in world space. */
static void add_plane(RTCDevice dev, RTCScene rtc, const shape *sh)
{
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4);
    unsigned *idx = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2);
    vec3 c = v3(sh->desc.center.x, sh->desc.center.y, sh->desc.center.z);
    for (int k = 0; k < 4; k++) {
        double a = (k == 1 || k == 2) ? SHAPE_PLANE_EXTENT : -SHAPE_PLANE_EXTENT;
        double b = k >= 2 ? SHAPE_PLANE_EXTENT : -SHAPE_PLANE_EXTENT;
        vec3 p = xf_point(&sh->to_world, v3_add(c, v3_add(v3_scale(sh->plane_u, a), v3_scale(sh->plane_v, b))));
        v[3 * k] = (float)p.x;
        v[3 * k + 1] = (float)p.y;
        v[3 * k + 2] = (float)p.z;
    }
    const unsigned quad[6] = {0, 1, 2, 0, 2, 3};
    memcpy(idx, quad, sizeof quad);
    rtcCommitGeometry(g);
    rtcAttachGeometry(rtc, g);
    rtcReleaseGeometry(g);
}

/* The spheres without a transform as one geometry of Embree's own exact
 * spheres (sphere points: centre and radius in single precision). */
static void add_spheres(RTCDevice dev, RTCScene rtc, const glint_scene *s)
{
    int count = 0;
    for (int i = 0; i < s->shape_count; i++)
        count += s->shapes[i].desc.kind == GLINT_SHAPE_SPHERE;
    if (count == 0)
        return;
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                       (size_t)count);
    for (int i = 0, k = 0; i < s->shape_count; i++) {
        const shape *sh = &s->shapes[i];
        if (sh->desc.kind != GLINT_SHAPE_SPHERE)
            continue;
        if (sh->has_transform)
            die("the ceiling takes spheres without a transform only");
        v[4 * k] = (float)sh->desc.center.x;
        v[4 * k + 1] = (float)sh->desc.center.y;
        v[4 * k + 2] = (float)sh->desc.center.z;
        v[4 * k + 3] = (float)sh->desc.radius;
        k++;
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rtc, g);
    rtcReleaseGeometry(g);
}

/* Whether sh is an open cylinder or cone (the NFF's), which Embree's cone
 * curves are. */
static bool open_cone(const shape *sh)
{
    return (sh->desc.kind == GLINT_SHAPE_CYLINDER || sh->desc.kind == GLINT_SHAPE_CONE) && !sh->desc.capped &&
           !sh->desc.top_capped;
}

/* The open cylinders and cones as one geometry of Embree's own cone curves,
 * a segment each from its base to its top (world space, single
 * precision), so that a ceiling for the SPD rings and tree has their
 * shapes exact and without callbacks. Each segment ends in a flat cap where
 * glint's are open: inside the spheres joining them in the SPD scenes. */
static void add_cones(RTCDevice dev, RTCScene rtc, const glint_scene *s)
{
    int count = 0;
    for (int i = 0; i < s->shape_count; i++)
        count += open_cone(&s->shapes[i]);
    if (count == 0)
        return;
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_CONE_LINEAR_CURVE);
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                       2 * (size_t)count);
    unsigned *idx = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned),
                                            (size_t)count);
    for (int i = 0, k = 0; i < s->shape_count; i++) {
        const shape *sh = &s->shapes[i];
        if (!open_cone(sh))
            continue;
        vec3 base = v3(sh->desc.center.x, sh->desc.center.y, sh->desc.center.z);
        vec3 ends[2] = {xf_point(&sh->to_world, base), xf_point(&sh->to_world, v3_add(base, v3(0, sh->desc.height, 0)))};
        double radii[2] = {sh->desc.radius,
                           sh->desc.kind == GLINT_SHAPE_CONE ? sh->desc.top_radius : sh->desc.radius};
        for (int e = 0; e < 2; e++) {
            float *p = v + 4 * (2 * k + e);
            p[0] = (float)ends[e].x;
            p[1] = (float)ends[e].y;
            p[2] = (float)ends[e].z;
            p[3] = (float)radii[e];
        }
        idx[k] = 2 * (unsigned)k;
        k++;
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rtc, g);
    rtcReleaseGeometry(g);
}

/* One triangle geometry per placed mesh, its vertices moved to world space,
 * two triangles per plane, and the spheres as Embree's. */
static RTCScene build_scene(RTCDevice dev, const glint_scene *s)
{
    RTCScene rtc = rtcNewScene(dev);
    for (int i = 0; i < s->shape_count; i++)
        if (s->shapes[i].desc.kind == GLINT_SHAPE_PLANE)
            add_plane(dev, rtc, &s->shapes[i]);
        else if (s->shapes[i].desc.kind != GLINT_SHAPE_SPHERE && !open_cone(&s->shapes[i]))
            die("the ceiling takes meshes, planes, spheres and open cylinders and cones only");
    add_spheres(dev, rtc, s);
    add_cones(dev, rtc, s);
    for (int i = 0; i < s->instance_count; i++) {
        const instance *inst = &s->instances[i];
        const mesh *m = &s->meshes[inst->mesh];
        RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
        float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                           (size_t)m->vertex_count);
        for (int k = 0; k < m->vertex_count; k++) {
            vec3 p = xf_point(&inst->to_world, v3(m->positions[3 * k], m->positions[3 * k + 1], m->positions[3 * k + 2]));
            v[3 * k] = (float)p.x;
            v[3 * k + 1] = (float)p.y;
            v[3 * k + 2] = (float)p.z;
        }
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m->indices, 0, 3 * sizeof(uint32_t),
                                   (size_t)m->triangle_count);
        rtcCommitGeometry(g);
        rtcAttachGeometry(rtc, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(rtc);
    return rtc;
}

/* How far a shadow ray starts off the surface, relative to the scene scale
 * at the hit. glint refines each hit in double precision and starts 1e-7
 * off it; here p comes from Embree's single-precision distance, which can
 * put it 1e-6 of the distance inside the surface, and from there the ray
 * would stop on the surface it leaves. 1e-4 clears that, so the rays cross
 * what glint's cross (bench_ceiling --mask shows them). */
#define SHADOW_OFFSET 1e-4

/* The shadow ray from a hit at p with geometric normal ng (any side, any
 * length: Embree's Ng is the edges' cross product) towards light l; false
 * when the hit does not face the light. The offset is along the unit normal:
 * along Ng itself a shadow ray from a plane's two huge triangles started
 * some 1e5 units up and missed the whole model. */
static bool shadow_ray(const light *l, vec3 p, vec3 ng, vec3 dir, struct RTCRay *out)
{
    light_sample ls;
    if (!l->kind->sample(l, p, 0.5, 0.5, &ls))
        return false;
    ng = v3_normalize(ng);
    vec3 n = v3_dot(ng, dir) < 0 ? ng : v3_neg(ng);
    if (v3_dot(n, ls.to_light) <= 0)
        return false;
    double scale = fmax(1.0, fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
    vec3 o = v3_madd(p, n, SHADOW_OFFSET * scale);
    *out = (struct RTCRay){.org_x = (float)o.x, .org_y = (float)o.y, .org_z = (float)o.z, .tnear = 0,
                           .dir_x = (float)ls.to_light.x, .dir_y = (float)ls.to_light.y,
                           .dir_z = (float)ls.to_light.z, .tfar = isfinite(ls.distance) ? (float)ls.distance : INFINITY,
                           .mask = 0xFFFFFFFFu};
    return true;
}

/* The camera rays through the centres of pixels (px[i], py[i]), as glint
 * makes them: a packet at a time. */
static void centre_rays(const camera *c, const int px[RAY8], const int py[RAY8], ray8 *out)
{
    double x[RAY8], y[RAY8];
    for (int i = 0; i < RAY8; i++) {
        x[i] = px[i] + 0.5;
        y[i] = py[i] + 0.5;
    }
    camera_rays8(c, x, y, &camera_lens_centre, camera_shutter_middle, out);
}

static uint64_t trace_single(bench *b, int x0, int y0, int x1, int y1, struct RTCIntersectContext *ctx)
{
    uint64_t rays = 0;
    for (int y = y0; y < y1; y++) {
        ray8 row;
        for (int x = x0; x < x1; x++) {
            /* The rays of the row's next RAY8 pixels are made together and
             * traced one by one. */
            int lane = (x - x0) % RAY8;
            if (lane == 0) {
                int px[RAY8], py[RAY8];
                for (int i = 0; i < RAY8; i++) {
                    px[i] = x + i;
                    py[i] = y;
                }
                centre_rays(&b->cam, px, py, &row);
            }
            ray r = ray8_get(&row, lane);
            struct RTCRayHit rh = {.ray = {.org_x = (float)r.o.x, .org_y = (float)r.o.y, .org_z = (float)r.o.z,
                                           .dir_x = (float)r.d.x, .dir_y = (float)r.d.y, .dir_z = (float)r.d.z,
                                           .tfar = INFINITY, .mask = 0xFFFFFFFFu},
                                   .hit = {.geomID = RTC_INVALID_GEOMETRY_ID}};
            rtcIntersect1(b->rtc, ctx, &rh);
            rays++;
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
                continue;
            vec3 p = v3_madd(r.o, r.d, rh.ray.tfar), ng = v3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
            for (int l = 0; l < b->scene->light_count; l++) {
                struct RTCRay sr;
                if (!shadow_ray(&b->scene->lights[l], p, ng, r.d, &sr))
                    continue;
                rtcOccluded1(b->rtc, ctx, &sr);
                rays++;
                if (b->mask && l == 0)
                    b->mask[(size_t)y * b->width + x] = sr.tfar == -INFINITY ? MASK_BLOCKED : MASK_LIT;
            }
        }
    }
    return rays;
}

/* Lane i of an 8-wide packet from a single ray. */
static void set_lane(struct RTCRay8 *p, int i, const struct RTCRay *r)
{
    p->org_x[i] = r->org_x;
    p->org_y[i] = r->org_y;
    p->org_z[i] = r->org_z;
    p->dir_x[i] = r->dir_x;
    p->dir_y[i] = r->dir_y;
    p->dir_z[i] = r->dir_z;
    p->tnear[i] = r->tnear;
    p->tfar[i] = r->tfar;
    p->mask[i] = r->mask;
    p->time[i] = 0;
    p->id[i] = 0;
    p->flags[i] = 0;
}

static uint64_t trace_packets(bench *b, int x0, int y0, int x1, int y1, struct RTCIntersectContext *ctx)
{
    uint64_t rays = 0;
    for (int y = y0; y < y1; y += 2) {
        for (int x = x0; x < x1; x += 4) {
            _Alignas(32) int valid[8];
            int px[8], py[8];
            ray r[8];
            ray8 r8;
            struct RTCRayHit8 rh;
            for (int i = 0; i < 8; i++) {
                px[i] = x + i % 4;
                py[i] = y + i / 4;
            }
            centre_rays(&b->cam, px, py, &r8);
            for (int i = 0; i < 8; i++) {
                valid[i] = px[i] < x1 && py[i] < y1 ? -1 : 0;
                r[i] = ray8_get(&r8, i);
                struct RTCRay one = {.org_x = (float)r[i].o.x, .org_y = (float)r[i].o.y, .org_z = (float)r[i].o.z,
                                     .dir_x = (float)r[i].d.x, .dir_y = (float)r[i].d.y, .dir_z = (float)r[i].d.z,
                                     .tfar = INFINITY, .mask = 0xFFFFFFFFu};
                set_lane(&rh.ray, i, &one);
                rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
                rays += valid[i] != 0;
            }
            rtcIntersect8(valid, b->rtc, ctx, &rh);
            for (int l = 0; l < b->scene->light_count; l++) {
                _Alignas(32) int svalid[8];
                struct RTCRay8 sr;
                for (int i = 0; i < 8; i++) {
                    struct RTCRay one;
                    svalid[i] = 0;
                    if (!valid[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID)
                        continue;
                    vec3 p = v3_madd(r[i].o, r[i].d, rh.ray.tfar[i]);
                    vec3 ng = v3(rh.hit.Ng_x[i], rh.hit.Ng_y[i], rh.hit.Ng_z[i]);
                    if (!shadow_ray(&b->scene->lights[l], p, ng, r[i].d, &one))
                        continue;
                    set_lane(&sr, i, &one);
                    svalid[i] = -1;
                    rays++;
                }
                rtcOccluded8(svalid, b->rtc, ctx, &sr);
                for (int i = 0; b->mask && l == 0 && i < 8; i++)
                    if (svalid[i])
                        b->mask[(size_t)(y + i / 4) * b->width + x + i % 4] =
                            sr.tfar[i] == -INFINITY ? MASK_BLOCKED : MASK_LIT;
            }
        }
    }
    return rays;
}

typedef struct worker {
    bench *b;
    pthread_t thread;
    uint64_t rays;
} worker;

static void *work(void *arg)
{
    worker *w = arg;
    bench *b = w->b;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    int t;
    while ((t = atomic_fetch_add(&b->next, 1)) < b->tiles) {
        int x0 = (t % b->tiles_x) * TILE, y0 = (t / b->tiles_x) * TILE;
        int x1 = x0 + TILE < b->width ? x0 + TILE : b->width, y1 = y0 + TILE < b->height ? y0 + TILE : b->height;
        w->rays += b->packet == 8 ? trace_packets(b, x0, y0, x1, y1, &ctx) : trace_single(b, x0, y0, x1, y1, &ctx);
    }
    return NULL;
}

static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    const char *path = NULL, *mask_path = NULL;
    int threads = 2, packet = 8, runs = 3;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--threads") == 0 && i + 1 < argc)
            threads = atoi(argv[++i]);
        else if (strcmp(argv[i], "--packet") == 0 && i + 1 < argc)
            packet = atoi(argv[++i]);
        else if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
            runs = atoi(argv[++i]);
        else if (strcmp(argv[i], "--mask") == 0 && i + 1 < argc)
            mask_path = argv[++i];
        else if (!path && argv[i][0] != '-')
            path = argv[i];
        else
            die("usage: bench_ceiling SCENE.yaml [--threads N] [--packet 1|8] [--runs N] [--mask FILE.pgm]");
    }
    if (!path || threads < 1 || threads > MAX_THREADS || (packet != 1 && packet != 8) || runs < 1 || runs > 100)
        die("usage: bench_ceiling SCENE.yaml [--threads 1..256] [--packet 1|8] [--runs 1..100] [--mask FILE.pgm]");
    glint_error err;
    glint_scene *s = glint_scene_load_file(path, NULL, &err);
    if (!s)
        die(err.message);

    char config[64];
    snprintf(config, sizeof config, "threads=%d", threads);
    RTCDevice dev = rtcNewDevice(config);
    if (!dev)
        die("cannot create the Embree device");
    double t0 = now();
    bench b = {.scene = s, .packet = packet, .width = s->settings.width, .height = s->settings.height};
    b.rtc = build_scene(dev, s);
    double build = now() - t0;
    camera_init(&b.cam, &s->camera, b.width, b.height);
    b.tiles_x = (b.width + TILE - 1) / TILE;
    b.tiles = b.tiles_x * ((b.height + TILE - 1) / TILE);
    if (mask_path) {
        b.mask = malloc((size_t)b.width * b.height);
        if (!b.mask)
            die("out of memory for the mask");
        memset(b.mask, MASK_NONE, (size_t)b.width * b.height);
    }

    double times[100];
    uint64_t rays = 0;
    for (int run = 0; run < runs; run++) {
        worker ws[MAX_THREADS] = {0};
        atomic_init(&b.next, 0);
        double start = now();
        for (int i = 1; i < threads; i++) {
            ws[i].b = &b;
            if (pthread_create(&ws[i].thread, NULL, work, &ws[i]) != 0)
                die("cannot start a thread");
        }
        ws[0].b = &b;
        work(&ws[0]);
        rays = ws[0].rays;
        for (int i = 1; i < threads; i++) {
            pthread_join(ws[i].thread, NULL);
            rays += ws[i].rays;
        }
        times[run] = now() - start;
    }
    qsort(times, (size_t)runs, sizeof times[0], compare);
    double median = times[runs / 2];
    printf("ceiling: %dx%d, %d threads, packet %d: build %.3f s, trace %.3f s (median of %d), %llu rays, %.1f Mrays/s\n",
           b.width, b.height, threads, packet, build, median, runs, (unsigned long long)rays, rays / median * 1e-6);
    if (mask_path) {
        FILE *f = fopen(mask_path, "wb");
        if (!f || fprintf(f, "P5\n%d %d\n255\n", b.width, b.height) < 0 ||
            fwrite(b.mask, 1, (size_t)b.width * b.height, f) != (size_t)b.width * b.height || fclose(f) != 0)
            die("cannot write the mask");
        free(b.mask);
    }
    rtcReleaseScene(b.rtc);
    rtcReleaseDevice(dev);
    glint_scene_free(s);
    return 0;
}
