/* obj_ahead.h - pieces of OBJ text parsed ahead by threads into records,
 * then merged into the model in the file's order (obj_ahead.c), giving the
 * model and the messages of reading the text in one pass. */
#ifndef GLINT_MODEL_OBJ_AHEAD_H
#define GLINT_MODEL_OBJ_AHEAD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "model/obj_parse.h"

/* A piece of whole lines and the records a thread parsed from it. */
typedef struct text_piece {
    const char *start, *end;  /* whole lines */
    bool last;                /* end is the end of the text, which may lack a break */
    const char *file;
    long rows;                /* its physical lines */
    struct ahead *items;      /* a record for each line that is not blank, a comment or ignored */
    size_t count, cap;
    int32_t *corners;         /* v, vt, vn as written, 3 each; 0 for a part a corner lacks */
    size_t corner_count, corner_cap;
    bool no_memory;
} text_piece;

/* Makes pc the piece of lines [start, end) of `file` with no records,
 * keeping the room its records had; `last` when the text ends at end.
 * Zero a piece before its first use. */
void text_piece_set(text_piece *pc, const char *start, const char *end, bool last, const char *file);

/* Parses the lines of the text_piece `piece` into its records, touching
 * nothing else: a thread's work, so pthread_create can start it. */
void *text_piece_parse(void *piece);

/* Applies the records of a parsed piece to r's model in order, its first
 * line being r->line; memory that ran out while parsing it counts after
 * the lines it parsed. */
glint_status text_piece_merge(obj_parser *r, const text_piece *pc, glint_error *err);

/* Frees the room of pc's records. */
void text_piece_free(text_piece *pc);

#endif
