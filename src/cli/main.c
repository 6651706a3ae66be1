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
#include "cli/setup.h"

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

/* Prints `before`, then n and the word for n things: "1 texture", "2 textures". */
static void print_count(const char *before, long long n, const char *one, const char *many)
{
    printf("%s%lld %s", before, n, n == 1 ? one : many);
}

/* Checks one scene file: what it holds on stdout, or its problems on stderr. */
static int check_one(const cli_options *o, const char *path)
{
    int code;
    glint_scene *scene = cli_load_scene(o, path, "not valid", true, &code);
    if (!scene)
        return code;
    glint_scene_counts c = glint_scene_get_counts(scene);
    printf("%s: ok:", cli_scene_name(path));
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

/* An interrupted render: nothing written, or with --partial its finished
 * tiles. Either way the exit code says it was interrupted. */
static int interrupted_run(const cli_options *o, const glint_image *image, const glint_render_stats *stats,
                           const cli_run *r)
{
    if (!o->partial)
        return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: nothing written");
    glint_error err = {0};
    glint_status st = cli_write_image(r, image, &err);
    if (st)
        return cli_complain(cli_exit_code_of(st), "interrupted, and the finished tiles were not written: %s", err.message);
    return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: %d of %d tiles finished, written to %s (the rest black)",
                        stats->tiles_done, stats->tiles_total, r->dest.shown);
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
    return st ? cli_complain(cli_exit_code_of(st), "%s", err.message) : CLI_EXIT_OK;
}

static int run(const cli_options *o)
{
    /* Image bytes on a terminal are a mistake, found before the work. */
    if (o->output && strcmp(o->output, "-") == 0 && isatty(STDOUT_FILENO))
        return cli_complain(CLI_EXIT_USAGE, "will not write a%s %s image to a terminal; redirect stdout or give -o FILE",
                            o->format && strchr("AEIOU", o->format->name[0]) ? "n" : "",
                            o->format ? o->format->name : "PNG");
    cli_run r;
    int code = cli_prepare(o, true, &r);
    if (code >= 0)
        return code;
    if (o->print_scene)
        return print_scene(r.scene, o->output);

    /* From here on a signal cancels the render (its BVH build included),
     * which then writes nothing, or with --partial its finished tiles. */
    rendering = 1;
    cli_progress prog = {.last_print = -1};
    clock_gettime(CLOCK_MONOTONIC, &prog.start);
    glint_render_options ro = {.threads = o->threads > 0 ? (int)o->threads : 0,
                               .cancel = (const volatile int *)&interrupted, .keep_partial = o->partial};
    if (!o->quiet && isatty(STDERR_FILENO)) {
        ro.progress = cli_show_progress;
        ro.progress_user = &prog;
    }
    glint_image image;
    glint_render_stats stats;
    glint_error err = {0};
    glint_status st = glint_render(r.scene, &ro, &image, &stats, &err);
    if (ro.progress && st == GLINT_ERR_CANCELLED)
        fputs("\r\033[K", stderr); /* the progress line stopped short */
    if (st == GLINT_ERR_CANCELLED) {
        code = interrupted_run(o, &image, &stats, &r);
        glint_image_free(&image);
        glint_scene_free(r.scene);
        return code;
    }
    if (!st)
        st = cli_write_image(&r, &image, &err);
    glint_image_free(&image);
    if (st) {
        glint_scene_free(r.scene);
        return cli_complain(cli_exit_code_of(st), "%s", err.message);
    }
    cli_warn_nan(stats.nan_samples);
    if (!o->quiet) {
        const glint_settings *settings = &r.settings;
        long threads = o->threads > 0 ? (long)o->threads : sysconf(_SC_NPROCESSORS_ONLN);
        fprintf(stderr, "glint: %dx%d, %d spp, %ld thread%s: %.3f s, %llu samples, %llu rays, %.1f Mrays/s -> %s\n",
                settings->width, settings->height, settings->samples_per_pixel, threads, threads == 1 ? "" : "s",
                stats.seconds, (unsigned long long)stats.samples, (unsigned long long)stats.rays,
                stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, r.dest.shown);
    }
    glint_scene_free(r.scene); /* last: output may point into it */
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
