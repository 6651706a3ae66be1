/* main.c - the glint command: reads its flags (args.c), renders the scene
 * (a file, standard input) or the built-in seed room through the public
 * API, shows progress (and with --display the image, display.c) and writes
 * the image to a file or standard output; or checks scene files. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "glint.h"
#include "cli/args.h"
#include "cli/display.h"
#include "cli/frames.h"
#include "cli/reports.h"
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

/* Renders the run's scene to its destination, as frame `frame` of f when
 * f has several (said in the progress line and the summary); the exit
 * code. */
static int render_one(const cli_options *o, cli_run *r, display *window, const cli_frames *f, int frame)
{
    /* From here on a signal cancels the render (its BVH build included),
     * which then writes nothing, or with --partial its finished tiles. */
    rendering = 1;
    cli_progress prog = {.last_print = -1, .frame = frame, .frames = f->last - f->first + 1,
                         .frames_done = frame - f->first};
    clock_gettime(CLOCK_MONOTONIC, &prog.start);
    glint_render_options ro = {.threads = o->threads > 0 ? (int)o->threads : 0,
                               .cancel = (const volatile int *)&interrupted, .keep_partial = o->partial};
    if (!o->quiet && isatty(STDERR_FILENO)) {
        ro.progress = cli_show_progress;
        ro.progress_user = &prog;
    }
    if (window) {
        ro.tile_done = display_tile;
        ro.tile_user = window;
    }
    glint_image image;
    glint_render_stats stats;
    glint_error err = {0};
    glint_status st = glint_render(r->scene, &ro, &image, &stats, &err);
    if (ro.progress && st == GLINT_ERR_CANCELLED)
        fputs("\r\033[K", stderr); /* the progress line stopped short */
    if (st == GLINT_ERR_CANCELLED) {
        int code = cli_interrupted(o, r, &image, stats.tiles_done, stats.tiles_total);
        glint_image_free(&image);
        return code;
    }
    if (!st)
        st = cli_write_image(r, &image, &err);
    glint_image_free(&image);
    if (st)
        return cli_complain(cli_exit_code_of(st), "%s", err.message);
    cli_warn_nan(stats.nan_samples);
    if (!o->quiet) {
        const glint_settings *settings = &r->settings;
        long threads = o->threads > 0 ? (long)o->threads : sysconf(_SC_NPROCESSORS_ONLN);
        char which[64] = "";
        if (f->last > f->first)
            snprintf(which, sizeof which, "frame %d (%d of %d), ", frame, frame - f->first + 1, f->last - f->first + 1);
        fprintf(stderr, "glint: %s%dx%d, %d spp, %ld thread%s: %.3f s, %llu samples, %llu rays, %.1f Mrays/s -> %s\n",
                which, settings->width, settings->height, settings->samples_per_pixel, threads, threads == 1 ? "" : "s",
                stats.seconds, (unsigned long long)stats.samples, (unsigned long long)stats.rays,
                stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, r->dest.shown);
    }
    if (window)
        display_finished(window, stats.seconds);
    return CLI_EXIT_OK;
}

/* Points the run's destination at frame `frame`'s file, named from the
 * output's pattern into path ("-" stays standard output), and checks that
 * it is none of the scene's inputs; -1 to go on, or the exit code after
 * complaining. */
static int aim_at_frame(cli_run *r, const char *pattern, int frame, char *path, size_t size)
{
    if (strcmp(pattern, "-") == 0) {
        snprintf(path, size, "-");
        return -1;
    }
    if (!cli_frame_path(pattern, frame, path, size))
        return cli_complain(CLI_EXIT_USAGE, "the output name '%s' is too long", pattern);
    r->dest.path = r->dest.shown = path;
    glint_error err = {0};
    if (glint_scene_check_output(r->scene, path, &err))
        return cli_complain(CLI_EXIT_IO, "%s", err.message);
    return -1;
}

static int run(const cli_options *o)
{
    /* Image bytes on a terminal are a mistake, found before the work. */
    if (o->output && strcmp(o->output, "-") == 0 && isatty(STDOUT_FILENO))
        return cli_complain(CLI_EXIT_USAGE, "will not write a%s %s image to a terminal; redirect stdout or give -o FILE",
                            o->format && strchr("AEIOU", o->format->name[0]) ? "n" : "",
                            o->format ? o->format->name : "PNG");
    /* The window's SDL starts while the scene loads. */
    int code;
    display *window = NULL;
    if (o->display && !(window = display_start(&interrupted, &code)))
        return code;
    /* Loaded at time 0 first: the frames and their rate are the scene's. */
    cli_run r;
    code = cli_prepare(o, true, 0, &r);
    if (code >= 0) {
        display_close(window);
        return code;
    }
    cli_frames f;
    char pattern[4096], path[4096];
    snprintf(pattern, sizeof pattern, "%s", r.dest.path); /* the path may point into the scene */
    if ((code = cli_frames_choose(o, &r.settings, pattern, &f)) >= 0) {
        display_close(window);
        glint_scene_free(r.scene);
        return code;
    }
    for (int frame = f.first; frame <= f.last; frame++) {
        double time = cli_frame_time(&f, frame);
        if (time != 0) {
            glint_scene_free(r.scene);
            r.scene = NULL;
            if ((code = cli_prepare(o, true, time, &r)) >= 0)
                break;
        }
        /* The frame moves the random patterns: its noise is its own. */
        r.settings.frame = frame;
        glint_error err = {0};
        if (glint_scene_set_settings(r.scene, &r.settings, &err)) {
            code = cli_complain(CLI_EXIT_INTERNAL, "%s", err.message);
            break;
        }
        if ((code = aim_at_frame(&r, pattern, frame, path, sizeof path)) >= 0)
            break;
        if (frame == f.first && window && !display_show(window, o, &r, &code)) {
            window = NULL; /* closed */
            break;
        }
        if (o->resume && strcmp(path, "-") != 0 && cli_frame_done(path)) {
            if (!o->quiet)
                fprintf(stderr, "glint: frame %d is done: %s\n", frame, path);
            continue;
        }
        if ((code = render_one(o, &r, window, &f, frame)) != CLI_EXIT_OK)
            break;
    }
    if (code < 0 || code == CLI_EXIT_OK) {
        code = CLI_EXIT_OK;
        /* The image is written: the window stays until the user closes it. */
        if (window)
            display_wait(window);
    } else {
        display_close(window);
    }
    glint_scene_free(r.scene); /* last: output may point into it */
    return code;
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
        return cli_reported(code);
    cli_catch_signals(on_signal);
    if (o.check)
        return cli_reported(cli_check_only(&o));
    if (o.print_scene)
        return cli_reported(cli_print_frame(&o));
    return run(&o);
}
