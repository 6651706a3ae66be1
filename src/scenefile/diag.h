/* diag.h - collecting the problems of a scene file: each with its place,
 * all of them up to a limit, the first kept for the caller's glint_error. */
#ifndef GLINT_SCENEFILE_DIAG_H
#define GLINT_SCENEFILE_DIAG_H

#include <stdbool.h>
#include "glint.h"
#include "scenefile/yaml_tree.h"

typedef struct diag {
    glint_report_fn report;
    void *user;
    int max;                  /* stop reporting after this many */
    int count;                /* problems found */
    glint_error *first;       /* receives the first problem; may be NULL */
    glint_status first_status;
    bool closed;              /* no more reports: the walk was cut short */
} diag;

/* Reports "file:line:column: message" at node n (or "file: message" when n
 * is NULL and file is given). When n has a note (yaml_tree.h), the note is
 * the message. */
void diag_at(diag *d, const ynode *n, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Reports a failed call's error at node n with the call's status, so that
 * running out of memory stays GLINT_ERR_NOMEM. */
void diag_error(diag *d, const ynode *n, const glint_error *err);

/* Reports a message that already carries its place, or has none. */
void diag_raw(diag *d, glint_status status, const char *message);

/* True once the limit of problems is reached: the walk should stop. */
bool diag_full(const diag *d);

/* Of `count` candidate words, the one `word` most likely meant, or NULL:
 * for "did you mean" hints. First one that differs only in case and in
 * '_', '-' or spaces; then the closest within a small edit distance (one
 * edit for words of up to 4 letters, two for longer ones); then the only
 * one that starts with word (3 letters or more) or with all of it but its
 * last two letters (6 letters or more). */
const char *diag_suggest(const char *word, const char *const *candidates, int count);

#endif
