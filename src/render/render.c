/* render.c - the render back-end (render_tiles.h) and glint_render, its
 * local case: threads take tiles from a feed, trace each tile's blocks of
 * pixels through the camera into the film (film.h) and hand the finished
 * tile back to the feed; progress, and stopping when cancelled. Each pixel
 * depends only on its own position and the scene, so the image is the same
 * for any thread count, tile size, tile order or process a tile is
 * rendered in. */
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
#include "render/pixel_samples.h"
#include "render/plain_packet.h"
#include "render/render_tiles.h"

#define MAX_THREADS 1024

typedef struct job {
    const glint_scene *scene;
    const accel *acc;
    camera cam;
    camera poses[CAMERA_MAX_POSES]; /* a moving camera's, pose_count of them (0: it stands still) */
    int pose_count;
    bool motion;                  /* something moves over the shutter: each sample has a time */
    const glint_render_options *opts;
    const render_feed *feed;
    film film;
    render_layout layout;
    pixel_sampler sampler;
    int samples;                  /* each pixel's, before adaptive sampling adds any */
    bool signed_film;             /* pixels take the film's signed path (film.h) */
    bool keys;                    /* tracing uses the samples' keys: tracer_needs_keys */
    bool plain;                   /* plain_packet_scene */
    uint32_t key_seed;            /* what they are hashed with: the frame's random seed */
    light_choice choice;          /* with settings.light_samples: the area lights and emitters by power */
    spectrum bands;               /* settings.dispersion_bands' colours */
    double cone_width, cone_spread; /* a sample's footprint (tracer's) */
    int tiles_done;               /* under progress_lock */
    pthread_mutex_t progress_lock;
} job;

typedef struct worker {
    job *job;
    float *tile_pixels;           /* a tile's pixels, when the feed keeps no image */
    int tiles_done;
    uint64_t pixels_done;         /* in the tiles it finished */
    uint64_t rays;
    uint64_t nan_samples;         /* samples left out of their pixels as NaN */
    uint64_t extra_samples;       /* samples adaptive sampling added */
} worker;

/* Camera rays go in packets of 4 x 2 neighbouring pixels, the blocks
 * aligned to the image (not to tiles), so each pixel's rays, and so its
 * colour, do not depend on the tile size or the thread count. */
#define BLOCK_W 4
#define BLOCK_H (ACCEL_PACKET / BLOCK_W)
_Static_assert(BLOCK_W % BLOCK_H == 0, "a tile size rounded to BLOCK_W must hold whole blocks");

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

/* Traces sample k of each pixel of the block whose lane is traced[i],
 * one packet, into *b; `careful` as for film_block_add. */
__attribute__((always_inline)) static inline void trace_sample(tracer *t, const job *j, const pixel_block_samples *bs,
                                                               int k, const bool traced[ACCEL_PACKET], bool careful,
                                                               film_block *b)
{
    double x[ACCEL_PACKET], y[ACCEL_PACKET];
    bool negative[ACCEL_PACKET];
    camera_lens8 lens;
    ray8 rays;
    color c[ACCEL_PACKET];
    pixel_samples_at(&j->sampler, bs, k, x, y, &lens, negative);
    /* Without motion, every ray is at the shutter's middle. */
    double time[ACCEL_PACKET];
    if (j->motion)
        pixel_samples_time(bs, k, time);
    const camera_lens8 *through = j->cam.uses_lens ? &lens : &camera_lens_centre;
    if (j->pose_count)
        camera_moving_rays8(j->poses, j->pose_count, x, y, through, time, &rays);
    else
        camera_rays8(&j->cam, x, y, through, j->motion ? time : camera_shutter_middle, &rays);
    /* What every other random number of the sample is hashed from. */
    uint32_t key[ACCEL_PACKET] = {0};
    if (j->keys)
        for (int i = 0; i < ACCEL_PACKET; i++)
            key[i] = hash4((uint32_t)bs->px[i], (uint32_t)bs->py[i], (uint32_t)k, j->key_seed);
    tracer_trace8(t, &rays, j->motion ? time : NULL, traced, key, c);
    if (j->signed_film)
        film_block_add_signed(b, traced, c, negative, careful);
    else
        film_block_add(b, traced, c, careful);
}

/* Adaptive sampling: rounds that each double the samples of the block's
 * pixels while the samples so far of any of them differ by more than the
 * threshold, up to the most allowed; the samples added, in *extra.
 *
 * The block's pixels take more together, neighbours of a pixel whose
 * samples differ (POV-Ray's +AM2 compares neighbours too): a pixel's own
 * few samples often agree where the picture does not, the four samples of
 * a blurred checker all landing on dark cells, say, and it then kept that
 * colour. On the depth of field, from 9 samples up to 72, each pixel
 * judged alone gave the noise of about 36 uniform samples; judged by
 * blocks, that of 64, with half of 64's samples (bench/README.md). The
 * block is the same for any tile size, thread or rank count, so the choice
 * depends on its pixels' samples alone, and its packets stay full. */
static void trace_more_samples(tracer *t, const job *j, const pixel_block_samples *bs,
                               const bool active[ACCEL_PACKET], bool careful, film_block *b, uint64_t *extra)
{
    const glint_settings *s = &j->scene->settings;
    int pixels = 0;
    for (int i = 0; i < ACCEL_PACKET; i++)
        pixels += active[i];
    for (int from = j->samples; from < s->adaptive_max_samples; from *= 2) {
        bool differ = false;
        for (int i = 0; i < ACCEL_PACKET && !differ; i++)
            differ = active[i] && film_block_spread(b, i, j->film.exposure_scale) > s->adaptive_threshold;
        if (!differ)
            return;
        int to = 2 * from < s->adaptive_max_samples ? 2 * from : s->adaptive_max_samples;
        for (int k = from; k < to; k++)
            trace_sample(t, j, bs, k, active, careful, b);
        *extra += (uint64_t)pixels * (uint64_t)(to - from);
    }
}

/* Traces every sample of the block's pixels, a packet of one sample of
 * each at a time, into *b; `careful` as for film_block_add. Always
 * inlined, so that each block renderer has its own copy with `careful` a
 * constant: left to GCC since the film took the pixels (film.h), it made
 * one copy taking `careful` at run time (seed room +0.7%, bunny +1%
 * instructions). */
__attribute__((always_inline)) static inline void trace_samples(tracer *t, const job *j, const int px[ACCEL_PACKET],
                                                                const int py[ACCEL_PACKET],
                                                                const bool active[ACCEL_PACKET], bool careful,
                                                                film_block *b, uint64_t *extra)
{
    pixel_block_samples bs;
    pixel_samples_start(&j->sampler, px, py, &bs);
    if (j->signed_film)
        film_block_start_signed(b);
    else
        film_block_start(b);
    for (int k = 0; k < j->samples; k++)
        trace_sample(t, j, &bs, k, active, careful, b);
    if (j->scene->settings.adaptive_max_samples)
        trace_more_samples(t, j, &bs, active, careful, b, extra);
}

/* Writes the block's pixels from *b. */
__attribute__((always_inline)) static inline void put_block(job *j, film *f, const film_block *b, const int px[ACCEL_PACKET], const int py[ACCEL_PACKET],
                      const bool active[ACCEL_PACKET])
{
    if (j->signed_film)
        film_block_put_signed(f, b, px, py, active);
    else
        film_block_put(f, b, px, py, active);
}

/* Renders the pixels of the block at (x0, y0) that lie in the image: every
 * sample of the grid as one packet over the block. */
static void render_block(tracer *t, job *j, film *f, int x0, int y0, uint64_t *extra)
{
    bool active[ACCEL_PACKET];
    int px[ACCEL_PACKET], py[ACCEL_PACKET];
    film_block b;
    block_lanes(j, x0, y0, px, py, active);
    trace_samples(t, j, px, py, active, false, &b, extra);
    put_block(j, f, &b, px, py, active);
}

/* render_block for a block with a NaN pixel: traced again, the same rays
 * giving the same colours, with the NaN samples left out of their pixels
 * and counted in *nan_samples. The rays and samples were counted the
 * first time. Out of
 * line and cold: no valid scene should come here. (One render_block taking
 * `careful` for both cost the common path 1% of the seed room's
 * instructions and 2% of the bunny's, the profile-guided build inlining
 * otherwise; hence the two.) */
__attribute__((noinline, cold)) static void render_block_leaving_nan(tracer *t, job *j, film *f, int x0, int y0,
                                                                     uint64_t *nan_samples)
{
    bool active[ACCEL_PACKET];
    int px[ACCEL_PACKET], py[ACCEL_PACKET];
    film_block b;
    uint64_t rays = t->rays, extra = 0;
    block_lanes(j, x0, y0, px, py, active);
    trace_samples(t, j, px, py, active, true, &b, &extra);
    put_block(j, f, &b, px, py, active);
    t->rays = rays;
    *nan_samples += film_block_nan_samples(&b);
}

/* Whether the render has been asked to stop. */
static bool cancelled(const job *j)
{
    return j->opts->cancel && *j->opts->cancel;
}

void render_tile_bounds(const render_layout *l, int tile, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = (tile % l->tiles_x) * l->tile_size;
    *y0 = (tile / l->tiles_x) * l->tile_size;
    *x1 = *x0 + l->tile_size < l->width ? *x0 + l->tile_size : l->width;
    *y1 = *y0 + l->tile_size < l->height ? *y0 + l->tile_size : l->height;
}

glint_status render_layout_for(const glint_scene *scene, int tile_size, render_layout *l, glint_error *err)
{
    if (tile_size < 0 || tile_size > 65536)
        return error_set(err, GLINT_ERR_INVALID, "tile size must be 0..65536, got %d", tile_size);
    /* Tiles hold whole blocks: the size is rounded up to a multiple of 4. */
    int size = tile_size ? tile_size : 32;
    l->tile_size = (size + BLOCK_W - 1) / BLOCK_W * BLOCK_W;
    l->width = scene->settings.width;
    l->height = scene->settings.height;
    l->tiles_x = (l->width + l->tile_size - 1) / l->tile_size;
    l->tiles_total = l->tiles_x * ((l->height + l->tile_size - 1) / l->tile_size);
    return GLINT_OK;
}

/* Renders a tile into film f; false if the render was cancelled before it
 * was whole.
 * Tiles are whole blocks: tile_size is a multiple of BLOCK_W and BLOCK_H.
 * The tracer reads the cancel flag at every packet of rays, and a tile it
 * saw the flag in is not whole: what it traced since is black. Here the
 * flag is read before each block as well, so that the rest of a tile costs
 * nothing once it is set, even at thousands of samples a pixel.
 *
 * A NaN colour never reaches a pixel (film.h's rule): a tile that shows one
 * renders its blocks that show one again, leaving it out. */
static bool render_tile(tracer *t, job *j, film *f, int tile, uint64_t *nan_samples, uint64_t *extra_samples)
{
    int x0, y0, x1, y1;
    render_tile_bounds(&j->layout, tile, &x0, &y0, &x1, &y1);
    for (int y = y0; y < y1; y += BLOCK_H) {
        for (int x = x0; x < x1; x += BLOCK_W) {
            if (cancelled(j))
                return false;
            render_block(t, j, f, x, y, extra_samples);
        }
    }
    if (t->stopped)
        return false;
    if (!film_has_nan(f, x0, y0, x1, y1))
        return true;
    for (int y = y0; y < y1; y += BLOCK_H) {
        for (int x = x0; x < x1; x += BLOCK_W) {
            int bx = x + BLOCK_W < x1 ? x + BLOCK_W : x1, by = y + BLOCK_H < y1 ? y + BLOCK_H : y1;
            if (film_has_nan(f, x, y, bx, by))
                render_block_leaving_nan(t, j, f, x, y, nan_samples);
        }
    }
    return true;
}

static void *worker_run(void *arg)
{
    worker *w = arg;
    job *j = w->job;
    tracer t = {.scene = j->scene, .acc = j->acc, .reach = tracer_reach(j->scene), .cancel = j->opts->cancel,
                .keys = j->keys, .choice = j->scene->settings.light_samples > 0 ? &j->choice : NULL,
                .spectrum = &j->bands, .cone_width = j->cone_width, .cone_spread = j->cone_spread,
                .plain = j->plain};
    const render_feed *f = j->feed;
    const render_layout *l = &j->layout;
    int tile;
    while ((tile = f->next(f->user)) >= 0 && tile < l->tiles_total) {
        if (cancelled(j))
            break;
        int x0, y0, x1, y1;
        render_tile_bounds(l, tile, &x0, &y0, &x1, &y1);
        film *into = &j->film, own;
        if (w->tile_pixels) {
            own = (film){.pixels = w->tile_pixels, .width = x1 - x0, .height = y1 - y0, .x0 = x0, .y0 = y0,
                         .samples = j->film.samples, .exposure_scale = j->film.exposure_scale};
            into = &own;
        }
        if (!render_tile(&t, j, into, tile, &w->nan_samples, &w->extra_samples)) {
            /* What a cancelled tile traced is not its image. */
            film_clear(into, x0, y0, x1, y1);
            break;
        }
        w->tiles_done++;
        w->pixels_done += (uint64_t)(x1 - x0) * (uint64_t)(y1 - y0);
        size_t stride = 3 * (size_t)into->width;
        const float *finished = into->pixels + stride * (size_t)(y0 - into->y0) + 3 * (size_t)(x0 - into->x0);
        if (j->opts->tile_done)
            j->opts->tile_done(j->opts->tile_user, x0, y0, x1, y1, finished, stride);
        if (f->done)
            f->done(f->user, tile, finished, stride);
        if (j->opts->progress) {
            /* The lock keeps the calls one at a time and their counts in order. */
            pthread_mutex_lock(&j->progress_lock);
            j->opts->progress(j->opts->progress_user, ++j->tiles_done, l->tiles_total);
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

/* Runs the job on `count` threads, the caller's being the first, adding
 * up their counts in *sum. */
static glint_status run_workers(job *j, int count, worker *sum, glint_error *err)
{
    worker *ws = calloc((size_t)count, sizeof *ws);
    if (!ws)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory starting threads");
    const render_layout *l = &j->layout;
    size_t tile_floats = 3 * (size_t)(l->tile_size < l->width ? l->tile_size : l->width) *
                         (size_t)(l->tile_size < l->height ? l->tile_size : l->height);
    bool fits = true;
    for (int i = 0; i < count; i++) {
        ws[i].job = j;
        if (j->feed->tiles_only)
            fits = fits && (ws[i].tile_pixels = malloc(tile_floats * sizeof(float))) != NULL;
    }
    if (fits)
        parallel_run(count, worker_run, ws, sizeof *ws);
    for (int i = 0; i < count; i++) {
        sum->tiles_done += ws[i].tiles_done;
        sum->pixels_done += ws[i].pixels_done;
        sum->rays += ws[i].rays;
        sum->nan_samples += ws[i].nan_samples;
        sum->extra_samples += ws[i].extra_samples;
        free(ws[i].tile_pixels);
    }
    free(ws);
    return fits ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "out of memory for the threads' tiles");
}

/* Whether some material of the scene sends rays on from its hits. */
static bool some_material_branches(const glint_scene *scene)
{
    for (int i = 0; i < scene->material_count; i++)
        if (material_branches(&scene->materials[i].m))
            return true;
    return false;
}

/* Frees the film unless it is the caller's. */
static void drop_film(job *j)
{
    if (!j->feed->pixels)
        film_free(&j->film);
}

glint_status render_tiles(const glint_scene *scene, const glint_render_options *options, const render_feed *feed,
                          glint_image *out, glint_render_stats *stats, glint_error *err)
{
    static const glint_render_options defaults;
    const glint_render_options *o = options ? options : &defaults;
    const glint_settings *s = &scene->settings;
    out->width = out->height = 0;
    out->pixels = NULL;
    if (o->threads < 0 || o->threads > MAX_THREADS)
        return error_set(err, GLINT_ERR_INVALID, "thread count must be 0..%d, got %d", MAX_THREADS, o->threads);
    job j = {.scene = scene, .opts = o, .feed = feed};
    glint_status st = render_layout_for(scene, o->tile_size, &j.layout, err);
    if (st)
        return st;
    double start = now_seconds();

    j.samples = s->samples_per_pixel;
    j.keys = tracer_needs_keys(scene);
    j.plain = plain_packet_scene(scene);
    spectrum_init(&j.bands, s->dispersion_bands);
    j.key_seed = glint_settings_random_seed(&scene->settings) ^ 0x4b455953U;
    camera_init(&j.cam, &scene->camera, s->width, s->height);
    /* A sample covers its share of the pixel: the samples of a pixel
     * together cover it. */
    j.cone_width = j.cam.cone_width / sqrt(s->samples_per_pixel);
    j.cone_spread = j.cam.cone_spread / sqrt(s->samples_per_pixel);
    /* Motion blur only with a shutter open for a while. */
    bool shutter = s->shutter_close > s->shutter_open;
    j.pose_count = shutter ? scene->camera_pose_count : 0;
    for (int k = 0; k < j.pose_count; k++)
        camera_init(&j.poses[k], &scene->camera_poses[k], s->width, s->height);
    j.motion = j.pose_count > 0;
    for (int i = 0; shutter && i < scene->shape_count; i++)
        j.motion |= scene->shapes[i].pose_count > 0;
    for (int i = 0; shutter && i < scene->light_count; i++)
        j.motion |= scene->lights[i].pose_count > 0;
    for (int i = 0; shutter && i < scene->instance_count; i++)
        j.motion |= scene->instances[i].pose_count > 0;
    pixel_sampler_init(&j.sampler, s, j.cam.uses_lens, j.motion);
    j.signed_film = s->adaptive_max_samples != 0 || j.sampler.filter.has_negative_lobes;
    /* Embree builds with every thread asked for; tracing needs no more
     * threads than tiles. */
    int build_threads = o->threads ? o->threads : processors_online(MAX_THREADS);
    int threads = build_threads < j.layout.tiles_total ? build_threads : j.layout.tiles_total;

    accel *acc = NULL;
    bool *shape_opaque, *instance_opaque;
    if (!hit_opacity(scene, &shape_opaque, &instance_opaque)) {
        st = error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    } else {
        accel_geometry geo = {.threads = build_threads,
                              .shapes = scene->shapes,
                              .shape_count = scene->shape_count,
                              .meshes = scene->meshes,
                              .mesh_count = scene->mesh_count,
                              .instances = scene->instances,
                              .instance_count = scene->instance_count,
                              .shape_opaque = shape_opaque,
                              .instance_opaque = instance_opaque,
                              .cancel = o->cancel,
                              .camera_samples = (double)s->width * s->height * s->samples_per_pixel,
                              .bounces = some_material_branches(scene) ? s->max_depth : 0};
        st = accel_build(&acc, &geo, err);
    }
    /* A build the cancel flag stopped goes on as a render that finished no
     * tile. The image after the hierarchy: the build's scratch memory is given
     * back before the image's pages are touched, so a scene of a million
     * spheres peaks 25 MiB lower at 1920x1080. Every pixel is written once
     * its tile is done, so the image starts black only where a cancelled
     * render keeps the tiles it finished. */
    if (!st || st == GLINT_ERR_CANCELLED) {
        if (feed->pixels || feed->tiles_only)
            j.film = (film){.pixels = feed->pixels, .width = s->width, .height = s->height, .samples = j.samples};
        else if (!film_init(&j.film, s->width, s->height, j.samples, o->keep_partial))
            st = error_set(err, GLINT_ERR_NOMEM, "out of memory for a %dx%d image", s->width, s->height);
        j.film.exposure_scale = exp2(s->exposure);
    }
    if (st && st != GLINT_ERR_CANCELLED) {
        accel_free(acc);
        free(shape_opaque);
        free(instance_opaque);
        return st;
    }
    worker sum = {0};
    if (!st) {
        j.acc = acc;
        pthread_mutex_init(&j.progress_lock, NULL);
        /* Built only for a render that chooses among its lights. */
        if (s->light_samples > 0 && !light_choice_init(&j.choice, scene->lights, scene->area_lights,
                                                       scene->area_light_count, scene->emitters,
                                                       scene->emitter_count))
            st = error_set(err, GLINT_ERR_NOMEM, "out of memory choosing among the lights");
        else
            st = run_workers(&j, threads, &sum, err);
        light_choice_free(&j.choice);
        pthread_mutex_destroy(&j.progress_lock);
        accel_free(acc);
    }
    free(shape_opaque);
    free(instance_opaque);
    bool stopped = (!st || st == GLINT_ERR_CANCELLED) && cancelled(&j);
    if (stopped)
        st = error_set(err, GLINT_ERR_CANCELLED, "render cancelled");
    if (st && !(stopped && o->keep_partial)) {
        drop_film(&j);
        return st;
    }
    /* A cancelled render keeping its finished tiles: the others, rendered
     * in part (made black again) or not at all, are black. A feed of tiles
     * alone gets no image. */
    if (j.film.pixels)
        *out = (glint_image){.width = s->width, .height = s->height, .pixels = j.film.pixels};
    if (stats) {
        stats->seconds = now_seconds() - start;
        stats->samples = sum.pixels_done * (uint64_t)j.samples + sum.extra_samples;
        stats->rays = sum.rays;
        stats->nan_samples = sum.nan_samples;
        stats->tiles_done = sum.tiles_done;
        stats->tiles_total = j.layout.tiles_total;
    }
    return st;
}

/* glint_render's feed: every tile in order, from a counter. */
static int next_in_order(void *user)
{
    return atomic_fetch_add((atomic_int *)user, 1);
}

glint_status glint_render(const glint_scene *scene, const glint_render_options *options, glint_image *out,
                          glint_render_stats *stats, glint_error *err)
{
    atomic_int next;
    atomic_init(&next, 0);
    render_feed feed = {.next = next_in_order, .user = &next};
    return render_tiles(scene, options, &feed, out, stats, err);
}
