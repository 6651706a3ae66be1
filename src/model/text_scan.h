/* text_scan.h - the words and numbers of line-based text formats (OBJ and
 * MTL): logical lines (a backslash ending a line joins the next one to it),
 * blanks, '#' comments, decimal numbers read without strtod in the common
 * case, and messages placed at file:line:column. */
#ifndef GLINT_MODEL_TEXT_SCAN_H
#define GLINT_MODEL_TEXT_SCAN_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"

/* Where a logical line ends. */
typedef struct scan_span {
    const char *end;          /* end of its text, before its "\n" or "\r\n" */
    const char *next;         /* first byte after its line break */
    long rows;                /* physical lines it spans */
} scan_span;

/* Classes of bytes, looked up once each in the inner loops. */
enum {
    SCAN_BLANK = 1,           /* space, tab, CR, VT, FF */
    SCAN_DIGIT = 2,
    SCAN_STOP = 4             /* may end a word: a blank, or the backslash of a continuation */
};

/* The class bits of each byte. */
extern const unsigned char scan_class[256];

/* True when c is a blank: space, tab, CR, VT or FF. */
static inline bool scan_is_blank(char c)
{
    return scan_class[(unsigned char)c] & SCAN_BLANK;
}

/* True when c is a decimal digit. */
static inline bool scan_is_digit(char c)
{
    return scan_class[(unsigned char)c] & SCAN_DIGIT;
}

/* Finds the logical line starting at `start` among the bytes before `end`.
 * A backslash right before a line break continues the line, except on a
 * line with a comment. Returns false when the line has no break before
 * `end` and `last` is false: more bytes are needed. With `last` set, `end`
 * closes the line. */
bool scan_next_line(const char *start, const char *end, bool last, scan_span *out);

/* Reading one logical line. */
typedef struct scan_line {
    const char *p;            /* next byte to read */
    const char *end;          /* end of the line's text */
    const char *row;          /* first byte of the physical line p is in */
    long line;                /* that line's number, from 1 */
    const char *file;         /* the file, for messages */
} scan_line;

/* A place in the file, for messages. */
typedef struct scan_pos {
    long line, column;        /* from 1; the column counts bytes */
} scan_pos;

/* Starts reading the line [start, end), numbered `line`, of `file`. */
void scan_start(scan_line *l, const char *start, const char *end, long line, const char *file);

/* Skips blanks and continuations; at a '#' that starts a word, skips the
 * comment to the line's end. True when a word starts at l->p. */
bool scan_more(scan_line *l);

/* The place of l->p. */
scan_pos scan_here(const scan_line *l);

/* True when p (within the line) is where a word ends: the line's end, a
 * blank or a continuation. */
bool scan_at_break(const scan_line *l, const char *p);

/* The word at l->p, up to the next break; moves past it. *len is its
 * length. */
const char *scan_word(scan_line *l, size_t *len);

typedef enum scan_result {
    SCAN_NONE,                /* no word left on the line */
    SCAN_BAD,                 /* a word that is not a number; l->p stays at its start */
    SCAN_OK
} scan_result;

/* Reads the next word as a number (see scan_decimal), which must be the
 * whole word. */
scan_result scan_number(scan_line *l, double *out);

/* Reads the numbers left on the line: the first `keep` into out, their
 * places into at (when not NULL). Returns how many there were, or -1 with
 * err filled at the first word that is not a number. */
int scan_numbers(scan_line *l, double *out, scan_pos *at, int keep, glint_error *err);

/* True when the word [w, w + n) is `keyword`. */
bool scan_word_is(const char *w, size_t n, const char *keyword);

/* The rest of the line from the next word on, less a comment and trailing
 * blanks, as [*s, *e); moves to the line's end. False when it is empty. */
bool scan_rest(scan_line *l, const char **s, const char **e);

/* Copies [s, e) to out, which has room for e - s + 1 bytes, turning each
 * continuation into one blank and stopping at a NUL byte; terminates it
 * and returns its length. */
size_t scan_copy_text(const char *s, const char *e, char *out);

/* Appends the copy scan_copy_text makes of [s, e) to the growing text
 * *text, of which *len bytes are used out of *cap, and sets *offset to
 * where it starts. False when out of memory. */
bool scan_keep_text(char **text, size_t *len, size_t *cap, const char *s, const char *e, size_t *offset);

/* Reads a decimal number at s, before end: an optional sign, then digits
 * with an optional '.' (at least one digit on either side), then an
 * optional exponent (e or E, an optional sign, digits); or nan, inf or
 * infinity in any case. Returns the first byte after it, with *out set to
 * the nearest double, or NULL when no number starts at s. Up to 19
 * significant digits worth at most 2^53 with a power of ten up to 22 are
 * exact in one multiplication or division; anything else goes to strtod. */
const char *scan_decimal(const char *s, const char *end, double *out);

/* For the plain readers: the first byte from p on that is not a blank, or
 * end. */
static inline const char *scan_skip_blanks(const char *p, const char *end)
{
    while (p < end && scan_is_blank(*p))
        p++;
    return p;
}

/* For the plain readers: true when a word starts at p, after blanks: p is
 * before end and not at a line break. */
static inline bool scan_plain_start(const char *p, const char *end)
{
    return p < end && *p != '\n';
}

/* For the plain readers: true when a word ending at p ends there as a
 * plain one, at end, a blank or a line break. */
static inline bool scan_plain_stop(const char *p, const char *end)
{
    return p == end || scan_is_blank(*p) || *p == '\n';
}

/* Reads the rest of the line as `least` to `most` plain decimals between
 * blanks, the form nearly every file writes (an optional sign, then digits
 * with an optional '.', at least one digit and at most 19 in all, worth
 * at most 2^53 as an integer, no exponent), into out, as scan_decimal
 * reads them, and moves to the line's end; returns how many there were.
 * Returns -1, l unchanged, when the rest of the line is anything else (a
 * continuation, a comment, another word or number form, or too few or
 * many): then scan_numbers is to read it. A line break ends the line too,
 * at which l->p then stops: a caller may set l->end to the end of the text
 * and find the line's end so. */
int scan_plain_numbers(scan_line *l, double *out, int least, int most);

/* Writes at most 24 bytes of the word [s, s + len) into out for a message,
 * each byte that is not printable as '?', and "..." when it is cut. */
void scan_quote(const char *s, size_t len, char *out, size_t size);

/* Fills err with "file:line:column: message" and returns GLINT_ERR_INVALID. */
glint_status scan_error(const scan_line *l, scan_pos at, glint_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Reports the word at l->p as "'word' is not a number". */
glint_status scan_not_number(scan_line *l, glint_error *err);

#endif
