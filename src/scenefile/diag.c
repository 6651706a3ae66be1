/* diag.c - problem reports and "did you mean" suggestions. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "core/message_fit.h"
#include "scenefile/diag.h"

void diag_raw(diag *d, glint_status status, const char *text)
{
    if (d->closed)
        return;
    /* Every report fits a glint_error, as the first is kept in one. */
    char message[MESSAGE_ROOM];
    snprintf(message, sizeof message, "%s", text);
    message_fit(message, sizeof d->first->message);
    if (d->count == 0 && d->first) {
        memcpy(d->first->message, message, strlen(message) + 1);
        d->first->status = status;
        d->first_status = status;
    }
    if (d->count < d->max && d->report)
        d->report(d->user, message);
    d->count++;
}

/* Reports body at n with the given status; a note on n (a colour that a
 * comment hid) says what the problem really is, instead of body. */
static void report_at(diag *d, const ynode *n, glint_status status, const char *body)
{
    char line[MESSAGE_ROOM];
    if (n && n->note)
        body = n->note;
    if (n)
        snprintf(line, sizeof line, "%s:%d:%d: %s", n->file, n->line, n->column, body);
    else
        snprintf(line, sizeof line, "%s", body);
    diag_raw(d, status, line);
}

void diag_at(diag *d, const ynode *n, const char *fmt, ...)
{
    char body[MESSAGE_ROOM / 2]; /* a path of PATH_MAX and words; the file's name comes before it */
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

/* word lower-cased, without '_', '-' or spaces, into buf (64 bytes and the
 * NUL); false when it does not fit. */
static bool fold(const char *word, char buf[65])
{
    size_t n = 0;
    for (; *word; word++) {
        if (*word == '_' || *word == '-' || *word == ' ')
            continue;
        if (n == 64)
            return false;
        buf[n++] = (char)(*word >= 'A' && *word <= 'Z' ? *word - 'A' + 'a' : *word);
    }
    buf[n] = '\0';
    return n > 0;
}

/* The one candidate that starts with the first `len` bytes of word, or
 * NULL when none or several do. */
static const char *only_start(const char *word, size_t len, const char *const *candidates, int count)
{
    const char *found = NULL;
    for (int i = 0; i < count; i++) {
        if (strncmp(candidates[i], word, len) != 0)
            continue;
        if (found)
            return NULL;
        found = candidates[i];
    }
    return found;
}

const char *diag_suggest(const char *word, const char *const *candidates, int count)
{
    /* The same word written another way ("rotateY", "rotate-y" for
     * rotate_y): before any typo, which would find the nearer "rotate". */
    char folded[65], other[65];
    if (fold(word, folded))
        for (int i = 0; i < count; i++)
            if (fold(candidates[i], other) && strcmp(folded, other) == 0)
                return candidates[i];
    /* A typo: short words allow one edit, longer ones two. */
    size_t len = strlen(word);
    int cap = len <= 4 ? 1 : 2;
    const char *best = NULL;
    int best_d = cap + 1;
    for (int i = 0; i < count; i++) {
        int dd = distance(word, candidates[i], cap);
        if (dd < best_d) {
            best_d = dd;
            best = candidates[i];
        }
    }
    if (best)
        return best;
    /* A word cut short ("pos" for position), or another ending of the same
     * stem ("sphere" for spherical, "cylinder" for cylindrical). */
    const char *start = len >= 3 ? only_start(word, len, candidates, count) : NULL;
    return start ? start : len >= 6 ? only_start(word, len - 2, candidates, count) : NULL;
}
