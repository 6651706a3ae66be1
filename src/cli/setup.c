/* setup.c - what glint (main.c) and glint-mpi (src/mpi/) share around a
 * render: loading the scene and applying the flags, choosing and checking
 * where the image goes, writing it, the progress line, and the words for
 * what went wrong. */
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "cli/setup.h"

int cli_exit_code_of(glint_status s)
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
    if (o->exposure_given) s->exposure = o->exposure;
    if (o->sampler >= 0) s->sampler = (glint_sampler)o->sampler;
    /* A filter named on the command line takes its own radius, not one
     * the scene gave another filter. */
    if (o->filter >= 0) {
        s->filter = (glint_filter)o->filter;
        s->filter_radius = 0;
    }
}


#define MAX_PROBLEMS 20

static void print_problem(void *user, const char *message)
{
    ++*(int *)user;
    fprintf(cli_messages(), "%s\n", message);
}

const char *cli_scene_name(const char *path)
{
    return strcmp(path, "-") == 0 ? "<stdin>" : path;
}

glint_scene *cli_load_scene(const cli_options *o, const char *path, double time, const char *outcome, bool warnings,
                            int *code)
{
    glint_error err = {0};
    glint_scene *scene;
    const char *name = cli_scene_name(path);
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
        glint_load_options lo = {.report = print_problem, .report_user = &problems, .max_errors = MAX_PROBLEMS,
                                 .time = time};
        scene = from_stdin ? glint_scene_load_stream(stdin, name, &lo, &err) : glint_scene_load_file(path, &lo, &err);
        if (!scene)
            cli_complain(CLI_EXIT_BAD_INPUT, "%s: %d problem%s%s; %s", name, problems, problems == 1 ? "" : "s",
                         problems >= MAX_PROBLEMS ? " (stopped at the limit)" : "", outcome);
    }
    for (int i = 0; warnings && i < glint_scene_warning_count(scene); i++)
        fprintf(stderr, "glint: warning: %s\n", glint_scene_warning(scene, i));
    *code = err.status == GLINT_ERR_NOMEM ? CLI_EXIT_INTERNAL : CLI_EXIT_BAD_INPUT;
    return scene;
}


/* Chooses where the image goes and in which format, and checks before
 * rendering that it can go there: -o, else the scene's output setting, else
 * glint.png (glint.ppm with --format ppm); a --format that disagrees with
 * the file's extension, an --exr-pixel for other formats, or a --bit-depth
 * for OpenEXR, is refused.
 * Returns -1 to go on, or the exit code after complaining. The path may
 * point into the scene. */
static int choose_destination(const cli_options *o, const glint_scene *scene, cli_destination *d)
{
    /* Also where --display's s saves an image sent to standard output. */
    snprintf(d->default_path, sizeof d->default_path, "glint%s", o->format ? o->format->extensions[0] : ".png");
    d->path = o->output ? o->output : glint_scene_get_output(scene);
    if (!d->path)
        d->path = d->default_path;
    glint_error err = {0};
    if (strcmp(d->path, "-") == 0) {
        d->format = o->format ? o->format : glint_image_format_named("png");
        d->shown = "<stdout>";
    } else {
        glint_status st = glint_image_check_path(d->path, &err);
        if (st)
            return cli_complain(st == GLINT_ERR_INVALID ? CLI_EXIT_USAGE : cli_exit_code_of(st), "%s", err.message);
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
    if (o->bit_depth >= 0 && strcmp(d->format->name, "OpenEXR") == 0)
        return strcmp(d->path, "-") != 0
                   ? cli_complain(CLI_EXIT_USAGE, "--bit-depth is for .png and .ppm output, not '%s'", d->path)
                   : cli_complain(CLI_EXIT_USAGE, "--bit-depth is for .png and .ppm output, not OpenEXR on "
                                                  "standard output");
    return -1;
}

static double seconds_since(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (t.tv_sec - t0->tv_sec) + (t.tv_nsec - t0->tv_nsec) * 1e-9;
}

void cli_show_progress(void *user, int done, int total)
{
    cli_progress *p = user;
    double elapsed = seconds_since(&p->start);
    if (done < total && elapsed - p->last_print < 0.1)
        return;
    p->last_print = elapsed;
    double left = done > 0 ? elapsed * (total - done) / done : 0;
    if (p->frames > 1) {
        /* The frames after this one, each as long as this one looks to be. */
        double frame = done > 0 ? elapsed * total / done : 0;
        left += frame * (p->frames - p->frames_done - 1);
        fprintf(stderr, "\rframe %d: %3d%%, %d of %d frames done, %.1f s left   ", p->frame,
                (int)(100.0 * done / total), p->frames_done, p->frames, left);
    } else {
        fprintf(stderr, "\r%3d%%  %.1f s elapsed, %.1f s left   ", (int)(100.0 * done / total), elapsed, left);
    }
    if (done == total)
        fputs("\r\033[K", stderr);
    fflush(stderr);
}

int cli_prepare(const cli_options *o, bool with_output, double time, cli_run *r)
{
    glint_error err = {0};
    int code = CLI_EXIT_INTERNAL;
    glint_scene *scene = o->scene ? cli_load_scene(o, o->scene, time, "nothing rendered", with_output, &code)
                                  : glint_scene_seed_room(&err);
    if (!scene)
        return o->scene ? code : cli_complain(CLI_EXIT_INTERNAL, "%s", err.message);
    if (with_output) {
        code = choose_destination(o, scene, &r->dest);
        if (code >= 0) {
            glint_scene_free(scene); /* last: the path may point into it */
            return code;
        }
    }
    glint_status st = GLINT_OK;
    r->write_options = (glint_image_write_options){.exr_pixel = o->exr_pixel >= 0 ? o->exr_pixel : GLINT_EXR_HALF,
                                                   .bit_depth = o->bit_depth == 1 ? 16 : 8};
    for (int i = 0; i < o->swaps && !st; i++)
        st = glint_scene_replace_image(scene, o->swap_name[i], o->swap_path[i], &err);
    r->settings = glint_scene_get_settings(scene);
    apply_overrides(o, &r->settings);
    if (st) {
        glint_scene_free(scene);
        /* Whatever stopped the scene, unreadable textures included, is bad input. */
        return cli_complain(st == GLINT_ERR_NOMEM ? CLI_EXIT_INTERNAL : CLI_EXIT_BAD_INPUT, "%s", err.message);
    }
    /* The scene's own settings passed when it loaded: only the flags can
     * make them fail now (an image too large in all, say). */
    if (glint_scene_set_settings(scene, &r->settings, &err)) {
        glint_scene_free(scene);
        return cli_complain(CLI_EXIT_USAGE, "%s", err.message);
    }
    /* An output over one of the run's own inputs would destroy it. */
    if (with_output && !o->print_scene && strcmp(r->dest.path, "-") != 0 &&
        glint_scene_check_output(scene, r->dest.path, &err)) {
        glint_scene_free(scene);
        return cli_complain(CLI_EXIT_IO, "%s", err.message);
    }
    r->scene = scene;
    return -1;
}

glint_status cli_write_image(const cli_run *r, const glint_image *image, glint_error *err)
{
    const cli_destination *d = &r->dest;
    return strcmp(d->path, "-") == 0
               ? glint_image_write_fd(image, STDOUT_FILENO, d->format, &r->write_options, d->shown, err)
               : glint_image_write_ex(image, d->path, &r->write_options, err);
}

int cli_interrupted(const cli_options *o, const cli_run *r, const glint_image *image, int tiles_done,
                    int tiles_total)
{
    if (!o->partial)
        return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: nothing written");
    glint_error err = {0};
    glint_status st = cli_write_image(r, image, &err);
    if (st)
        return cli_complain(cli_exit_code_of(st), "interrupted, and the finished tiles were not written: %s", err.message);
    return cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: %d of %d tiles finished, written to %s (the rest black)",
                        tiles_done, tiles_total, r->dest.shown);
}

void cli_catch_signals(void (*on_signal)(int))
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    static const int stops[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; i++)
        sigaction(stops[i], &sa, NULL);
}

void cli_warn_nan(uint64_t nan_samples)
{
    /* A warning, not a failure: the image is written, without them. */
    if (nan_samples > 0)
        fprintf(stderr, "glint: warning: %llu sample%s came out NaN (not a number) and %s left out of %s pixel%s\n",
                (unsigned long long)nan_samples, nan_samples == 1 ? "" : "s", nan_samples == 1 ? "was" : "were",
                nan_samples == 1 ? "its" : "their", nan_samples == 1 ? "" : "s");
}
