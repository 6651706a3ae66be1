/* main.c - the glint command: parses flags, renders the built-in seed room
 * through the public API, shows progress and writes the image. */
#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "glint.h"

enum exit_code {
    EXIT_OK = 0,
    EXIT_BAD_INPUT = 1,   /* a scene or texture that cannot be used */
    EXIT_USAGE = 2,       /* flags that do not parse */
    EXIT_IO = 3,          /* the output cannot be written */
    EXIT_INTERRUPTED = 4, /* SIGINT or SIGTERM */
    EXIT_INTERNAL = 5     /* out of memory, Embree failure */
};

#define MAX_TEXTURE_SWAPS 16

typedef struct options {
    const char *scene;          /* NULL: the built-in seed room */
    const char *output;         /* NULL: the scene's, else glint.png */
    bool check;
    long long width, height, spp, depth, threads, seed; /* -1: the scene's own */
    int sampler;                                        /* -1: the scene's own */
    bool quiet;
    bool partial;
    const char *swap_name[MAX_TEXTURE_SWAPS], *swap_path[MAX_TEXTURE_SWAPS];
    char swap_buf[MAX_TEXTURE_SWAPS][256];
    int swaps;
} options;

static const char USAGE[] =
    "usage: glint [SCENE.yaml | MODEL] [options]\n"
    "Renders a scene file (docs/scene-format.md), a model file (.obj, .ply, .stl,\n"
    ".gltf, .glb: framed on a floor, lit), or without either the built-in seed room\n"
    "(the COSC363 scene), to an image. Flags override the file's settings.\n"
    "\n"
    "options:\n"
    "  -o, --output FILE      image to write, .png (8-bit sRGB) or .ppm (default: the\n"
    "                         scene's output setting, else glint.png)\n"
    "      --check            validate the scene file, report every problem, render nothing\n"
    "  -w, --width N          image width in pixels, 1..65536\n"
    "  -h, --height N         image height in pixels, 1..65536; at most 16384 x 16384\n"
    "                         pixels in all\n"
    "      --spp N            samples per pixel, a square number 1, 4, 9, ... 4096\n"
    "      --sampler NAME     regular (an N x N grid) or jittered (one random point in\n"
    "                         each cell of the grid)\n"
    "      --seed N           seed of the jittered sampler, 0..4294967295\n"
    "      --depth N          reflection and refraction recursion limit, 0..64\n"
    "                         (the seed room: 1000 x 1000, 4 samples, regular, depth 5)\n"
    "      --threads N        render threads, 1..1024 (default: one per core); the image\n"
    "                         is the same for any count\n"
    "      --texture NAME=FILE\n"
    "                         replace the image of the scene's texture NAME (the seed\n"
    "                         room's is 'moon') with a PNG or JPEG file\n"
    "      --partial          when interrupted, write the finished tiles (the rest\n"
    "                         black) instead of nothing, and still exit 4\n"
    "  -q, --quiet            no progress line and no summary on stderr\n"
    "      --help             show this help and exit\n"
    "      --version          print the version and exit\n"
    "\n"
    "Exit codes: 0 success, 1 bad input (scene file, texture), 2 bad usage, 3 the output\n"
    "cannot be written, 4 interrupted (SIGINT or SIGTERM), 5 internal failure (out of\n"
    "memory, Embree). An interrupted render stops within a moment and writes nothing\n"
    "unless --partial. The image is written under a temporary name and renamed into\n"
    "place, so a failed or interrupted run never leaves a half-written file or destroys\n"
    "an existing one.\n";

/* The render's cancel flag is a volatile int; on the platforms glint runs
 * on, sig_atomic_t is that int. */
_Static_assert(sizeof(sig_atomic_t) == sizeof(int), "sig_atomic_t must be an int");
static volatile sig_atomic_t interrupted;

static void on_signal(int sig)
{
    (void)sig;
    interrupted = 1;
}

static int complain(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("glint: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return code;
}

/* Parses a whole decimal number in [lo, hi]. */
static bool parse_int(const char *text, long long lo, long long hi, long long *out)
{
    char *end;
    errno = 0;
    long long v = strtoll(text, &end, 10);
    if (errno || end == text || *end != '\0' || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

typedef struct number_flag {
    const char *long_name, *short_name;
    size_t field;                 /* offset of the long long in options */
    long long lo, hi;
    const char *what;
} number_flag;

static const number_flag NUMBER_FLAGS[] = {
    {"--width", "-w", offsetof(options, width), 1, 65536, "a whole number from 1 to 65536"},
    {"--height", "-h", offsetof(options, height), 1, 65536, "a whole number from 1 to 65536"},
    {"--spp", NULL, offsetof(options, spp), 1, 4096, "a square number from 1 to 4096 (1, 4, 9, 16, ...)"},
    {"--depth", NULL, offsetof(options, depth), 0, 64, "a whole number from 0 to 64"},
    {"--threads", NULL, offsetof(options, threads), 1, 1024, "a whole number from 1 to 1024"},
    {"--seed", NULL, offsetof(options, seed), 0, 4294967295LL, "a whole number from 0 to 4294967295"},
};

static bool is_square(long long n)
{
    long long r = 0;
    while ((r + 1) * (r + 1) <= n)
        r++;
    return r * r == n;
}

static int parse_texture_swap(options *o, const char *arg)
{
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg || eq[1] == '\0' || (size_t)(eq - arg) >= sizeof o->swap_buf[0])
        return complain(EXIT_USAGE, "--texture needs NAME=FILE, got '%s'", arg);
    if (o->swaps == MAX_TEXTURE_SWAPS)
        return complain(EXIT_USAGE, "--texture may be given at most %d times", MAX_TEXTURE_SWAPS);
    memcpy(o->swap_buf[o->swaps], arg, (size_t)(eq - arg));
    o->swap_buf[o->swaps][eq - arg] = '\0';
    o->swap_name[o->swaps] = o->swap_buf[o->swaps];
    o->swap_path[o->swaps] = eq + 1;
    o->swaps++;
    return 0;
}

/* Fills o from argv; returns -1 to go on, or an exit code. */
static int parse_args(int argc, char **argv, options *o)
{
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0) {
            fputs(USAGE, stdout);
            return EXIT_OK;
        }
        if (strcmp(a, "--version") == 0) {
            printf("glint %s\n", glint_version());
            return EXIT_OK;
        }
        if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
            o->quiet = true;
            continue;
        }
        if (strcmp(a, "--check") == 0) {
            o->check = true;
            continue;
        }
        if (strcmp(a, "--partial") == 0) {
            o->partial = true;
            continue;
        }
        if (a[0] != '-' || a[1] == '\0') {
            if (o->scene)
                return complain(EXIT_USAGE, "unexpected argument '%s': one scene file at a time (try 'glint --help')", a);
            o->scene = a;
            continue;
        }
        const number_flag *nf = NULL;
        for (size_t k = 0; k < sizeof NUMBER_FLAGS / sizeof NUMBER_FLAGS[0]; k++)
            if (strcmp(a, NUMBER_FLAGS[k].long_name) == 0 ||
                (NUMBER_FLAGS[k].short_name && strcmp(a, NUMBER_FLAGS[k].short_name) == 0))
                nf = &NUMBER_FLAGS[k];
        bool takes_value = nf || strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0 ||
                           strcmp(a, "--sampler") == 0 || strcmp(a, "--texture") == 0;
        if (!takes_value)
            return complain(EXIT_USAGE, "unknown option '%s' (try 'glint --help')", a);
        if (i + 1 >= argc)
            return complain(EXIT_USAGE, "option '%s' needs a value", a);
        const char *v = argv[++i];
        if (nf) {
            long long *field = (long long *)((char *)o + nf->field);
            if (!parse_int(v, nf->lo, nf->hi, field) || (field == &o->spp && !is_square(*field)))
                return complain(EXIT_USAGE, "%s needs %s, got '%s'", nf->long_name, nf->what, v);
        } else if (strcmp(a, "--sampler") == 0) {
            if (strcmp(v, "regular") == 0)
                o->sampler = GLINT_SAMPLER_REGULAR;
            else if (strcmp(v, "jittered") == 0)
                o->sampler = GLINT_SAMPLER_JITTERED;
            else
                return complain(EXIT_USAGE, "--sampler needs 'regular' or 'jittered', got '%s'", v);
        } else if (strcmp(a, "--texture") == 0) {
            int code = parse_texture_swap(o, v);
            if (code)
                return code;
        } else {
            if (v[0] == '\0')
                return complain(EXIT_USAGE, "%s needs a file name", a);
            o->output = v;
        }
    }
    if (o->check && !o->scene)
        return complain(EXIT_USAGE, "--check needs a scene file");
    return -1;
}

static int exit_code_of(glint_status s)
{
    switch (s) {
    case GLINT_OK: return EXIT_OK;
    case GLINT_ERR_INVALID: return EXIT_BAD_INPUT;
    case GLINT_ERR_IO: return EXIT_IO;
    case GLINT_ERR_CANCELLED: return EXIT_INTERRUPTED;
    default: return EXIT_INTERNAL;
    }
}

static void apply_overrides(const options *o, glint_settings *s)
{
    if (o->width >= 0) s->width = (int)o->width;
    if (o->height >= 0) s->height = (int)o->height;
    if (o->spp >= 0) s->samples_per_pixel = (int)o->spp;
    if (o->depth >= 0) s->max_depth = (int)o->depth;
    if (o->seed >= 0) s->seed = (uint32_t)o->seed;
    if (o->sampler >= 0) s->sampler = (glint_sampler)o->sampler;
}

typedef struct progress {
    struct timespec start;
    double last_print;
} progress;

static double seconds_since(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (t.tv_sec - t0->tv_sec) + (t.tv_nsec - t0->tv_nsec) * 1e-9;
}

static void show_progress(void *user, int done, int total)
{
    progress *p = user;
    double elapsed = seconds_since(&p->start);
    if (done < total && elapsed - p->last_print < 0.1)
        return;
    p->last_print = elapsed;
    double left = done > 0 ? elapsed * (total - done) / done : 0;
    fprintf(stderr, "\r%3d%%  %.1f s elapsed, %.1f s left   ", (int)(100.0 * done / total), elapsed, left);
    if (done == total)
        fputs("\r\033[K", stderr);
    fflush(stderr);
}

#define MAX_PROBLEMS 20

static void print_problem(void *user, const char *message)
{
    ++*(int *)user;
    fprintf(stderr, "%s\n", message);
}

/* Loads the scene file (or builds a scene around a model file), printing
 * every problem and a last line saying what became of the run; NULL after
 * reporting. */
static glint_scene *load_scene(const char *path, const char *outcome)
{
    glint_error err = {{0}};
    if (glint_is_model_path(path)) {
        glint_scene *model = glint_scene_for_model(path, &err);
        if (!model)
            complain(EXIT_BAD_INPUT, "%s", err.message);
        return model;
    }
    int problems = 0;
    glint_load_options lo = {.report = print_problem, .report_user = &problems, .max_errors = MAX_PROBLEMS};
    glint_scene *scene = glint_scene_load_file(path, &lo, &err);
    if (!scene)
        complain(EXIT_BAD_INPUT, "%s: %d problem%s%s; %s", path, problems, problems == 1 ? "" : "s",
                 problems >= MAX_PROBLEMS ? " (stopped at the limit)" : "", outcome);
    return scene;
}

static int check_only(const options *o)
{
    glint_scene *scene = load_scene(o->scene, "not valid");
    if (!scene)
        return EXIT_BAD_INPUT;
    glint_scene_counts c = glint_scene_get_counts(scene);
    printf("%s: ok: %d textures, %d materials, %d shapes, %d lights", o->scene, c.textures, c.materials, c.shapes,
           c.lights);
    if (c.meshes > 0)
        printf(", %d meshes (%lld triangles) placed %d times", c.meshes, c.triangles, c.instances);
    putchar('\n');
    glint_scene_free(scene);
    return EXIT_OK;
}

/* An interrupted render: nothing written, or with --partial its finished
 * tiles. Either way the exit code says it was interrupted. */
static int interrupted_run(const options *o, const glint_image *image, const glint_render_stats *stats,
                           const char *output)
{
    if (!o->partial)
        return complain(EXIT_INTERRUPTED, "interrupted: nothing written");
    glint_error err = {{0}};
    glint_status st = glint_image_write(image, output, &err);
    if (st)
        return complain(exit_code_of(st), "interrupted, and the finished tiles were not written: %s", err.message);
    return complain(EXIT_INTERRUPTED, "interrupted: %d of %d tiles finished, written to %s (the rest black)",
                    stats->tiles_done, stats->tiles_total, output);
}

static int run(const options *o)
{
    glint_error err = {{0}};
    glint_scene *scene = o->scene ? load_scene(o->scene, "nothing rendered") : glint_scene_seed_room(&err);
    if (!scene)
        return o->scene ? EXIT_BAD_INPUT : complain(EXIT_INTERNAL, "%s", err.message);
    const char *output = o->output ? o->output : glint_scene_get_output(scene) ? glint_scene_get_output(scene)
                                                                                 : "glint.png";
    glint_status st = glint_image_check_path(output, &err);
    if (st) {
        glint_scene_free(scene);
        return complain(st == GLINT_ERR_INVALID ? EXIT_USAGE : exit_code_of(st), "%s", err.message);
    }
    for (int i = 0; i < o->swaps && !st; i++)
        st = glint_scene_replace_image(scene, o->swap_name[i], o->swap_path[i], &err);
    glint_settings settings = glint_scene_get_settings(scene);
    apply_overrides(o, &settings);
    if (st) {
        glint_scene_free(scene);
        /* Whatever stopped the scene, unreadable textures included, is bad input. */
        return complain(st == GLINT_ERR_NOMEM ? EXIT_INTERNAL : EXIT_BAD_INPUT, "%s", err.message);
    }
    /* The scene's own settings passed when it loaded: only the flags can
     * make them fail now (an image too large in all, say). */
    if (glint_scene_set_settings(scene, &settings, &err)) {
        glint_scene_free(scene);
        return complain(EXIT_USAGE, "%s", err.message);
    }

    /* From here on a signal cancels the render, which then writes nothing;
     * before, the default action ends glint, which has written nothing yet. */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    progress prog = {.last_print = -1};
    clock_gettime(CLOCK_MONOTONIC, &prog.start);
    glint_render_options ro = {.threads = o->threads > 0 ? (int)o->threads : 0,
                               .cancel = (const volatile int *)&interrupted, .keep_partial = o->partial};
    if (!o->quiet && isatty(STDERR_FILENO)) {
        ro.progress = show_progress;
        ro.progress_user = &prog;
    }
    glint_image image;
    glint_render_stats stats;
    st = glint_render(scene, &ro, &image, &stats, &err);
    if (ro.progress && st == GLINT_ERR_CANCELLED)
        fputs("\r\033[K", stderr); /* the progress line stopped short */
    if (st == GLINT_ERR_CANCELLED) {
        int code = interrupted_run(o, &image, &stats, output);
        glint_image_free(&image);
        glint_scene_free(scene);
        return code;
    }
    if (!st)
        st = glint_image_write(&image, output, &err);
    glint_image_free(&image);
    if (st) {
        glint_scene_free(scene);
        return complain(exit_code_of(st), "%s", err.message);
    }
    /* A warning, not a failure: the image is written, without them. */
    if (stats.nan_samples > 0)
        fprintf(stderr, "glint: warning: %llu sample%s came out NaN (not a number) and %s left out of %s pixel%s\n",
                (unsigned long long)stats.nan_samples, stats.nan_samples == 1 ? "" : "s",
                stats.nan_samples == 1 ? "was" : "were", stats.nan_samples == 1 ? "its" : "their",
                stats.nan_samples == 1 ? "" : "s");
    if (!o->quiet) {
        long threads = o->threads > 0 ? (long)o->threads : sysconf(_SC_NPROCESSORS_ONLN);
        fprintf(stderr, "glint: %dx%d, %d spp, %ld thread%s: %.3f s, %llu samples, %llu rays, %.1f Mrays/s -> %s\n",
                settings.width, settings.height, settings.samples_per_pixel, threads, threads == 1 ? "" : "s", stats.seconds,
                (unsigned long long)stats.samples, (unsigned long long)stats.rays,
                stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, output);
    }
    glint_scene_free(scene); /* last: output may point into it */
    return EXIT_OK;
}

int main(int argc, char **argv)
{
    options o = {.width = -1, .height = -1, .spp = -1, .depth = -1,
                 .threads = -1, .seed = -1, .sampler = -1};
    int code = parse_args(argc, argv, &o);
    if (code >= 0)
        return code;
    return o.check ? check_only(&o) : run(&o);
}
