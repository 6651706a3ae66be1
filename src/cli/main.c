/* main.c - the glint command: reads its flags (args.c), renders the scene
 * (a file, standard input) or the built-in seed room through the public
 * API, shows progress and writes the image to a file or standard output;
 * or checks scene files. */
#include <errno.h>
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

/* SIGINT, SIGTERM, SIGHUP (the terminal closed) and SIGQUIT (Ctrl-\) go to
 * on_signal from here on: each ends a render the same way, rather than
 * kill glint without a word (and, for SIGQUIT, a core dump). */
static void catch_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    static const int stops[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++)
        sigaction(stops[i], &sa, NULL);
}

/* Why the first flush of a report to stdout failed, or 0: a stream that
 * failed once may flush its next buffer without error, and errno is gone. */
static int report_errno;

/* Writes out what a report has put on stdout so far, remembering why if
 * it cannot (reported gives the exit code). */
static void flush_report(void)
{
    errno = 0;
    if (fflush(stdout) != 0 && !report_errno)
        report_errno = errno ? errno : EIO;
}

/* The exit code of a run that reports on stdout, with its problems on
 * stderr (the help, the version, --check, --print-scene): `code`, or 3 when
 * either could not be written in whole (a full disk, a reader gone), as a
 * lost report is no success. The reason is said on stderr, while that can
 * still be written, unless the run had already failed as badly: a higher
 * code wins, as in --check's worst of its files. */
static int reported(int code)
{
    flush_report();
    bool out_lost = report_errno != 0 || ferror(stdout);
    bool err_lost = fflush(stderr) != 0 || ferror(stderr);
    if (!out_lost && !err_lost)
        return code;
    /* A write that failed inside printf left its reason behind. */
    if (out_lost && code < CLI_EXIT_IO)
        cli_complain(CLI_EXIT_IO, "cannot write '<stdout>': %s", strerror(report_errno ? report_errno : EIO));
    return code > CLI_EXIT_IO ? code : CLI_EXIT_IO;
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

/* The name of a scene file in messages: "<stdin>" for '-'. */
static const char *scene_name(const char *path)
{
    return strcmp(path, "-") == 0 ? "<stdin>" : path;
}

/* Loads the scene file, or standard input for '-' (or builds a scene
 * around a model file, seen as o asks and framed for the image size it
 * gives), printing every problem and a last line saying what became of the
 * run; NULL after reporting, with *code the exit code: bad input, or an
 * internal failure when memory ran out. */
static glint_scene *load_scene(const cli_options *o, const char *path, const char *outcome, int *code)
{
    glint_error err = {0};
    glint_scene *scene;
    const char *name = scene_name(path);
    bool from_stdin = strcmp(path, "-") == 0;
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
        scene = from_stdin ? glint_scene_load_stream(stdin, name, &lo, &err) : glint_scene_load_file(path, &lo, &err);
        if (!scene)
            cli_complain(CLI_EXIT_BAD_INPUT, "%s: %d problem%s%s; %s", name, problems, problems == 1 ? "" : "s",
                         problems >= MAX_PROBLEMS ? " (stopped at the limit)" : "", outcome);
    }
    for (int i = 0; i < glint_scene_warning_count(scene); i++)
        fprintf(stderr, "glint: warning: %s\n", glint_scene_warning(scene, i));
    *code = err.status == GLINT_ERR_NOMEM ? CLI_EXIT_INTERNAL : CLI_EXIT_BAD_INPUT;
    return scene;
}

/* Prints `before`, then n and the word for n things: "1 texture", "2 textures". */
static void print_count(const char *before, long long n, const char *one, const char *many)
{
    printf("%s%lld %s", before, n, n == 1 ? one : many);
}

/* Checks one scene file: what it holds on stdout, or its problems on stderr. */
static int check_one(const cli_options *o, const char *path)
{
    int code;
    glint_scene *scene = load_scene(o, path, "not valid", &code);
    if (!scene)
        return code;
    glint_scene_counts c = glint_scene_get_counts(scene);
    printf("%s: ok:", scene_name(path));
    print_count(" ", c.textures, "texture", "textures");
    print_count(", ", c.materials, "material", "materials");
    print_count(", ", c.shapes, "shape", "shapes");
    print_count(", ", c.lights, "light", "lights");
    if (c.meshes > 0) {
        print_count(", ", c.meshes, "mesh", "meshes");
        print_count(" (", c.triangles, "triangle", "triangles");
        if (c.instances == 1)
            fputs(") placed once", stdout);
        else
            printf(") placed %d times", c.instances);
    }
    putchar('\n');
    glint_scene_free(scene);
    return CLI_EXIT_OK;
}

/* Checks every file named, each reported in turn; the exit code is the
 * worst of theirs, the highest: 5 (out of memory) over 1 (not valid) over
 * 0. */
static int check_only(const cli_options *o)
{
    int worst = CLI_EXIT_OK;
    for (int i = 0; i < o->scene_count; i++) {
        int code = check_one(o, o->scenes[i]);
        if (code > worst)
            worst = code;
        /* In order with the problems on stderr, when both go to one place. */
        flush_report();
    }
    return worst;
}

/* Where the image goes: a file, or standard output for "-". */
typedef struct destination {
    const char *path;                 /* the file, or "-" */
    const glint_image_format *format;
    const char *shown;                /* its name in messages: the file's, or "<stdout>" */
    char default_path[32];            /* glint.png, or glint.EXT of --format */
} destination;

/* Chooses where the image goes and in which format, and checks before
 * rendering that it can go there: -o, else the scene's output setting, else
 * glint.png (glint.ppm with --format ppm); a --format that disagrees with
 * the file's extension, or an --exr-pixel for other formats, is refused.
 * Returns -1 to go on, or the exit code after complaining. The path may
 * point into the scene. */
static int choose_destination(const cli_options *o, const glint_scene *scene, destination *d)
{
    d->path = o->output ? o->output : glint_scene_get_output(scene);
    if (!d->path) {
        snprintf(d->default_path, sizeof d->default_path, "glint%s", o->format ? o->format->extensions[0] : ".png");
        d->path = d->default_path;
    }
    glint_error err = {0};
    if (strcmp(d->path, "-") == 0) {
        d->format = o->format ? o->format : glint_image_format_named("png");
        d->shown = "<stdout>";
    } else {
        glint_status st = glint_image_check_path(d->path, &err);
        if (st)
            return cli_complain(st == GLINT_ERR_INVALID ? CLI_EXIT_USAGE : exit_code_of(st), "%s", err.message);
        d->format = glint_image_format_for_path(d->path);
        d->shown = d->path;
        if (o->format && o->format != d->format)
            return cli_complain(CLI_EXIT_USAGE, "--format %s does not match the output '%s', a %s file by its extension",
                                o->format->extensions[0] + 1, d->path, d->format->name);
    }
    /* A pixel type asked for and not given would be a surprise found after
     * the render. */
    if (o->exr_pixel >= 0 && strcmp(d->format->name, "OpenEXR") != 0)
        return strcmp(d->path, "-") != 0
                   ? cli_complain(CLI_EXIT_USAGE, "--exr-pixel is for .exr output, not '%s'", d->path)
                   : cli_complain(CLI_EXIT_USAGE, "--exr-pixel is for .exr output, not %s on standard output "
                                                  "(add --format exr)", d->format->name);
    return -1;
}

/* Writes the image to its destination. */
static glint_status write_image(const destination *d, const glint_image *image,
                                const glint_image_write_options *options, glint_error *err)
{
    return strcmp(d->path, "-") == 0 ? glint_image_write_fd(image, STDOUT_FILENO, d->format, options, d->shown, err)
                                     : glint_image_write_ex(image, d->path, options, err);
}

/* An interrupted render: nothing written, or with --partial its finished
 * tiles. Either way the exit code says it was interrupted. */
static int interrupted_run(const cli_options *o, const glint_image *image, const glint_render_stats *stats,
                           const destination *d, const glint_image_write_options *write_options)
{
    if (!o->partial)
        return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: nothing written");
    glint_error err = {0};
    glint_status st = write_image(d, image, write_options, &err);
    if (st)
        return cli_complain(exit_code_of(st), "interrupted, and the finished tiles were not written: %s", err.message);
    return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: %d of %d tiles finished, written to %s (the rest black)",
                        stats->tiles_done, stats->tiles_total, d->shown);
}

/* --print-scene: the scene, with the output -o names, as a scene file on
 * stdout. */
static int print_scene(glint_scene *scene, const char *output)
{
    glint_error err = {0};
    glint_status st = output ? glint_scene_set_output(scene, output, &err) : GLINT_OK;
    if (!st)
        st = glint_scene_write_yaml(scene, stdout, &err);
    glint_scene_free(scene);
    return st ? cli_complain(exit_code_of(st), "%s", err.message) : CLI_EXIT_OK;
}

static int run(const cli_options *o)
{
    /* Image bytes on a terminal are a mistake, found before the work. */
    if (o->output && strcmp(o->output, "-") == 0 && isatty(STDOUT_FILENO))
        return cli_complain(CLI_EXIT_USAGE, "will not write a%s %s image to a terminal; redirect stdout or give -o FILE",
                            o->format && strchr("AEIOU", o->format->name[0]) ? "n" : "",
                            o->format ? o->format->name : "PNG");
    glint_error err = {0};
    int code = CLI_EXIT_INTERNAL;
    glint_scene *scene = o->scene ? load_scene(o, o->scene, "nothing rendered", &code) : glint_scene_seed_room(&err);
    if (!scene)
        return o->scene ? code : cli_complain(CLI_EXIT_INTERNAL, "%s", err.message);
    destination d;
    code = choose_destination(o, scene, &d);
    if (code >= 0) {
        glint_scene_free(scene); /* last: the path may point into it */
        return code;
    }
    glint_status st = GLINT_OK;
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

    if (o->print_scene)
        return print_scene(scene, o->output);

    /* An output over one of the run's own inputs would destroy it. */
    if (strcmp(d.path, "-") != 0 && glint_scene_check_output(scene, d.path, &err)) {
        glint_scene_free(scene);
        return cli_complain(CLI_EXIT_IO, "%s", err.message);
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
        code = interrupted_run(o, &image, &stats, &d, &write_options);
        glint_image_free(&image);
        glint_scene_free(scene);
        return code;
    }
    if (!st)
        st = write_image(&d, &image, &write_options, &err);
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
                stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, d.shown);
    }
    glint_scene_free(scene); /* last: output may point into it */
    return CLI_EXIT_OK;
}

int main(int argc, char **argv)
{
    /* A reader of stdout or stderr that goes away makes a write fail with
     * EPIPE, reported with exit code 3, rather than kill glint (141) after
     * its work; the help and the flags' errors included. */
    signal(SIGPIPE, SIG_IGN);
    cli_options o;
    int code = cli_parse_args(argc, argv, &o);
    if (code >= 0)
        return reported(code);
    catch_signals();
    if (o.check)
        return reported(check_only(&o));
    code = run(&o);
    return o.print_scene ? reported(code) : code;
}
