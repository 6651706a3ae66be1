/* tile_times.c - the measured cost of every tile of one render, for the
 * glint-mpi scaling model (bench/mpi_model.c). It loads a scene file
 * (timing glint_scene_load_file, which reads OBJ files on every core),
 * optionally at another image size or sample count, and renders it with
 * one thread through the render back-end (render/render_tiles.h), with a
 * feed that hands out the tiles in order and times each one from the
 * moment the thread takes it to the moment it is finished. The time from
 * calling the back-end to the first tile taken is its set-up: the camera,
 * the film and Embree's BVH, built with one thread as a one-thread rank
 * builds it. With --runs N it loads and renders N times and keeps the
 * median load, the median set-up and each tile's median time, so that
 * whatever else the machine runs disturbs no tile much; each tile's
 * shortest time instead made the frame 15% faster than any one render.
 *
 *   bench_tile_times SCENE.yaml [--size WxH] [--spp N] [--tile N] [--runs N] > times.txt
 *
 * Prints, on stdout, `image W H TILE`, `load S`, `setup S`, then one line
 * `tile X0 Y0 S` per tile in the layout's order; on stderr one summary
 * line: `tile_times: WxH, N tiles of T px, load L s, set-up S s, tiles R s
 * (sum, median of N runs)`. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "glint.h"
#include "render/render_tiles.h"

#define MAX_RUNS 100

/* The feed's state over one render. One render thread, so no locks. */
typedef struct tile_clock {
    int next_tile;
    int tiles_total;
    double first_taken;     /* when the first tile was taken: set-up ends; < 0 before */
    double taken;           /* when the tile being rendered was taken */
    double *seconds;        /* per tile, this run's time */
} tile_clock;

/* The monotonic clock, in seconds. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Says what went wrong and exits with 1. */
_Noreturn static void die(const char *msg)
{
    fprintf(stderr, "bench_tile_times: %s\n", msg);
    exit(1);
}

/* The feed's next: every tile in order, noting when it was taken. */
static int take_tile(void *user)
{
    tile_clock *c = user;
    c->taken = now();
    if (c->first_taken < 0)
        c->first_taken = c->taken;
    return c->next_tile < c->tiles_total ? c->next_tile++ : -1;
}

/* The feed's done: the tile's time. */
static void finish_tile(void *user, int tile, const float *pixels, size_t stride)
{
    tile_clock *c = user;
    c->seconds[tile] = now() - c->taken;
}

/* qsort's order of two doubles. */
static int compare_seconds(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n values, which it sorts. */
static double median(double *values, int n)
{
    qsort(values, (size_t)n, sizeof *values, compare_seconds);
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

/* Reads "WxH" into *w and *h; false when it is not two positive numbers. */
static bool parse_size(const char *text, int *w, int *h)
{
    char end;
    return sscanf(text, "%dx%d%c", w, h, &end) == 2 && *w > 0 && *h > 0;
}

/* Loads the scene file `runs` times (each load of the same warm files),
 * keeping the last scene; the median load time in *load. */
static glint_scene *load_timed(const char *path, int runs, double *load)
{
    glint_error err = {0};
    glint_scene *scene = NULL;
    double loads[MAX_RUNS];
    for (int run = 0; run < runs; run++) {
        glint_scene_free(scene);
        double start = now();
        scene = glint_scene_load_file(path, NULL, &err);
        loads[run] = now() - start;
        if (!scene)
            die(err.message);
    }
    *load = median(loads, runs);
    return scene;
}

/* Renders the scene `runs` times with one thread, tile by tile in order:
 * run r's time of tile t into seconds[t * runs + r]; the median set-up. */
static double render_timed(const glint_scene *scene, const render_layout *layout, int runs, double *seconds)
{
    int tiles = layout->tiles_total;
    tile_clock clock = {.tiles_total = tiles, .seconds = malloc((size_t)tiles * sizeof *clock.seconds)};
    if (!clock.seconds)
        die("out of memory for the tiles' times");
    double setups[MAX_RUNS];
    glint_render_options options = {.threads = 1, .tile_size = layout->tile_size};
    render_feed feed = {.next = take_tile, .done = finish_tile, .user = &clock};
    for (int run = 0; run < runs; run++) {
        clock.next_tile = 0;
        clock.first_taken = -1;
        double started = now();
        glint_image image;
        glint_error err = {0};
        if (render_tiles(scene, &options, &feed, &image, NULL, &err))
            die(err.message);
        glint_image_free(&image);
        setups[run] = clock.first_taken - started;
        for (int t = 0; t < tiles; t++)
            seconds[(size_t)t * (size_t)runs + (size_t)run] = clock.seconds[t];
    }
    free(clock.seconds);
    return median(setups, runs);
}

int main(int argc, char **argv)
{
    const char *path = NULL;
    int width = 0, height = 0, spp = 0, tile_size = 32, runs = 1;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            if (!parse_size(argv[++i], &width, &height))
                die("--size needs WxH, e.g. 3840x2160");
        } else if (strcmp(argv[i], "--spp") == 0 && i + 1 < argc) {
            spp = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--tile") == 0 && i + 1 < argc) {
            tile_size = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = atoi(argv[++i]);
        } else if (!path && argv[i][0] != '-') {
            path = argv[i];
        } else {
            die("usage: bench_tile_times SCENE.yaml [--size WxH] [--spp N] [--tile N] [--runs N]");
        }
    }
    if (!path || spp < 0 || tile_size < 4 || runs < 1 || runs > MAX_RUNS)
        die("usage: bench_tile_times SCENE.yaml [--size WxH] [--spp N] [--tile 4..] [--runs 1..100]");

    double load;
    glint_scene *scene = load_timed(path, runs, &load);
    glint_error err = {0};
    glint_settings settings = glint_scene_get_settings(scene);
    settings.width = width ? width : settings.width;
    settings.height = width ? height : settings.height;
    settings.samples_per_pixel = spp ? spp : settings.samples_per_pixel;
    if (glint_scene_set_settings(scene, &settings, &err))
        die(err.message);
    render_layout layout;
    if (render_layout_for(scene, tile_size, &layout, &err))
        die(err.message);

    int tiles = layout.tiles_total;
    double *seconds = malloc((size_t)tiles * (size_t)runs * sizeof *seconds);
    if (!seconds)
        die("out of memory for the tiles' times");
    double setup = render_timed(scene, &layout, runs, seconds), total = 0;
    printf("image %d %d %d\nload %.6f\nsetup %.6f\n", layout.width, layout.height, layout.tile_size, load, setup);
    for (int t = 0; t < tiles; t++) {
        int x0, y0, x1, y1;
        render_tile_bounds(&layout, t, &x0, &y0, &x1, &y1);
        double tile_seconds = median(seconds + (size_t)t * (size_t)runs, runs);
        printf("tile %d %d %.7f\n", x0, y0, tile_seconds);
        total += tile_seconds;
    }
    fprintf(stderr, "tile_times: %dx%d, %d tiles of %d px, load %.3f s, set-up %.3f s, tiles %.3f s (sum, median of %d run%s)\n",
            layout.width, layout.height, tiles, layout.tile_size, load, setup, total, runs, runs == 1 ? "" : "s");
    free(seconds);
    glint_scene_free(scene);
    return 0;
}
