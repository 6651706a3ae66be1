/* args.h - the glint command's arguments: its exit codes, the options its
 * flags set and the parser that reads them (apart from main.c so that the
 * parser can be fuzzed, tests/fuzz/fuzz_cli.c). */
#ifndef GLINT_CLI_ARGS_H
#define GLINT_CLI_ARGS_H

#include <stdbool.h>
#include <stdio.h>
#include "glint.h"

/* What the glint command's exit status means (glint --help lists them). */
enum cli_exit_code {
    CLI_EXIT_OK = 0,
    CLI_EXIT_BAD_INPUT = 1,   /* a scene or texture that cannot be used */
    CLI_EXIT_USAGE = 2,       /* flags that do not parse */
    CLI_EXIT_IO = 3,          /* the output, or a report on stdout or stderr, cannot be written */
    CLI_EXIT_INTERRUPTED = 4, /* SIGINT, SIGTERM, SIGHUP or SIGQUIT */
    CLI_EXIT_INTERNAL = 5     /* out of memory, Embree failure */
};

/* The most --texture NAME=FILE flags one command line may give. */
#define CLI_MAX_TEXTURE_SWAPS 16

/* What the command line asks for. The numbers are -1 where the scene's own
 * setting stands, else within their flag's range (glint --help). Its
 * strings point into argv or into the options themselves, so they must not
 * outlive argv nor the options be copied. */
typedef struct cli_options {
    const char *scene;          /* NULL: the built-in seed room; "-": standard input */
    const char *const *scenes;  /* all the scene files named, scenes[0] == scene: several only with --check */
    int scene_count;
    const char *output;         /* NULL: the scene's, else glint.png; "-": standard output */
    const glint_image_format *format; /* --format: NULL, else the output's format (PNG on standard output) */
    bool check;
    bool print_scene;           /* write the scene as YAML on stdout instead of rendering */
    long long width, height, spp, depth, threads, seed; /* -1: the scene's own */
    int sampler;                                        /* -1: the scene's own, else a glint_sampler */
    int filter;                                         /* -1: the scene's own, else a glint_filter */
    int exr_pixel;                                      /* -1: not given, else a glint_exr_pixel */
    int bit_depth;                                      /* -1: not given, 0: 8 bits, 1: 16 bits */
    int view;                                           /* -1: not given, else a glint_model_view */
    bool exposure_given;
    double exposure;                                    /* --exposure, in stops, when given */
    long long frame_first, frame_last; /* --frame, --frames: -1, the scene's own frames */
    bool resume;                /* skip the frames whose files are there, complete */
    bool quiet;
    bool partial;
    bool display;               /* show the image in a window as it renders (display.h) */
    const char *swap_name[CLI_MAX_TEXTURE_SWAPS], *swap_path[CLI_MAX_TEXTURE_SWAPS];
    char swap_buf[CLI_MAX_TEXTURE_SWAPS][256];
    int swaps;
} cli_options;

/* Prints "glint: ", the message formatted from fmt and a newline on the
 * thread's messages (cli_messages: stderr unless sent elsewhere), and
 * returns code, so that a caller can return both at once. */
int cli_complain(int code, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Where the calling thread's messages about the run go: stderr, or the
 * stream cli_send_messages gave. */
FILE *cli_messages(void);

/* Sends the calling thread's messages to `to` (NULL: stderr again): a
 * glint-mpi worker keeps its load's, which it shows only when the failure
 * was its own and not rank 0's (rank 0 says its own). */
void cli_send_messages(FILE *to);

/* Fills all of *o from the argc arguments in argv (argv[0] the program's
 * name, skipped), moving the scene files named to argv[1] on, in their
 * order, as GNU's getopt does (o->scenes points there). Returns -1 to go on and render or check, or the code to
 * exit with at once: CLI_EXIT_OK after printing the help or the version on
 * stdout, CLI_EXIT_USAGE after printing why the flags do not parse on
 * stderr (cli_complain). */
int cli_parse_args(int argc, char **argv, cli_options *o);

#endif
