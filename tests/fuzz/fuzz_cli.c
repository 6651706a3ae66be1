/* fuzz_cli.c - libFuzzer target for the glint command's flags: the input,
 * split at its NUL bytes, is a command line (argv[0] "glint", at most
 * MAX_ARGS arguments after it; a final argument needs no NUL after it) for
 * cli_parse_args, whose promises are checked: it returns -1 (go on), 0
 * (only for --help, --version or a last -h) or 2 (usage), and when it goes on, every
 * number is -1 or within its flag's range (the ranges glint --help gives;
 * a sample count need not be square, which the settings check with the
 * sampler), the sampler, the filter, the OpenEXR pixel type, the image format and the model
 * view known ones, a view only with a model file, --print-scene only when
 * given and never with --check, every string one the command line holds,
 * and the scene files those arguments that are not flags nor their
 * values, in order, "-" at most once, several only with --check.
 * A broken promise aborts, which libFuzzer counts as a crash. The help,
 * the version and the complaints are printed as glint prints them: run it
 * with -close_fd_mask=3 (tests/fuzz/README.md). */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "cli/args.h"

#define MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Whether v is -1 (not given) or in [lo, hi]. */
static bool unset_or_in(long long v, long long lo, long long hi)
{
    return v == -1 || (v >= lo && v <= hi);
}

/* Whether v is a flag's value as the parser takes it: a whole argument, or
 * the part after the first '=' of a long option's argument (--name=value). */
static bool is_value(const char *v, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *eq = strchr(argv[i], '=');
        if (v == argv[i] || (argv[i][0] == '-' && argv[i][1] == '-' && eq && v == eq + 1))
            return true;
    }
    return false;
}

/* Whether some argument is exactly s. */
static bool has_argument(const char *s, int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], s) == 0)
            return true;
    return false;
}

/* Whether the scene files are arguments as given, in their order, none a
 * flag ("-" is stdin, at most once), several only with --check, and scene
 * the first. */
static bool scenes_ok(const cli_options *o, int argc, char **argv)
{
    if (o->scene_count < 0 || o->scene_count > argc - 1 || (o->scene_count > 1 && !o->check) ||
        o->scene != (o->scene_count > 0 ? o->scenes[0] : NULL))
        return false;
    int stdin_count = 0, at = 0;
    for (int k = 0; k < o->scene_count; k++) {
        const char *f = o->scenes[k];
        while (++at < argc && argv[at] != f)
            ;
        if (at >= argc || (f[0] == '-' && f[1] != '\0'))
            return false;
        stdin_count += strcmp(f, "-") == 0;
    }
    return stdin_count <= 1;
}

/* Whether format is NULL or one of the library's formats. */
static bool known_format(const glint_image_format *format)
{
    for (int i = 0; format && glint_image_format_at(i); i++)
        if (glint_image_format_at(i) == format)
            return true;
    return format == NULL;
}

static void check_options(const cli_options *o, int argc, char **argv)
{
    if (!unset_or_in(o->width, 1, 65536) || !unset_or_in(o->height, 1, 65536) ||
        !unset_or_in(o->spp, 1, 4096) ||
        !unset_or_in(o->depth, 0, 64) || !unset_or_in(o->threads, 0, 1024) ||
        !unset_or_in(o->seed, 0, 4294967295LL))
        abort();
    if (!unset_or_in(o->sampler, GLINT_SAMPLER_REGULAR, GLINT_SAMPLER_SOBOL) ||
        !unset_or_in(o->filter, GLINT_FILTER_BOX, GLINT_FILTER_LANCZOS))
        abort();
    if (o->exr_pixel != -1 && o->exr_pixel != GLINT_EXR_HALF && o->exr_pixel != GLINT_EXR_FLOAT)
        abort();
    if (!unset_or_in(o->bit_depth, 0, 1))
        abort();
    if (o->view != -1 && (o->view < GLINT_VIEW_AUTO || o->view > GLINT_VIEW_ISO || !o->scene ||
                          !glint_is_model_path(o->scene)))
        abort();
    if (!scenes_ok(o, argc, argv) || !known_format(o->format))
        abort();
    if (o->check && !o->scene)
        abort();
    if (o->print_scene && (o->check || !has_argument("--print-scene", argc, argv)))
        abort();
    if (o->output && (!is_value(o->output, argc, argv) || o->output[0] == '\0' ||
                      (o->output[0] == '-' && o->output[1] != '\0')))
        abort();
    if (o->swaps < 0 || o->swaps > CLI_MAX_TEXTURE_SWAPS)
        abort();
    for (int i = 0; i < o->swaps; i++) {
        const char *name = o->swap_name[i], *path = o->swap_path[i];
        size_t len = strlen(name);
        /* The name is what came before the first '=' of an argument, and
         * the file all after it. */
        if (len == 0 || len >= sizeof o->swap_buf[i] || strchr(name, '=') || path[0] == '\0' ||
            !is_value(path - len - 1, argc, argv) || path[-1] != '=' || memcmp(path - len - 1, name, len) != 0)
            abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    char *argv[MAX_ARGS + 2] = {"glint"};
    int argc = 1;
    for (size_t at = 0; at < size && argc <= MAX_ARGS; at += strlen(text + at) + 1)
        argv[argc++] = text + at;
    argv[argc] = NULL;

    /* The parser moves the scene files to the front of its argv: the
     * promises are checked against the arguments as given. */
    char *given[MAX_ARGS + 2];
    memcpy(given, argv, sizeof argv);
    cli_options o;
    /* Garbage first, so that a field the parser forgets to set shows. */
    memset(&o, 0xa5, sizeof o);
    int code = cli_parse_args(argc, argv, &o);
    if (code == -1)
        check_options(&o, argc, given);
    else if (code == CLI_EXIT_OK) {
        /* -h alone, the last argument, asks for the help too. */
        bool help_last = argc > 1 && strcmp(given[argc - 1], "-h") == 0;
        if (!has_argument("--help", argc, given) && !has_argument("--version", argc, given) && !help_last)
            abort();
    } else if (code != CLI_EXIT_USAGE)
        abort();
    free(text);
    return 0;
}
