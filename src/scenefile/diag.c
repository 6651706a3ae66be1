/* diag.c - problem reports and "did you mean" suggestions. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "scenefile/diag.h"

void diag_raw(diag *d, glint_status status, const char *message)
{
    if (d->closed)
        return;
    if (d->count == 0 && d->first) {
        snprintf(d->first->message, sizeof d->first->message, "%s", message);
        d->first->status = status;
        d->first_status = status;
    }
    if (d->count < d->max && d->report)
        d->report(d->user, message);
    d->count++;
}

/* Reports body at n with the given status. */
static void report_at(diag *d, const ynode *n, glint_status status, const char *body)
{
    char line[512];
    if (n)
        snprintf(line, sizeof line, "%s:%d:%d: %.400s", n->file, n->line, n->column, body);
    else
        snprintf(line, sizeof line, "%.500s", body);
    diag_raw(d, status, line);
}

void diag_at(diag *d, const ynode *n, const char *fmt, ...)
{
    char body[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(body, sizeof body, fmt, ap);
    va_end(ap);
    report_at(d, n, GLINT_ERR_INVALID, body);
}

void diag_error(diag *d, const ynode *n, const glint_error *err)
{
    report_at(d, n, err->status ? err->status : GLINT_ERR_INVALID, err->message);
}

bool diag_full(const diag *d)
{
    return d->count >= d->max;
}

/* Edit distance counting a swap of neighbours as one edit (optimal string
 * alignment); anything over `cap` counts as cap + 1. */
static int distance(const char *a, const char *b, int cap)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 64 || lb > 64)
        return cap + 1;
    int d[65][65];
    for (size_t i = 0; i <= la; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= lb; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        for (size_t j = 1; j <= lb; j++) {
            int v = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < v)
                v = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < v)
                v = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < v)
                v = d[i - 2][j - 2] + 1;
            d[i][j] = v;
        }
    }
    return d[la][lb] > cap ? cap + 1 : d[la][lb];
}

const char *diag_suggest(const char *word, const char *const *candidates, int count)
{
    /* Short words allow one edit, longer ones two, as a typo usually is. */
    int cap = strlen(word) <= 4 ? 1 : 2;
    const char *best = NULL;
    int best_d = cap + 1;
    for (int i = 0; i < count; i++) {
        int dd = distance(word, candidates[i], cap);
        if (dd < best_d) {
            best_d = dd;
            best = candidates[i];
        }
    }
    return best;
}
