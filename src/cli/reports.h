/* reports.h - what the glint and glint-mpi commands report on stdout
 * instead of rendering: a check of scene files (--check) and the scene as
 * a scene file (--print-scene); and the exit code of a run that reports on
 * stdout, which is no success when the report was lost. */
#ifndef GLINT_CLI_REPORTS_H
#define GLINT_CLI_REPORTS_H

#include "glint.h"
#include "cli/args.h"

/* Checks every scene file o names, each reported in turn: what it holds on
 * stdout, its problems on stderr. The exit code is the worst of theirs,
 * the highest: 5 (out of memory) over 1 (not valid) over 0. */
int cli_check_only(const cli_options *o);

/* --print-scene: the scene o names (its first frame, or --frame N's) as a
 * still on stdout, every keyed value fixed at that frame's time and the
 * seed the frame's, so that it renders the frame's bytes, with the output
 * o names (when given). The exit code. */
int cli_print_frame(const cli_options *o);

/* The exit code of a run that reports on stdout, with its problems on
 * stderr (the help, the version, --check, --print-scene): `code`, or 3
 * when either could not be written in whole (a full disk, a reader gone),
 * as a lost report is no success. The reason is said on stderr, while that
 * can still be written, unless the run had already failed as badly: a
 * higher code wins, as in --check's worst of its files. */
int cli_reported(int code);

#endif
