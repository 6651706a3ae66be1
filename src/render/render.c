/* render.c - glint_render: hands out tiles to threads, traces each tile's
 * blocks of pixels through the camera into the film (film.h), reports
 * progress and stops when cancelled. Each pixel depends only on its own
 * position and the scene, so the image is the same for any thread count,
 * tile size or tile order. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>
#include "core/error.h"
#include "core/hash.h"
#include "core/parallel.h"
#include "core/processors.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/hit.h"
#include "render/integrator.h"

#define MAX_THREADS 1024

typedef struct job {
    const glint_scene *scene;
    const accel *acc;
    camera cam;
    const glint_render_options *opts;
    film film;
    int tiles_x, tiles_total, tile_size, grid;
    atomic_int next_tile;
    unsigned char *finished;      /* finished[tile] != 0 once its pixels are all rendered */
    int tiles_done;               /* under progress_lock */
    pthread_mutex_t progress_lock;
} job;

typedef struct worker {
    job *job;
    uint64_t rays;
    uint64_t nan_samples;         /* samples left out of their pixels as NaN */
} worker;

/* Camera rays go in packets of 4 x 2 neighbouring pixels, the blocks
 * aligned to the image (not to tiles), so each pixel's rays, and so its
 * colour, do not depend on the tile size or the thread count. */
#define BLOCK_W 4
#define BLOCK_H (ACCEL_PACKET / BLOCK_W)
_Static_assert(BLOCK_W % BLOCK_H == 0, "a tile size rounded to BLOCK_W must hold whole blocks");

/* The position in pixel (px, py) of sample (sx, sy) of the n x n grid. */
static void sample_offset(const glint_settings *s, int n, int px, int py, int sx, int sy, double *ox, double *oy)
{
    *ox = (sx + 0.5) / n;
    *oy = (sy + 0.5) / n;
    if (s->sampler == GLINT_SAMPLER_JITTERED) {
        uint32_t h = hash4((uint32_t)px, (uint32_t)py, (uint32_t)(sy * n + sx), s->seed);
        *ox = (sx + hash_unit(h)) / n;
        *oy = (sy + hash_unit(hash_u32(h ^ 0x9e3779b9U))) / n;
    }
}

/* The lanes of the block at (x0, y0): their pixels, and which lie in the image. */
static void block_lanes(const job *j, int x0, int y0, int px[ACCEL_PACKET], int py[ACCEL_PACKET],
                        bool active[ACCEL_PACKET])
{
    const glint_settings *s = &j->scene->settings;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        px[i] = x0 + i % BLOCK_W;
        py[i] = y0 + i / BLOCK_W;
        active[i] = px[i] < s->width && py[i] < s->height;
    }
}

/* Traces every sample of the grid as one packet over the block's lanes
 * into *b; `careful` as for film_block_add. Always inlined, so that each
 * block renderer has its own copy with `careful` a constant: left to GCC
 * since the film took the pixels (film.h), it made one copy taking
 * `careful` at run time (seed room +0.7%, bunny +1% instructions). */
__attribute__((always_inline)) static inline void trace_samples(tracer *t, const job *j, const int px[ACCEL_PACKET],
                                                                const int py[ACCEL_PACKET],
                                                                const bool active[ACCEL_PACKET], bool careful,
                                                                film_block *b)
{
    const glint_settings *s = &j->scene->settings;
    int n = j->grid;
    bool jittered = s->sampler == GLINT_SAMPLER_JITTERED;
    ray8 rays;
    color c[ACCEL_PACKET];
    film_block_start(b);
    for (int sy = 0; sy < n; sy++) {
        for (int sx = 0; sx < n; sx++) {
            double x[ACCEL_PACKET], y[ACCEL_PACKET], ox = 0, oy = 0;
            /* The regular grid's offsets are the same for every lane. */
            if (!jittered)
                sample_offset(s, n, px[0], py[0], sx, sy, &ox, &oy);
            for (int i = 0; i < ACCEL_PACKET; i++) {
                if (jittered)
                    sample_offset(s, n, px[i], py[i], sx, sy, &ox, &oy);
                x[i] = px[i] + ox;
                y[i] = py[i] + oy;
            }
            /* The sampler makes image positions only: every ray passes the
             * lens's centre at the shutter's middle. */
            camera_rays8(&j->cam, x, y, &camera_lens_centre, camera_shutter_middle, &rays);
            tracer_trace8(t, &rays, active, c);
            film_block_add(b, active, c, careful);
        }
    }
}

/* Renders the pixels of the block at (x0, y0) that lie in the image: every
 * sample of the grid as one packet over the block. */
static void render_block(tracer *t, job *j, int x0, int y0)
{
    bool active[ACCEL_PACKET];
    int px[ACCEL_PACKET], py[ACCEL_PACKET];
    film_block b;
    block_lanes(j, x0, y0, px, py, active);
    trace_samples(t, j, px, py, active, false, &b);
    film_block_put(&j->film, &b, px, py, active);
}

/* render_block for a block with a NaN pixel: traced again, the same rays
 * giving the same colours, with the NaN samples left out of their pixels
 * and counted in *nan_samples. The rays were counted the first time. Out of
 * line and cold: no valid scene should come here. (One render_block taking
 * `careful` for both cost the common path 1% of the seed room's
 * instructions and 2% of the bunny's, the profile-guided build inlining
 * otherwise; hence the two.) */
__attribute__((noinline, cold)) static void render_block_leaving_nan(tracer *t, job *j, int x0, int y0,
                                                                     uint64_t *nan_samples)
{
    bool active[ACCEL_PACKET];
    int px[ACCEL_PACKET], py[ACCEL_PACKET];
    film_block b;
    uint64_t rays = t->rays;
    block_lanes(j, x0, y0, px, py, active);
    trace_samples(t, j, px, py, active, true, &b);
    film_block_put(&j->film, &b, px, py, active);
    t->rays = rays;
    *nan_samples += film_block_nan_samples(&b);
}

/* Whether the render has been asked to stop. */
static bool cancelled(const job *j)
{
    return j->opts->cancel && *j->opts->cancel;
}

/* The pixels of tile `tile`: columns x0 to x1 and rows y0 to y1, the ends
 * excluded. */
static void tile_bounds(const job *j, int tile, int *x0, int *y0, int *x1, int *y1)
{
    const glint_settings *s = &j->scene->settings;
    *x0 = (tile % j->tiles_x) * j->tile_size;
    *y0 = (tile / j->tiles_x) * j->tile_size;
    *x1 = *x0 + j->tile_size < s->width ? *x0 + j->tile_size : s->width;
    *y1 = *y0 + j->tile_size < s->height ? *y0 + j->tile_size : s->height;
}

/* Renders a tile; false if the render was cancelled before it was whole.
 * Tiles are whole blocks: tile_size is a multiple of BLOCK_W and BLOCK_H.
 * The tracer reads the cancel flag at every packet of rays, and a tile it
 * saw the flag in is not whole: what it traced since is black. Here the
 * flag is read before each block as well, so that the rest of a tile costs
 * nothing once it is set, even at thousands of samples a pixel.
 *
 * A NaN colour never reaches a pixel (film.h's rule): a tile that shows one
 * renders its blocks that show one again, leaving it out. */
static bool render_tile(tracer *t, job *j, int tile, uint64_t *nan_samples)
{
    int x0, y0, x1, y1;
    tile_bounds(j, tile, &x0, &y0, &x1, &y1);
    for (int y = y0; y < y1; y += BLOCK_H) {
        for (int x = x0; x < x1; x += BLOCK_W) {
            if (cancelled(j))
                return false;
            render_block(t, j, x, y);
        }
    }
    if (t->stopped)
        return false;
    if (!film_has_nan(&j->film, x0, y0, x1, y1))
        return true;
    for (int y = y0; y < y1; y += BLOCK_H) {
        for (int x = x0; x < x1; x += BLOCK_W) {
            int bx = x + BLOCK_W < x1 ? x + BLOCK_W : x1, by = y + BLOCK_H < y1 ? y + BLOCK_H : y1;
            if (film_has_nan(&j->film, x, y, bx, by))
                render_block_leaving_nan(t, j, x, y, nan_samples);
        }
    }
    return true;
}

static void *worker_run(void *arg)
{
    worker *w = arg;
    job *j = w->job;
    tracer t = {.scene = j->scene, .acc = j->acc, .reach = tracer_reach(j->scene), .cancel = j->opts->cancel};
    int tile;
    while ((tile = atomic_fetch_add(&j->next_tile, 1)) < j->tiles_total) {
        if (cancelled(j) || !render_tile(&t, j, tile, &w->nan_samples))
            break;
        j->finished[tile] = 1;
        if (j->opts->progress) {
            /* The lock keeps the calls one at a time and their counts in order. */
            pthread_mutex_lock(&j->progress_lock);
            j->opts->progress(j->opts->progress_user, ++j->tiles_done, j->tiles_total);
            pthread_mutex_unlock(&j->progress_lock);
        }
    }
    w->rays = t.rays;
    return NULL;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Runs the job on `count` threads, the caller's being the first. */
static glint_status run_workers(job *j, int count, uint64_t *rays, uint64_t *nan_samples, glint_error *err)
{
    worker *ws = calloc((size_t)count, sizeof *ws);
    if (!ws)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory starting threads");
    for (int i = 0; i < count; i++)
        ws[i].job = j;
    parallel_run(count, worker_run, ws, sizeof *ws);
    *rays = *nan_samples = 0;
    for (int i = 0; i < count; i++) {
        *rays += ws[i].rays;
        *nan_samples += ws[i].nan_samples;
    }
    free(ws);
    return GLINT_OK;
}

glint_status glint_render(const glint_scene *scene, const glint_render_options *options, glint_image *out,
                          glint_render_stats *stats, glint_error *err)
{
    static const glint_render_options defaults;
    const glint_render_options *o = options ? options : &defaults;
    const glint_settings *s = &scene->settings;
    out->width = out->height = 0;
    out->pixels = NULL;
    if (o->threads < 0 || o->threads > MAX_THREADS)
        return error_set(err, GLINT_ERR_INVALID, "thread count must be 0..%d, got %d", MAX_THREADS, o->threads);
    if (o->tile_size < 0 || o->tile_size > 65536)
        return error_set(err, GLINT_ERR_INVALID, "tile size must be 0..65536, got %d", o->tile_size);
    double start = now_seconds();

    /* Tiles hold whole blocks: the size is rounded up to a multiple of 4. */
    int tile_size = o->tile_size ? o->tile_size : 32;
    tile_size = (tile_size + BLOCK_W - 1) / BLOCK_W * BLOCK_W;
    job j = {.scene = scene, .opts = o, .tile_size = tile_size};
    j.grid = 1;
    while (j.grid * j.grid < s->samples_per_pixel)
        j.grid++;
    if (!film_init(&j.film, s->width, s->height, j.grid * j.grid))
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a %dx%d image", s->width, s->height);
    camera_init(&j.cam, &scene->camera, s->width, s->height);
    j.tiles_x = (s->width + j.tile_size - 1) / j.tile_size;
    j.tiles_total = j.tiles_x * ((s->height + j.tile_size - 1) / j.tile_size);
    atomic_init(&j.next_tile, 0);
    if (!(j.finished = calloc((size_t)j.tiles_total, 1))) {
        film_free(&j.film);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a %dx%d image", s->width, s->height);
    }
    /* Embree builds with every thread asked for; tracing needs no more
     * threads than tiles. */
    int build_threads = o->threads ? o->threads : processors_online(MAX_THREADS);
    int threads = build_threads < j.tiles_total ? build_threads : j.tiles_total;

    accel *acc = NULL;
    bool *shape_opaque, *instance_opaque;
    glint_status st = GLINT_OK;
    if (!hit_opacity(scene, &shape_opaque, &instance_opaque)) {
        st = error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    } else {
        accel_geometry geo = {build_threads, scene->shapes, scene->shape_count, scene->meshes, scene->mesh_count,
                              scene->instances, scene->instance_count, shape_opaque, instance_opaque, o->cancel};
        st = accel_build(&acc, &geo, err);
    }
    /* A build the cancel flag stopped goes on as a render that finished no
     * tile. */
    if (st && st != GLINT_ERR_CANCELLED) {
        free(shape_opaque);
        free(instance_opaque);
        film_free(&j.film);
        free(j.finished);
        return st;
    }
    uint64_t rays = 0, nan_samples = 0;
    if (!st) {
        j.acc = acc;
        pthread_mutex_init(&j.progress_lock, NULL);
        st = run_workers(&j, threads, &rays, &nan_samples, err);
        pthread_mutex_destroy(&j.progress_lock);
        accel_free(acc);
    }
    free(shape_opaque);
    free(instance_opaque);
    bool stopped = (!st || st == GLINT_ERR_CANCELLED) && cancelled(&j);
    if (stopped)
        st = error_set(err, GLINT_ERR_CANCELLED, "render cancelled");
    if (st && !(stopped && o->keep_partial)) {
        film_free(&j.film);
        free(j.finished);
        return st;
    }
    /* A cancelled render keeping its finished tiles: the others, rendered
     * in part or not at all, are black. */
    uint64_t pixels_done = 0;
    int finished = 0;
    for (int tile = 0; tile < j.tiles_total; tile++) {
        int x0, y0, x1, y1;
        tile_bounds(&j, tile, &x0, &y0, &x1, &y1);
        if (j.finished[tile]) {
            finished++;
            pixels_done += (uint64_t)(x1 - x0) * (uint64_t)(y1 - y0);
            continue;
        }
        film_clear(&j.film, x0, y0, x1, y1);
    }
    free(j.finished);
    out->width = s->width;
    out->height = s->height;
    out->pixels = j.film.pixels;
    if (stats) {
        stats->seconds = now_seconds() - start;
        stats->samples = pixels_done * (uint64_t)(j.grid * j.grid);
        stats->rays = rays;
        stats->nan_samples = nan_samples;
        stats->tiles_done = finished;
        stats->tiles_total = j.tiles_total;
    }
    return st;
}
