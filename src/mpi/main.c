/* main.c - the glint-mpi command: every rank checked to run one build
 * (same_build.c); glint's flags (src/cli/args.c), read by every rank; the
 * scene loaded by rank 0, reporting its problems alone, and sent with its
 * files to the others, which load it from those bytes (ship_files.c); its
 * tiles rendered across the ranks (lead.c on rank 0, follow.c on the
 * others); the image written by rank 0 alone, as glint writes it; signals
 * handled as glint handles them; and one exit code for every rank.
 * --check and --print-scene are rank 0's alone. */
#define _GNU_SOURCE /* sched_getaffinity */
#include <fcntl.h>
#include <mpi.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/args.h"
#include "cli/reports.h"
#include "cli/setup.h"
#include "core/processors.h"
#include "mpi/agree.h"
#include "mpi/follow.h"
#include "mpi/lead.h"
#include "mpi/same_build.h"
#include "mpi/ship_files.h"
#include "render/render_tiles.h"

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

/* Rank 0's load of the scene (standard input kept first, when it is read)
 * with every file it reads noted in a new *log; -1, or the exit code after
 * complaining. */
static int load_recording(const cli_options *o, bool from_stdin, cli_run *r, file_log **log)
{
    if (from_stdin) {
        int code = keep_stdin();
        if (code >= 0)
            return code;
    }
    if (!(*log = file_log_new()))
        return cli_complain(CLI_EXIT_INTERNAL, "out of memory");
    file_log_record(*log);
    int code = cli_prepare(o, true, r);
    file_log_stop();
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
    if (o->check)
        return cli_reported(cli_check_only(o));
    cli_run r;
    int code = cli_prepare(o, true, &r);
    return cli_reported(code >= 0 ? code : cli_print_scene(r.scene, o->output));
}

/* The summary: the run as glint says it, with the ranks and their threads
 * (rank 0's count, when every rank has as many), and for each rank how
 * busy its threads were (their time on tiles over the render's time) and
 * how many tiles it rendered. */
static void print_summary(const cli_run *r, int ranks, const rank_report *reports, double seconds)
{
    uint64_t rays = 0, samples = 0;
    bool same_threads = true;
    for (int i = 0; i < ranks; i++) {
        rays += reports[i].rays;
        samples += reports[i].samples;
        same_threads = same_threads && reports[i].threads == reports[0].threads;
    }
    const glint_settings *s = &r->settings;
    fprintf(stderr, "glint-mpi: %dx%d, %d spp, %d rank%s x ", s->width, s->height, s->samples_per_pixel, ranks,
            ranks == 1 ? "" : "s");
    if (same_threads)
        fprintf(stderr, "%d thread%s", reports[0].threads, reports[0].threads == 1 ? "" : "s");
    else
        fputs("their threads", stderr);
    fprintf(stderr, ": %.3f s, %llu samples, %llu rays, %.1f Mrays/s -> %s; busy:", seconds,
            (unsigned long long)samples, (unsigned long long)rays, seconds > 0 ? rays / seconds * 1e-6 : 0.0,
            r->dest.shown);
    for (int i = 0; i < ranks; i++) {
        const rank_report *p = &reports[i];
        double busy = p->seconds > 0 && p->threads > 0 ? p->busy / (p->seconds * p->threads) : 0;
        fprintf(stderr, "%s rank %d %.0f%% (%d tile%s", i ? "," : "", i, 100 * (busy < 1 ? busy : 1), p->tiles,
                p->tiles == 1 ? "" : "s");
        if (!same_threads)
            fprintf(stderr, ", %d thread%s", p->threads, p->threads == 1 ? "" : "s");
        fputc(')', stderr);
    }
    fputc('\n', stderr);
}

/* The render threads of a rank without --threads: one per processor it
 * may run on. mpirun binds each rank to one core by default when there are
 * at most two ranks, to a socket beyond: a thread per core of the machine
 * would then share the cores bound to. */
static int default_threads(void)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    int n = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
    return n > 0 ? n : processors_online(1024);
}

/* Renders and, on rank 0, writes the image; the exit code. Every rank has
 * loaded the scene into r. */
static int render(const cli_options *o, cli_run *r, int rank, int ranks)
{
    glint_render_options ro = {.threads = o->threads > 0 ? (int)o->threads : default_threads(),
                               .cancel = (const volatile int *)&interrupted};
    if (rank != 0) {
        follow_render(r->scene, &ro);
        return CLI_EXIT_OK;
    }
    rank_report *reports = calloc((size_t)ranks, sizeof *reports);
    if (!reports)
        return cli_complain(CLI_EXIT_INTERNAL, "out of memory for %d ranks' reports", ranks);
    double start = MPI_Wtime();
    glint_image image;
    int tiles_done;
    int code = lead_render(r->scene, &ro, ranks, !o->quiet, &image, &tiles_done, reports);
    double seconds = MPI_Wtime() - start;
    if (code == CLI_EXIT_INTERRUPTED) {
        render_layout layout;
        glint_error err;
        render_layout_for(r->scene, ro.tile_size, &layout, &err); /* as lead_render's, which succeeded */
        code = cli_interrupted(o, r, &image, tiles_done, layout.tiles_total);
        glint_image_free(&image);
    } else if (!code) {
        glint_error err = {0};
        glint_status st = cli_write_image(r, &image, &err);
        glint_image_free(&image);
        if (st) {
            code = cli_complain(cli_exit_code_of(st), "%s", err.message);
        } else {
            uint64_t nan_samples = 0;
            for (int i = 0; i < ranks; i++)
                nan_samples += reports[i].nan_samples;
            cli_warn_nan(nan_samples);
            if (!o->quiet)
                print_summary(r, ranks, reports, seconds);
        }
    }
    free(reports);
    return code;
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
    int code = check_same_build(rank, ranks);
    cli_options o;
    /* Rank 0 parses first and prints; the others only when it found the
     * flags good, and silently, as they are the same flags. */
    if (rank == 0 && code < 0)
        code = cli_parse_args(argc, argv, &o);
    if (rank == 0 && code < 0 && provided < MPI_THREAD_FUNNELED)
        code = cli_complain(CLI_EXIT_INTERNAL, "this MPI cannot run threads beside the one calling it");
    agree_on_rank0(&code);
    /* --check and --print-scene are rank 0's alone. */
    int report = rank == 0 && code < 0 && (o.check || o.print_scene);
    agree_on_rank0(&report);
    if (report) {
        code = rank == 0 ? report_only(&o) : CLI_EXIT_OK;
        agree_on_rank0(&code);
        MPI_Finalize();
        return code;
    }
    cli_run r = {0};
    /* Rank 0 loads the scene and checks the output first: a problem is
     * reported once, by it, and every rank exits with its code. It notes
     * the files it reads, to send them to the others. */
    file_log *log = NULL;
    bool from_stdin = rank == 0 && code < 0 && o.scene && strcmp(o.scene, "-") == 0;
    if (code < 0 && rank == 0)
        code = load_recording(&o, from_stdin, &r, &log);
    agree_on_rank0(&code);
    if (code < 0)
        code = rank == 0 ? send_files(log, from_stdin) : receive_files(&log);
    /* The others load the same scene from what rank 0 sent: no path of
     * theirs is looked at. */
    if (code < 0 && rank != 0) {
        if (parse_silently(argc, argv, &o) >= 0) /* mpirun gives every rank the same arguments */
            code = cli_complain(CLI_EXIT_INTERNAL, "rank %d was given other arguments than rank 0", rank);
        else {
            file_log_replay(log);
            code = cli_prepare(&o, false, &r);
            file_log_stop();
        }
    }
    file_log_free(log);
    /* A rank that could not load what rank 0 loaded said why itself. */
    int own = code;
    agree_on_max(&code);
    if (rank == 0 && own < 0 && code >= 0)
        fputs("glint-mpi: another rank could not load the scene rank 0 loaded (its messages above)\n", stderr);
    rendering = code < 0;
    if (code < 0)
        code = render(&o, &r, rank, ranks);
    rendered = rendering;
    rendering = 0;
    agree_on_rank0(&code);
    if (r.scene)
        glint_scene_free(r.scene);
    /* When mpirun signalled every rank (Ctrl-C, SIGTERM), they end without
     * MPI_Finalize, which would wait for an mpirun that is ending the job
     * until it kills them, a second later. */
    int everyone_signalled = interrupted;
    agree_on_min(&everyone_signalled);
    if (!everyone_signalled)
        MPI_Finalize();
    return code;
}
