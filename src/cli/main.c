/* main.c - the glint command: reads its flags (args.c), renders the scene
 * or the built-in seed room through the public API, shows progress and
 * writes the image. */
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "glint.h"
#include "cli/args.h"

/* The render's cancel flag is a volatile int; on the platforms glint runs
 * on, sig_atomic_t is that int. */
_Static_assert(sizeof(sig_atomic_t) == sizeof(int), "sig_atomic_t must be an int");
static volatile sig_atomic_t interrupted;
/* Whether the render has begun: before, nothing can be cancelled gently
 * (reading a large model does not look at a flag), and nothing has been
 * written, so a signal ends glint at once, with the same message and exit
 * code as an interrupted render. */
static volatile sig_atomic_t rendering;

static void on_signal(int sig)
{
    (void)sig;
    interrupted = 1;
    if (!rendering) {
        static const char message[] = "glint: interrupted: nothing written\n";
        ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
        (void)ignored;
        _exit(CLI_EXIT_INTERRUPTED);
    }
}

/* SIGINT and SIGTERM go to on_signal from here on. */
static void catch_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

static int exit_code_of(glint_status s)
{
    switch (s) {
    case GLINT_OK: return CLI_EXIT_OK;
    case GLINT_ERR_INVALID: return CLI_EXIT_BAD_INPUT;
    case GLINT_ERR_IO: return CLI_EXIT_IO;
    case GLINT_ERR_CANCELLED: return CLI_EXIT_INTERRUPTED;
    default: return CLI_EXIT_INTERNAL;
    }
}

static void apply_overrides(const cli_options *o, glint_settings *s)
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

/* Loads the scene file (or builds a scene around a model file, seen as o
 * asks and framed for the image size it gives), printing every problem and
 * a last line saying what became of the run; NULL after reporting, with
 * *code the exit code: bad input, or an internal failure when memory ran
 * out. */
static glint_scene *load_scene(const cli_options *o, const char *path, const char *outcome, int *code)
{
    glint_error err = {0};
    glint_scene *scene;
    if (glint_is_model_path(path)) {
        /* An image over the pixel limit is framed for the default size:
         * the flags are refused as usage when the size is set (run). */
        bool fits = o->width * o->height <= GLINT_MAX_PIXELS;
        glint_model_view_options view = {.view = o->view >= 0 ? (glint_model_view)o->view : GLINT_VIEW_AUTO,
                                          .width = o->width > 0 && fits ? (int)o->width : 0,
                                          .height = o->height > 0 && fits ? (int)o->height : 0};
        scene = glint_scene_for_model_ex(path, &view, &err);
        if (!scene)
            cli_complain(CLI_EXIT_BAD_INPUT, "%s", err.message);
    } else {
        int problems = 0;
        glint_load_options lo = {.report = print_problem, .report_user = &problems, .max_errors = MAX_PROBLEMS};
        scene = glint_scene_load_file(path, &lo, &err);
        if (!scene)
            cli_complain(CLI_EXIT_BAD_INPUT, "%s: %d problem%s%s; %s", path, problems, problems == 1 ? "" : "s",
                         problems >= MAX_PROBLEMS ? " (stopped at the limit)" : "", outcome);
    }
    *code = err.status == GLINT_ERR_NOMEM ? CLI_EXIT_INTERNAL : CLI_EXIT_BAD_INPUT;
    return scene;
}

static int check_only(const cli_options *o)
{
    int code;
    glint_scene *scene = load_scene(o, o->scene, "not valid", &code);
    if (!scene)
        return code;
    glint_scene_counts c = glint_scene_get_counts(scene);
    printf("%s: ok: %d textures, %d materials, %d shapes, %d lights", o->scene, c.textures, c.materials, c.shapes,
           c.lights);
    if (c.meshes > 0)
        printf(", %d meshes (%lld triangles) placed %d times", c.meshes, c.triangles, c.instances);
    putchar('\n');
    glint_scene_free(scene);
    return CLI_EXIT_OK;
}

/* An interrupted render: nothing written, or with --partial its finished
 * tiles. Either way the exit code says it was interrupted. */
static int interrupted_run(const cli_options *o, const glint_image *image, const glint_render_stats *stats,
                           const char *output, const glint_image_write_options *write_options)
{
    if (!o->partial)
        return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: nothing written");
    glint_error err = {0};
    glint_status st = glint_image_write_ex(image, output, write_options, &err);
    if (st)
        return cli_complain(exit_code_of(st), "interrupted, and the finished tiles were not written: %s", err.message);
    return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: %d of %d tiles finished, written to %s (the rest black)",
                        stats->tiles_done, stats->tiles_total, output);
}

static int run(const cli_options *o)
{
    glint_error err = {0};
    int code = CLI_EXIT_INTERNAL;
    glint_scene *scene = o->scene ? load_scene(o, o->scene, "nothing rendered", &code) : glint_scene_seed_room(&err);
    if (!scene)
        return o->scene ? code : cli_complain(CLI_EXIT_INTERNAL, "%s", err.message);
    const char *output = o->output ? o->output : glint_scene_get_output(scene) ? glint_scene_get_output(scene)
                                                                                 : "glint.png";
    glint_status st = glint_image_check_path(output, &err);
    if (st) {
        glint_scene_free(scene);
        return cli_complain(st == GLINT_ERR_INVALID ? CLI_EXIT_USAGE : exit_code_of(st), "%s", err.message);
    }
    /* A pixel type asked for and not given would be a surprise found after
     * the render. */
    if (o->exr_pixel >= 0 && strcmp(glint_image_format_for_path(output)->name, "OpenEXR") != 0) {
        code = cli_complain(CLI_EXIT_USAGE, "--exr-pixel is for .exr output, not '%s'", output);
        glint_scene_free(scene); /* last: output may point into it */
        return code;
    }
    glint_image_write_options write_options = {.exr_pixel = o->exr_pixel >= 0 ? o->exr_pixel : GLINT_EXR_HALF};
    for (int i = 0; i < o->swaps && !st; i++)
        st = glint_scene_replace_image(scene, o->swap_name[i], o->swap_path[i], &err);
    glint_settings settings = glint_scene_get_settings(scene);
    apply_overrides(o, &settings);
    if (st) {
        glint_scene_free(scene);
        /* Whatever stopped the scene, unreadable textures included, is bad input. */
        return cli_complain(st == GLINT_ERR_NOMEM ? CLI_EXIT_INTERNAL : CLI_EXIT_BAD_INPUT, "%s", err.message);
    }
    /* The scene's own settings passed when it loaded: only the flags can
     * make them fail now (an image too large in all, say). */
    if (glint_scene_set_settings(scene, &settings, &err)) {
        glint_scene_free(scene);
        return cli_complain(CLI_EXIT_USAGE, "%s", err.message);
    }

    /* From here on a signal cancels the render (its BVH build included),
     * which then writes nothing, or with --partial its finished tiles. */
    rendering = 1;
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
        code = interrupted_run(o, &image, &stats, output, &write_options);
        glint_image_free(&image);
        glint_scene_free(scene);
        return code;
    }
    if (!st)
        st = glint_image_write_ex(&image, output, &write_options, &err);
    glint_image_free(&image);
    if (st) {
        glint_scene_free(scene);
        return cli_complain(exit_code_of(st), "%s", err.message);
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
    return CLI_EXIT_OK;
}

int main(int argc, char **argv)
{
    cli_options o;
    int code = cli_parse_args(argc, argv, &o);
    if (code >= 0)
        return code;
    catch_signals();
    return o.check ? check_only(&o) : run(&o);
}
