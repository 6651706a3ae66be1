/* main.c - the glint-mpi command: glint's flags (src/cli/args.c), read by
 * every rank; the scene loaded by rank 0, reporting its problems alone,
 * and by the others from the files it sends (load_everywhere.c); the
 * image rendered across the ranks (glint_mpi_render) and written by rank 0
 * alone, as glint writes it, and with --display shown by rank 0
 * (src/cli/display.c); signals handled as glint handles them; and one exit
 * code for every rank. --check and --print-scene are rank 0's alone. */
#include <fcntl.h>
#include <mpi.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/args.h"
#include "cli/display.h"
#include "cli/frames.h"
#include "cli/reports.h"
#include "cli/setup.h"
#include "core/error.h"
#include "mpi/agree.h"
#include "mpi/load_everywhere.h"
#include "mpi/render_across.h"
#include "mpi/same_build.h"
#include "mpi/sequence.h"

/* Runs parse with stdout and stderr sent nowhere: the other ranks read the
 * same flags as rank 0, which alone prints the help or their faults. */
static int parse_silently(int argc, char **argv, cli_options *o)
{
    fflush(stdout);
    fflush(stderr);
    int out = dup(STDOUT_FILENO), err = dup(STDERR_FILENO), null = open("/dev/null", O_WRONLY);
    if (out >= 0 && err >= 0 && null >= 0) {
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
    }
    int code = cli_parse_args(argc, argv, o);
    fflush(stdout);
    fflush(stderr);
    if (out >= 0 && err >= 0 && null >= 0) {
        dup2(out, STDOUT_FILENO);
        dup2(err, STDERR_FILENO);
    }
    if (out >= 0)
        close(out);
    if (err >= 0)
        close(err);
    if (null >= 0)
        close(null);
    return code;
}

/* The render's cancel flag (sig_atomic_t is an int where glint runs, as
 * src/cli/main.c asserts), and whether the render is under way: before
 * it a signal ends the rank at once, as it does glint, rank 0 saying so;
 * after it too (mpirun ending the job signals ranks that are finishing). */
static volatile sig_atomic_t interrupted, rendering;
static volatile sig_atomic_t rendered;
static int own_rank;

static void on_signal(int sig)
{
    (void)sig;
    interrupted = 1;
    if (!rendering) {
        static const char message[] = "glint-mpi: interrupted: nothing written\n";
        if (own_rank == 0 && !rendered) {
            ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
            (void)ignored;
        }
        _exit(CLI_EXIT_INTERRUPTED);
    }
}

/* --check and --print-scene, on rank 0 alone, as glint does them. */
static int report_only(const cli_options *o)
{
    return cli_reported(o->check ? cli_check_only(o) : cli_print_frame(o));
}

/* What the loader of the scene needs: the flags (on the other ranks,
 * whether they were rank 0's), and where the scene goes, with the exit
 * code of a failure and, on rank 0, the frames the run renders; on the
 * other ranks, where the load's messages wait. */
typedef struct flag_load {
    const cli_options *o;
    bool other_flags;
    cli_run *run;
    int code;
    cli_frames frames;        /* rank 0's: the frames to render */
    FILE *messages;
    display *window;
} flag_load;

/* A scene_loader: the scene as the flags ask, its problems said (on rank
 * 0 alone; on another rank kept in l->messages, which its thread loads
 * while rank 0 does, until it is known whether the failure was its own);
 * on rank 0, with --display, the window's SDL started before the load and
 * the window opened after it, a failure to open it failing the load,
 * before any rank renders. */
static glint_status load_flags_scene(void *user, bool rank0, glint_error *err)
{
    flag_load *l = user;
    cli_send_messages(l->messages);
    if (l->other_flags)
        l->code = cli_complain(CLI_EXIT_INTERNAL, "this rank was given other arguments than rank 0");
    else if (rank0 && l->o->display && !(l->window = display_start(&interrupted, &l->code)))
        ; /* said */
    else {
        l->code = cli_prepare(l->o, rank0, 0, l->run);
        /* Frames that cannot be rendered fail the load, before any is. */
        if (l->code < 0 && rank0 && (l->code = cli_frames_choose(l->o, &l->run->settings, l->run->dest.path,
                                                                 &l->frames)) >= 0) {
            glint_scene_free(l->run->scene);
            l->run->scene = NULL;
        }
        if (l->code >= 0)
            display_close(l->window);
        if (l->code >= 0 || (l->window && !display_show(l->window, l->o, l->run, &l->code)))
            l->window = NULL;
    }
    cli_send_messages(NULL);
    /* Said already; the status only tells failure from success. */
    return l->code < 0 ? GLINT_OK
                       : error_set(err, l->code == CLI_EXIT_INTERNAL ? GLINT_ERR_NOMEM : GLINT_ERR_INVALID,
                                   "the scene could not be loaded");
}

int main(int argc, char **argv)
{
    int provided = 0, rank = 0, ranks = 1;
    if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fputs("glint-mpi: MPI could not start\n", stderr);
        return CLI_EXIT_INTERNAL;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    own_rank = rank;
    /* mpirun passes SIGINT and SIGTERM on to every rank as SIGTERM, and
     * kills them a second later; a batch system may signal the ranks
     * themselves, or only one, which then stops the others. */
    cli_catch_signals(on_signal);
    /* Another build could read the flags otherwise: checked first. */
    glint_error err = {0};
    int code = -1;
    if (check_same_build(MPI_COMM_WORLD, &err))
        code = rank == 0 ? cli_complain(CLI_EXIT_USAGE, "%s", err.message) : CLI_EXIT_USAGE;
    cli_options o;
    /* Rank 0 parses first and prints; the others only when it found the
     * flags good, and silently, as they are the same flags. */
    if (rank == 0 && code < 0)
        code = cli_parse_args(argc, argv, &o);
    if (rank == 0 && code < 0 && provided < MPI_THREAD_FUNNELED)
        code = cli_complain(CLI_EXIT_INTERNAL, "this MPI cannot run threads beside the one calling it");
    agree_on_rank0(MPI_COMM_WORLD, &code);
    /* --check and --print-scene are rank 0's alone. */
    int report = rank == 0 && code < 0 && (o.check || o.print_scene);
    agree_on_rank0(MPI_COMM_WORLD, &report);
    if (report) {
        code = rank == 0 ? report_only(&o) : CLI_EXIT_OK;
        agree_on_rank0(MPI_COMM_WORLD, &code);
        MPI_Finalize();
        return code;
    }
    cli_run r = {0};
    flag_load load = {.o = &o, .run = &r, .code = -1};
    file_log *log = NULL; /* the files rank 0 sent, to load the frames of a sequence from */
    /* mpirun gives every rank the same arguments. */
    if (code < 0 && rank != 0)
        load.other_flags = parse_silently(argc, argv, &o) >= 0;
    /* Whether this rank takes part in the render: every rank when every
     * load succeeded; also a rank whose own load failed, which tells rank 0
     * so in the render (no rank waits for the others' loads: rank 0 begins
     * rendering at once); none when the flags or rank 0's load failed. */
    bool joins = code < 0;
    if (code < 0) {
        bool from_stdin = rank == 0 && o.scene && strcmp(o.scene, "-") == 0;
        int with_stdin = from_stdin;
        agree_on_rank0(MPI_COMM_WORLD, &with_stdin);
        int failed_rank;
        char *kept = NULL;
        size_t kept_size = 0;
        /* Without memory to keep them, the words are dropped, not said twice. */
        if (rank != 0 && !(load.messages = open_memstream(&kept, &kept_size)))
            load.messages = fopen("/dev/null", "w");
        glint_status st =
            load_everywhere(MPI_COMM_WORLD, load_flags_scene, &load, with_stdin, false, &log, &failed_rank, &err);
        if (load.messages && fclose(load.messages) == 0 && kept && st && failed_rank == rank)
            fputs(kept, stderr);
        free(kept);
        /* A failure the loader did not say (sending rank 0's files, memory)
         * is said here, on rank 0 and on the rank where it happened. */
        code = load.code >= 0 ? load.code : st ? cli_exit_code_of(st) : -1;
        if (st && load.code < 0 && (rank == 0 || rank == failed_rank))
            cli_complain(code, "%s", err.message);
        joins = !st || failed_rank != 0;
    }
    rendering = joins;
    if (joins) {
        int own = code;
        agree_on_rank0_bytes(MPI_COMM_WORLD, &load.frames, (int)sizeof load.frames);
        const volatile int *cancel = (const volatile int *)&interrupted;
        if (sequence_wanted(&o, &load.frames)) {
            code = sequence_render(&o, &r, &load.frames, log, rank, ranks, load.window, cancel);
        } else {
            /* A still needs the files no more. */
            file_log_free(log);
            log = NULL;
            code = render_across(&o, &r, rank, ranks, load.window, cancel, NULL);
        }
        code = own >= 0 ? own : code;
    }
    file_log_free(log);
    rendered = rendering;
    rendering = 0;
    /* Every rank exits with the worst code: a rank that ran out of memory
     * loading the scene makes it 5, as it would be for glint. */
    agree_on_max(MPI_COMM_WORLD, &code);
    if (code != CLI_EXIT_OK) {
        display_close(load.window);
        load.window = NULL;
    }
    if (r.scene)
        glint_scene_free(r.scene);
    /* When mpirun signalled every rank (Ctrl-C, SIGTERM), they end without
     * MPI_Finalize, which would wait for an mpirun that is ending the job
     * until it kills them, a second later. */
    int everyone_signalled = interrupted;
    agree_on_min(MPI_COMM_WORLD, &everyone_signalled);
    if (!everyone_signalled)
        MPI_Finalize();
    /* Rank 0 keeps the written image on screen until the user closes it,
     * with the other ranks gone rather than spinning in MPI meanwhile; a
     * signal now closes the window, as in glint, rather than end the rank. */
    if (load.window) {
        rendering = 1;
        display_wait(load.window);
    }
    return code;
}
