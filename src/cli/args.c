/* args.c - the glint command's flags: the help text, the tables of number
 * flags with their ranges and of word flags with their words, and the parser
 * that fills cli_options, printing why a command line does not parse. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "cli/args.h"
#include "cli/report_flush.h"
#include "core/word_list.h"
#include "scene/scene.h"

static const char USAGE[] =
    "usage: glint [SCENE.yaml | MODEL | -] [options]\n"
    "       glint --check SCENE.yaml...\n"
    "Renders a scene file (docs/scene-format.md; '-' reads it from standard input), a\n"
    "model file (.obj, .ply, .stl, .gltf, .glb: framed on a floor, lit), or without\n"
    "either the built-in seed room (the COSC363 scene), to an image. Flags override\n"
    "the file's settings.\n"
    "\n"
    "options:\n"
    "  -o, --output FILE      image to write, in the format its extension names (below;\n"
    "                         default: the scene's output setting, else glint.png);\n"
    "                         '-' is standard output (not a terminal)\n"
    "      --format png|ppm|exr\n"
    "                         format of standard output (default png), or of the\n"
    "                         default glint.png; a file's extension must agree\n"
    "      --exr-pixel TYPE   pixel type of .exr output: half (16-bit float, the default;\n"
    "                         values of 65520 and more become infinity) or float (32-bit)\n"
    "      --bit-depth 8|16   bits a channel of .png and .ppm output (default 8); 16\n"
    "                         keeps smooth gradients and faint noise that 8 rounds away\n"
    "      --check            validate each scene file given (several may be), report\n"
    "                         every problem, render nothing (exit 0: all valid)\n"
    "      --print-scene      write the scene glint would render, the flags applied, as a\n"
    "                         scene file on stdout, and render nothing\n"
    "      --view NAME        where a model file is seen from: auto (the default: the\n"
    "                         front, or a room open on one side through its opening),\n"
    "                         front, back, left, right, top, or iso (from +x +y +z)\n"
    "  -w, --width N          image width in pixels, 1..65536\n"
    "  -h, --height N         image height in pixels, 1..65536; at most 16384 x 16384\n"
    "                         pixels in all\n"
    "      --spp N            samples per pixel, 1..4096; a square number for the\n"
    "                         regular and jittered samplers\n"
    "      --sampler NAME     regular (an N x N grid), jittered (one random point in\n"
    "                         each cell of the grid) or sobol (scrambled Sobol\n"
    "                         points, any count)\n"
    "      --filter NAME      pixel filter, at its own radius: box, tent, gaussian,\n"
    "                         mitchell or lanczos\n"
    "      --seed N           seed of every random choice, 0..4294967295\n"
    "      --depth N          reflection and refraction recursion limit, 0..64\n"
    "                         (defaults: seed room 1000 x 1000, scene file 640 x 480,\n"
    "                         model 800 x 600; 4 samples, regular, depth 5)\n"
    "      --exposure STOPS   brighten (or, below 0, darken) the image by 2^STOPS,\n"
    "                         -64..64, as the scene's exposure setting\n"
    "      --threads N        render threads, 0..1024 (0, the default: one per core);\n"
    "                         the image is the same for any count\n"
    "      --texture NAME=FILE\n"
    "                         replace the image of the scene's texture NAME (the seed\n"
    "                         room's is 'moon') with a PNG or JPEG file\n"
    "      --frame N          render frame N of an animated scene (docs/animation.md)\n"
    "      --frames A-B       render frames A to B, each to the output's name with its\n"
    "                         #s replaced by the frame's number (-o out-####.png)\n"
    "                         (default: the scene's frames, else frame 0)\n"
    "      --resume           skip the frames whose image files are there and whole\n"
    "      --partial          when interrupted, write the finished tiles (the rest\n"
    "                         black) instead of nothing, and still exit 4\n"
    "      --display          show the image in a window as it renders, and keep it\n"
    "                         there until closed (Esc, q); s saves it (to the output\n"
    "                         file, or glint.png); closing it early interrupts (exit 4)\n"
    "  -q, --quiet            no progress line and no summary on stderr\n"
    "  -h, --help             show this help and exit (-h alone, with no number)\n"
    "      --version          print the version and exit\n"
    "Long options take their value as the next argument or after '=': --width=320.\n";

/* The help's end, after the list of image formats. */
static const char USAGE_END[] =
    "\n"
    "Exit codes: 0 success, 1 bad input (scene file, texture), 2 bad usage, 3 the output\n"
    "(or a report: this help, --check) cannot be written, 4 interrupted (SIGINT,\n"
    "SIGTERM, SIGHUP, SIGQUIT), 5 internal failure (out of memory, Embree). An interrupted render stops within a moment and writes nothing\n"
    "unless --partial. The image is written under a temporary name and renamed into\n"
    "place, so a failed or interrupted run never leaves a half-written file or destroys\n"
    "an existing one; standard output gets the whole image in one pass.\n";

/* The help: the flags, the image formats as the library lists them, and
 * the exit codes. */
static void print_help(void)
{
    /* Line by line, each written out: the help is longer than stdout's
     * buffer (cli_flush_report). */
    for (const char *line = USAGE, *end; *line; line = end) {
        end = strchr(line, '\n');
        end = end ? end + 1 : line + strlen(line);
        fwrite(line, 1, (size_t)(end - line), stdout);
        cli_flush_report();
    }
    puts("\nImage formats, by the output's extension in any case:");
    const glint_image_format *f;
    for (int i = 0; (f = glint_image_format_at(i)) != NULL; i++) {
        printf(" ");
        for (const char *const *ext = f->extensions; *ext; ext++)
            printf(" %s", *ext);
        printf("  %s: %s\n", f->name, f->meaning);
    }
    fputs(USAGE_END, stdout);
}

static _Thread_local FILE *messages;

FILE *cli_messages(void)
{
    return messages ? messages : stderr;
}

void cli_send_messages(FILE *to)
{
    messages = to;
}

int cli_complain(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    FILE *to = cli_messages();
    fputs("glint: ", to);
    vfprintf(to, fmt, ap);
    fputc('\n', to);
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

/* A flag that takes a whole number: one that sets a scene setting takes
 * the setting's range and rule from its parameter table, so the flag and
 * the scene file accept the same values. */
typedef struct number_flag {
    const char *long_name, *short_name;
    size_t field;                 /* offset of the long long in cli_options */
    const char *setting;          /* the settings key it overrides, or NULL */
    long long lo, hi;             /* without a setting: the range */
} number_flag;

static const number_flag NUMBER_FLAGS[] = {
    {"--width", "-w", offsetof(cli_options, width), "width", 0, 0},
    {"--height", "-h", offsetof(cli_options, height), "height", 0, 0},
    {"--spp", NULL, offsetof(cli_options, spp), "samples", 0, 0},
    {"--depth", NULL, offsetof(cli_options, depth), "depth", 0, 0},
    {"--threads", NULL, offsetof(cli_options, threads), NULL, 0, 1024},
    {"--seed", NULL, offsetof(cli_options, seed), "seed", 0, 0},
};

/* Parses the value v of flag nf into *out; false, with the wording of what
 * it needs in `what`, when v is not such a number. */
static bool parse_number_flag(const number_flag *nf, const char *v, long long *out, char *what, size_t size)
{
    const param *p = nf->setting ? params_find(settings_params(), nf->setting) : NULL;
    long long lo = p ? (long long)p->lo : nf->lo, hi = p ? (long long)p->hi : nf->hi;
    if (p && p->rule_text)
        snprintf(what, size, "%s", p->rule_text);
    else
        snprintf(what, size, "a whole number from %lld to %lld", lo, hi);
    return parse_int(v, lo, hi, out) && (!p || param_in_range(p, (double)*out));
}

/* --exposure: a number of stops in the setting's range. */
static int parse_exposure(cli_options *o, const char *v)
{
    const param *p = params_find(settings_params(), "exposure");
    char *end;
    errno = 0;
    double stops = strtod(v, &end);
    if (errno || end == v || *end != '\0' || !param_in_range(p, stops))
        return cli_complain(CLI_EXIT_USAGE, "--exposure needs a number of stops from %g to %g, got '%s'", p->lo, p->hi,
                            v);
    o->exposure = stops;
    o->exposure_given = true;
    return 0;
}

/* A flag whose value is one of a few words, each setting the flag's field
 * to its index, the enum's value: one that overrides a scene setting takes
 * the setting's words from its parameter table, so the flag and the scene
 * file accept the same words. */
typedef struct word_flag {
    const char *name;
    size_t field;                 /* offset of the int in cli_options */
    const char *setting;          /* the settings key it overrides, or NULL */
    const char *const *words;     /* without a setting: the words, in the enum's order */
    int word_count;
    param_table (*table)(void);   /* the setting's table: NULL for settings_params */
} word_flag;

static const char *const EXR_PIXELS[] = {"half", "float"}; /* glint_exr_pixel's order */
static const char *const BIT_DEPTHS[] = {"8", "16"};
static const char *const VIEWS[] = {"auto", "front", "back", "left", "right", "top", "iso"}; /* glint_model_view's */

static const word_flag WORD_FLAGS[] = {
    {"--sampler", offsetof(cli_options, sampler), "sampler", NULL, 0, NULL},
    {"--filter", offsetof(cli_options, filter), "type", NULL, 0, filter_params},
    {"--exr-pixel", offsetof(cli_options, exr_pixel), NULL, EXR_PIXELS, 2, NULL},
    {"--bit-depth", offsetof(cli_options, bit_depth), NULL, BIT_DEPTHS, 2, NULL},
    {"--view", offsetof(cli_options, view), NULL, VIEWS, 7, NULL},
};

/* Sets wf's field to the index of the word v; false, with the words
 * quoted in `what` ("'half' or 'float'"), when v is none of them (even
 * after an earlier good value). */
static bool parse_word_flag(const word_flag *wf, const char *v, int *field, char *what, size_t size)
{
    const param *p = wf->setting ? params_find(wf->table ? wf->table() : settings_params(), wf->setting) : NULL;
    const char *const *words = p ? p->words : wf->words;
    int count = p ? p->word_count : wf->word_count, found = -1;
    what[0] = '\0';
    for (int k = 0; k < count; k++) {
        char quoted[64];
        snprintf(quoted, sizeof quoted, "'%s'", words[k]);
        word_list_append(what, size, quoted, k, count);
        if (strcmp(v, words[k]) == 0)
            found = k;
    }
    if (found >= 0)
        *field = found;
    return found >= 0;
}

static int parse_texture_swap(cli_options *o, const char *arg)
{
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg || eq[1] == '\0' || (size_t)(eq - arg) >= sizeof o->swap_buf[0])
        return cli_complain(CLI_EXIT_USAGE, "--texture needs NAME=FILE, got '%s'", arg);
    if (o->swaps == CLI_MAX_TEXTURE_SWAPS)
        return cli_complain(CLI_EXIT_USAGE, "--texture may be given at most %d times", CLI_MAX_TEXTURE_SWAPS);
    memcpy(o->swap_buf[o->swaps], arg, (size_t)(eq - arg));
    o->swap_buf[o->swaps][eq - arg] = '\0';
    o->swap_name[o->swaps] = o->swap_buf[o->swaps];
    o->swap_path[o->swaps] = eq + 1;
    o->swaps++;
    return 0;
}

/* Sets o->format to the format named v; the formats' first extensions are
 * the words (--format png). */
static int parse_format(cli_options *o, const char *v)
{
    o->format = glint_image_format_named(v);
    if (o->format)
        return 0;
    int count = 0;
    while (glint_image_format_at(count))
        count++;
    char words[160] = "";
    for (int i = 0; i < count; i++) {
        char quoted[40];
        snprintf(quoted, sizeof quoted, "'%s'", glint_image_format_at(i)->extensions[0] + 1);
        word_list_append(words, sizeof words, quoted, i, count);
    }
    return cli_complain(CLI_EXIT_USAGE, "--format needs %s, got '%s'", words, v);
}

/* --frame N and --frames A-B: frames numbered as settings.frames's. */
static int parse_frames(cli_options *o, const char *flag, const char *v)
{
    const param *p = params_find(frames_params(), "end");
    long long lo = (long long)p->lo, hi = (long long)p->hi, first, last;
    char copy[48];
    const char *dash = strchr(v, '-');
    bool range = strcmp(flag, "--frames") == 0;
    if (!range && parse_int(v, lo, hi, &first)) {
        o->frame_first = o->frame_last = first;
        return 0;
    }
    if (range && dash && (size_t)(dash - v) < sizeof copy) {
        memcpy(copy, v, (size_t)(dash - v));
        copy[dash - v] = '\0';
        if (parse_int(copy, lo, hi, &first) && parse_int(dash + 1, lo, hi, &last) && last >= first) {
            o->frame_first = first;
            o->frame_last = last;
            return 0;
        }
    }
    return range ? cli_complain(CLI_EXIT_USAGE, "--frames needs FIRST-LAST, frames from %lld to %lld with LAST at "
                                                "least FIRST, got '%s'", lo, hi, v)
                 : cli_complain(CLI_EXIT_USAGE, "--frame needs a whole number from %lld to %lld, got '%s'", lo, hi, v);
}

/* Whether a is a flag that takes no value. */
static bool is_switch(const char *a)
{
    static const char *const SWITCHES[] = {"--help", "--version", "-q", "--quiet", "--check", "--partial",
                                             "--print-scene", "--display", "--resume"};
    for (size_t k = 0; k < sizeof SWITCHES / sizeof SWITCHES[0]; k++)
        if (strcmp(a, SWITCHES[k]) == 0)
            return true;
    return false;
}

int cli_parse_args(int argc, char **argv, cli_options *o)
{
    *o = (cli_options){.width = -1, .height = -1, .spp = -1, .depth = -1,
                       .threads = -1, .seed = -1, .sampler = -1, .filter = -1, .exr_pixel = -1, .bit_depth = -1,
                       .view = -1, .frame_first = -1, .frame_last = -1};
    /* The scene files move to argv[1] on: no slot is written before it is read. */
    int files = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        /* GNU's --name=value is --name value: split, into a copy of the name. */
        char name[32];
        const char *attached = NULL, *eq = strchr(a, '=');
        if (a[0] == '-' && a[1] == '-' && eq) {
            if ((size_t)(eq - a) >= sizeof name)
                return cli_complain(CLI_EXIT_USAGE, "unknown option '%.*s' (try 'glint --help')", (int)(eq - a), a);
            memcpy(name, a, (size_t)(eq - a));
            name[eq - a] = '\0';
            a = name;
            attached = eq + 1;
        }
        if (attached && is_switch(a))
            return cli_complain(CLI_EXIT_USAGE, "option '%s' takes no value, got '%s'", a, attached);
        /* -h is the height's short flag; alone at the end it asks for help,
         * as it does in most programs. */
        if (strcmp(a, "--help") == 0 || (strcmp(a, "-h") == 0 && i + 1 == argc)) {
            print_help();
            return CLI_EXIT_OK;
        }
        if (strcmp(a, "--version") == 0) {
            printf("glint %s\n", glint_version());
            return CLI_EXIT_OK;
        }
        if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
            o->quiet = true;
            continue;
        }
        if (strcmp(a, "--check") == 0) {
            o->check = true;
            continue;
        }
        if (strcmp(a, "--print-scene") == 0) {
            o->print_scene = true;
            continue;
        }
        if (strcmp(a, "--partial") == 0) {
            o->partial = true;
            continue;
        }
        if (strcmp(a, "--display") == 0) {
            o->display = true;
            continue;
        }
        if (strcmp(a, "--resume") == 0) {
            o->resume = true;
            continue;
        }
        if (a[0] != '-' || a[1] == '\0') {
            for (int k = 0; k < files; k++)
                if (strcmp(a, "-") == 0 && strcmp(argv[1 + k], "-") == 0)
                    return cli_complain(CLI_EXIT_USAGE, "'-' (standard input) can be read only once");
            argv[1 + files++] = argv[i];
            continue;
        }
        const number_flag *nf = NULL;
        for (size_t k = 0; k < sizeof NUMBER_FLAGS / sizeof NUMBER_FLAGS[0]; k++)
            if (strcmp(a, NUMBER_FLAGS[k].long_name) == 0 ||
                (NUMBER_FLAGS[k].short_name && strcmp(a, NUMBER_FLAGS[k].short_name) == 0))
                nf = &NUMBER_FLAGS[k];
        const word_flag *wf = NULL;
        for (size_t k = 0; k < sizeof WORD_FLAGS / sizeof WORD_FLAGS[0]; k++)
            if (strcmp(a, WORD_FLAGS[k].name) == 0)
                wf = &WORD_FLAGS[k];
        bool takes_value = nf || wf || strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0 ||
                           strcmp(a, "--texture") == 0 || strcmp(a, "--format") == 0 || strcmp(a, "--exposure") == 0 ||
                           strcmp(a, "--frame") == 0 || strcmp(a, "--frames") == 0;
        if (!takes_value)
            return cli_complain(CLI_EXIT_USAGE, "unknown option '%s' (try 'glint --help')", a);
        if (!attached && i + 1 >= argc)
            return cli_complain(CLI_EXIT_USAGE, "option '%s' needs a value", a);
        const char *v = attached ? attached : argv[++i];
        if (nf) {
            long long *field = (long long *)((char *)o + nf->field);
            char what[96];
            if (!parse_number_flag(nf, v, field, what, sizeof what))
                return cli_complain(CLI_EXIT_USAGE, "%s needs %s, got '%s'", nf->long_name, what, v);
        } else if (wf) {
            char what[160];
            if (!parse_word_flag(wf, v, (int *)((char *)o + wf->field), what, sizeof what))
                return cli_complain(CLI_EXIT_USAGE, "%s needs %s, got '%s'", wf->name, what, v);
        } else if (strcmp(a, "--frame") == 0 || strcmp(a, "--frames") == 0) {
            int code = parse_frames(o, a, v);
            if (code)
                return code;
        } else if (strcmp(a, "--texture") == 0 || strcmp(a, "--format") == 0 || strcmp(a, "--exposure") == 0) {
            int code = strcmp(a, "--texture") == 0  ? parse_texture_swap(o, v)
                       : strcmp(a, "--format") == 0 ? parse_format(o, v)
                                                    : parse_exposure(o, v);
            if (code)
                return code;
        } else {
            if (v[0] == '\0')
                return cli_complain(CLI_EXIT_USAGE, "%s needs a file name", a);
            /* "-o -q" is a forgotten name far more often than a file called -q. */
            if (v[0] == '-' && v[1] != '\0')
                return cli_complain(CLI_EXIT_USAGE, "%s needs a file name, got '%s' (write ./%s for a file of that name)",
                                    a, v, v);
            o->output = v;
        }
    }
    o->scenes = (const char *const *)argv + 1;
    o->scene_count = files;
    o->scene = files > 0 ? argv[1] : NULL;
    if (o->check && !o->scene)
        return cli_complain(CLI_EXIT_USAGE, "--check needs a scene file");
    if (files > 1 && !o->check)
        return cli_complain(CLI_EXIT_USAGE, "unexpected argument '%s': one scene file at a time, unless --check",
                            argv[2]);
    if (o->check && o->print_scene)
        return cli_complain(CLI_EXIT_USAGE, "--check and --print-scene do not go together: choose one");
    if (o->display && (o->check || o->print_scene))
        return cli_complain(CLI_EXIT_USAGE, "--display shows a render, and %s renders nothing",
                            o->check ? "--check" : "--print-scene");
    if (o->display && o->frame_last > o->frame_first)
        return cli_complain(CLI_EXIT_USAGE, "--display shows one frame: give --frame N");
    if (o->view >= 0 && !o->scene)
        return cli_complain(CLI_EXIT_USAGE, "--view needs a model file");
    if (o->view >= 0 && !glint_is_model_path(o->scene))
        return cli_complain(CLI_EXIT_USAGE, "--view is for model files, and '%s' is a scene file", o->scene);
    return -1;
}
