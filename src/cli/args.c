/* args.c - the glint command's flags: the help text, the table of number
 * flags and their ranges, and the parser that fills cli_options, printing
 * why a command line does not parse. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "cli/args.h"

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

int cli_complain(int code, const char *fmt, ...)
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
    size_t field;                 /* offset of the long long in cli_options */
    long long lo, hi;
    const char *what;
} number_flag;

static const number_flag NUMBER_FLAGS[] = {
    {"--width", "-w", offsetof(cli_options, width), 1, 65536, "a whole number from 1 to 65536"},
    {"--height", "-h", offsetof(cli_options, height), 1, 65536, "a whole number from 1 to 65536"},
    {"--spp", NULL, offsetof(cli_options, spp), 1, 4096, "a square number from 1 to 4096 (1, 4, 9, 16, ...)"},
    {"--depth", NULL, offsetof(cli_options, depth), 0, 64, "a whole number from 0 to 64"},
    {"--threads", NULL, offsetof(cli_options, threads), 1, 1024, "a whole number from 1 to 1024"},
    {"--seed", NULL, offsetof(cli_options, seed), 0, 4294967295LL, "a whole number from 0 to 4294967295"},
};

static bool is_square(long long n)
{
    long long r = 0;
    while ((r + 1) * (r + 1) <= n)
        r++;
    return r * r == n;
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

int cli_parse_args(int argc, char **argv, cli_options *o)
{
    *o = (cli_options){.width = -1, .height = -1, .spp = -1, .depth = -1,
                       .threads = -1, .seed = -1, .sampler = -1};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0) {
            fputs(USAGE, stdout);
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
        if (strcmp(a, "--partial") == 0) {
            o->partial = true;
            continue;
        }
        if (a[0] != '-' || a[1] == '\0') {
            if (o->scene)
                return cli_complain(CLI_EXIT_USAGE, "unexpected argument '%s': one scene file at a time (try 'glint --help')", a);
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
            return cli_complain(CLI_EXIT_USAGE, "unknown option '%s' (try 'glint --help')", a);
        if (i + 1 >= argc)
            return cli_complain(CLI_EXIT_USAGE, "option '%s' needs a value", a);
        const char *v = argv[++i];
        if (nf) {
            long long *field = (long long *)((char *)o + nf->field);
            if (!parse_int(v, nf->lo, nf->hi, field) || (field == &o->spp && !is_square(*field)))
                return cli_complain(CLI_EXIT_USAGE, "%s needs %s, got '%s'", nf->long_name, nf->what, v);
        } else if (strcmp(a, "--sampler") == 0) {
            if (strcmp(v, "regular") == 0)
                o->sampler = GLINT_SAMPLER_REGULAR;
            else if (strcmp(v, "jittered") == 0)
                o->sampler = GLINT_SAMPLER_JITTERED;
            else
                return cli_complain(CLI_EXIT_USAGE, "--sampler needs 'regular' or 'jittered', got '%s'", v);
        } else if (strcmp(a, "--texture") == 0) {
            int code = parse_texture_swap(o, v);
            if (code)
                return code;
        } else {
            if (v[0] == '\0')
                return cli_complain(CLI_EXIT_USAGE, "%s needs a file name", a);
            o->output = v;
        }
    }
    if (o->check && !o->scene)
        return cli_complain(CLI_EXIT_USAGE, "--check needs a scene file");
    return -1;
}
