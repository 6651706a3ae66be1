/* render_across.c - one image rendered across glint-mpi's ranks, written
 * and summed up by rank 0 (render_across.h). */
#include <stdio.h>
#include <stdlib.h>
#include "glint_mpi.h"
#include "mpi/render_across.h"

/* The summary: the run as glint says it, with the ranks and their threads
 * (rank 0's count, when every rank has as many), and for each rank how
 * busy its threads were (their time on tiles over the render's time) and
 * how many tiles it rendered. */
static void print_summary(const cli_run *r, int ranks, const glint_render_stats *total,
                          const glint_mpi_rank_stats *each, const cli_progress *frame)
{
    bool same_threads = true;
    for (int i = 0; i < ranks; i++)
        same_threads = same_threads && each[i].threads == each[0].threads;
    const glint_settings *s = &r->settings;
    fputs("glint-mpi: ", stderr);
    if (frame)
        fprintf(stderr, "frame %d (%d of %d), ", frame->frame, frame->frames_done + 1, frame->frames);
    fprintf(stderr, "%dx%d, %d spp, %d rank%s x ", s->width, s->height, s->samples_per_pixel, ranks,
            ranks == 1 ? "" : "s");
    if (same_threads)
        fprintf(stderr, "%d thread%s", each[0].threads, each[0].threads == 1 ? "" : "s");
    else
        fputs("their threads", stderr);
    fprintf(stderr, ": %.3f s, %llu samples, %llu rays, %.1f Mrays/s -> %s; busy:", total->seconds,
            (unsigned long long)total->samples, (unsigned long long)total->rays,
            total->seconds > 0 ? total->rays / total->seconds * 1e-6 : 0.0, r->dest.shown);
    for (int i = 0; i < ranks; i++) {
        const glint_mpi_rank_stats *p = &each[i];
        double busy = p->seconds > 0 && p->threads > 0 ? p->busy / (p->seconds * p->threads) : 0;
        fprintf(stderr, "%s rank %d %.0f%% (%d tile%s", i ? "," : "", i, 100 * (busy < 1 ? busy : 1), p->tiles,
                p->tiles == 1 ? "" : "s");
        if (!same_threads)
            fprintf(stderr, ", %d thread%s", p->threads, p->threads == 1 ? "" : "s");
        fputc(')', stderr);
    }
    fputc('\n', stderr);
}

int render_across(const cli_options *o, cli_run *r, int rank, int ranks, display *window, const volatile int *cancel,
                  const cli_progress *frame)
{
    cli_progress prog = frame ? *frame : (cli_progress){0};
    prog.last_print = -1;
    clock_gettime(CLOCK_MONOTONIC, &prog.start);
    glint_render_options ro = {.threads = o->threads > 0 ? (int)o->threads : 0, .cancel = cancel,
                               .keep_partial = o->partial};
    if (rank == 0 && !o->quiet) {
        ro.progress = cli_show_progress;
        ro.progress_user = &prog;
    }
    if (window) {
        ro.tile_done = display_tile;
        ro.tile_user = window;
    }
    glint_mpi_rank_stats *each = rank == 0 ? calloc((size_t)ranks, sizeof *each) : NULL;
    if (rank == 0 && !each) {
        fputs("glint-mpi: out of memory for the ranks' reports\n", stderr);
        MPI_Abort(MPI_COMM_WORLD, CLI_EXIT_INTERNAL); /* the others cannot be told */
    }
    glint_image image;
    glint_render_stats total;
    glint_error err = {0};
    glint_status st = glint_mpi_render(MPI_COMM_WORLD, r->scene, &ro, &image, &total, each, &err);
    if (ro.progress && st)
        fputs("\r\033[K", stderr); /* the progress line stopped short */
    int code = CLI_EXIT_OK;
    if (rank != 0)
        code = cli_exit_code_of(st);
    else if (st == GLINT_ERR_CANCELLED)
        code = cli_interrupted(o, r, &image, total.tiles_done, total.tiles_total);
    else if (st)
        code = cli_complain(cli_exit_code_of(st), "%s", err.message);
    else if ((st = cli_write_image(r, &image, &err)))
        code = cli_complain(cli_exit_code_of(st), "%s", err.message);
    else {
        cli_warn_nan(total.nan_samples);
        if (!o->quiet)
            print_summary(r, ranks, &total, each, frame);
        if (window)
            display_finished(window, total.seconds);
    }
    glint_image_free(&image);
    free(each);
    return code;
}
