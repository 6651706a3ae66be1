/* text_scan.c - logical lines, words and numbers of OBJ and MTL text. */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "core/message_fit.h"
#include "model/text_scan.h"

/* Significant digits kept when a number goes to strtod: more than any
 * double needs (767), the rest standing for one sticky digit. */
#define MAX_DIGITS 780
/* Exponents beyond this are infinity or zero whatever the digits. */
#define MAX_EXPONENT 100000

const unsigned char scan_class[256] = {
    [' '] = SCAN_BLANK | SCAN_STOP, ['\t'] = SCAN_BLANK | SCAN_STOP, ['\r'] = SCAN_BLANK | SCAN_STOP,
    ['\v'] = SCAN_BLANK | SCAN_STOP, ['\f'] = SCAN_BLANK | SCAN_STOP, ['\\'] = SCAN_STOP,
    ['0'] = SCAN_DIGIT, ['1'] = SCAN_DIGIT, ['2'] = SCAN_DIGIT, ['3'] = SCAN_DIGIT, ['4'] = SCAN_DIGIT,
    ['5'] = SCAN_DIGIT, ['6'] = SCAN_DIGIT, ['7'] = SCAN_DIGIT, ['8'] = SCAN_DIGIT, ['9'] = SCAN_DIGIT,
};

/* Length of the continuation at p ("\\\n" or "\\\r\n"), or 0. */
static size_t continuation(const char *p, const char *end)
{
    if (p >= end || *p != '\\')
        return 0;
    if (end - p >= 2 && p[1] == '\n')
        return 2;
    if (end - p >= 3 && p[1] == '\r' && p[2] == '\n')
        return 3;
    return 0;
}

/* True when the physical line [s, e) has a '#' starting a word. */
static bool has_comment(const char *s, const char *e)
{
    for (const char *p = s; p < e; p++)
        if (*p == '#' && (p == s || scan_is_blank(p[-1])))
            return true;
    return false;
}

bool scan_next_line(const char *start, const char *end, bool last, scan_span *out)
{
    const char *row = start;
    out->rows = 1;
    for (;;) {
        const char *nl = memchr(row, '\n', (size_t)(end - row));
        if (!nl) {
            if (!last)
                return false;
            out->end = end > row && end[-1] == '\r' ? end - 1 : end;
            out->next = end;
            return true;
        }
        const char *text_end = nl > row && nl[-1] == '\r' ? nl - 1 : nl;
        if (text_end > row && text_end[-1] == '\\' && !has_comment(row, text_end - 1)) {
            row = nl + 1;
            out->rows++;
            continue;
        }
        out->end = text_end;
        out->next = nl + 1;
        return true;
    }
}

void scan_start(scan_line *l, const char *start, const char *end, long line, const char *file)
{
    *l = (scan_line){.p = start, .end = end, .row = start, .line = line, .file = file};
}

bool scan_more(scan_line *l)
{
    while (l->p < l->end) {
        size_t c;
        if (scan_is_blank(*l->p)) {
            l->p++;
        } else if ((c = continuation(l->p, l->end)) != 0) {
            l->p += c;
            l->row = l->p;
            l->line++;
        } else if (*l->p == '#') {
            l->p = l->end;
        } else {
            return true;
        }
    }
    return false;
}

scan_pos scan_here(const scan_line *l)
{
    return (scan_pos){l->line, (long)(l->p - l->row) + 1};
}

bool scan_at_break(const scan_line *l, const char *p)
{
    return p >= l->end || scan_is_blank(*p) || continuation(p, l->end) != 0;
}

const char *scan_word(scan_line *l, size_t *len)
{
    const char *s = l->p;
    for (;;) {
        while (l->p < l->end && !(scan_class[(unsigned char)*l->p] & SCAN_STOP))
            l->p++;
        if (scan_at_break(l, l->p))
            break;
        l->p++; /* a backslash inside the word */
    }
    *len = (size_t)(l->p - s);
    return s;
}

scan_result scan_number(scan_line *l, double *out)
{
    if (!scan_more(l))
        return SCAN_NONE;
    const char *stop = scan_decimal(l->p, l->end, out);
    if (!stop || !scan_at_break(l, stop))
        return SCAN_BAD;
    l->p = stop;
    return SCAN_OK;
}

int scan_numbers(scan_line *l, double *out, scan_pos *at, int keep, glint_error *err)
{
    int n = 0;
    for (;;) {
        double x = 0;
        if (!scan_more(l))
            return n;
        scan_pos here = scan_here(l);
        scan_result got = scan_number(l, &x);
        if (got == SCAN_BAD) {
            scan_not_number(l, err);
            return -1;
        }
        if (n < keep) {
            out[n] = x;
            if (at)
                at[n] = here;
        }
        if (n < INT32_MAX)
            n++;
    }
}

bool scan_word_is(const char *w, size_t n, const char *keyword)
{
    return strlen(keyword) == n && memcmp(w, keyword, n) == 0;
}

bool scan_rest(scan_line *l, const char **s, const char **e)
{
    if (!scan_more(l))
        return false;
    const char *start = l->p, *stop = l->end;
    for (const char *p = start + 1; p < l->end; p++)
        if (*p == '#' && (scan_is_blank(p[-1]) || p[-1] == '\n')) {
            stop = p;
            break;
        }
    /* Trailing blanks, and continuations with only blanks after them. */
    for (;;) {
        while (stop > start && scan_is_blank(stop[-1]))
            stop--;
        if (stop > start && stop[-1] == '\n')
            stop -= stop - 1 > start && stop[-2] == '\r' ? 3 : 2;
        else
            break;
    }
    *s = start;
    *e = stop;
    l->p = l->end;
    return true;
}

size_t scan_copy_text(const char *s, const char *e, char *out)
{
    size_t n = 0;
    while (s < e && *s) {
        size_t c = continuation(s, e);
        out[n++] = c ? ' ' : *s;
        s += c ? c : 1;
    }
    out[n] = '\0';
    return n;
}

bool scan_keep_text(char **text, size_t *len, size_t *cap, const char *s, const char *e, size_t *offset)
{
    size_t n = (size_t)(e - s);
    if (n >= SIZE_MAX - *len || !array_reserve((void **)text, cap, *len + n + 1, 1))
        return false;
    *offset = *len;
    *len += scan_copy_text(s, e, *text + *len) + 1;
    return true;
}

/* Matches nan, inf or infinity, in any case, at s: the byte after it, or
 * NULL. */
static const char *special(const char *s, const char *end, double *out)
{
    static const struct {
        const char *word;
        double value;
    } words[] = {{"infinity", INFINITY}, {"inf", INFINITY}, {"nan", NAN}};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++) {
        size_t n = strlen(words[i].word), k = 0;
        while (k < n && s + k < end && (s[k] | 0x20) == words[i].word[k])
            k++;
        if (k == n) {
            *out = words[i].value;
            return s + n;
        }
    }
    return NULL;
}

/* The number at s, whose digits end at `stop`, through strtod: its
 * significant digits (the first MAX_DIGITS, then a sticky 1 for any
 * non-zero digit dropped after them, which rounds as all of them would)
 * and a decimal exponent, written out plainly. */
static double slow_decimal(const char *s, const char *stop)
{
    char buf[MAX_DIGITS + 32];
    size_t n = 0;
    long exponent = 0;
    bool fraction = false, dropped = false;
    const char *p = s;
    if (*p == '+' || *p == '-')
        buf[n++] = *p++;
    size_t first = n;
    for (; p < stop && *p != 'e' && *p != 'E'; p++) {
        if (*p == '.') {
            fraction = true;
        } else if (n == first && *p == '0') {
            exponent -= fraction;
        } else if (n - first < MAX_DIGITS) {
            buf[n++] = *p;
            exponent -= fraction;
        } else {
            dropped |= *p != '0';
            exponent += !fraction;
        }
    }
    if (n == first)
        buf[n++] = '0';
    if (dropped) {
        buf[n++] = '1';
        exponent--;
    }
    if (p < stop) {
        long e = 0;
        bool negative = *++p == '-';
        p += *p == '-' || *p == '+';
        for (; p < stop; p++)
            e = e < MAX_EXPONENT ? e * 10 + (*p - '0') : e;
        exponent += negative ? -e : e;
    }
    if (exponent > MAX_EXPONENT)
        exponent = MAX_EXPONENT;
    if (exponent < -MAX_EXPONENT)
        exponent = -MAX_EXPONENT;
    snprintf(buf + n, sizeof buf - n, "e%ld", exponent);
    return strtod(buf, NULL);
}

/* Reads a plain decimal at s, before end, the form nearly every file
 * writes: an optional sign, then digits with an optional '.', at least one
 * digit and at most 19 in all, worth at most 2^53 as an integer, and no
 * exponent after them. Returns the first byte after it, with *out set to
 * what scan_decimal gives (one exact division), or NULL for anything else,
 * for scan_decimal to read. */
static inline const char *plain_decimal(const char *s, const char *end, double *out)
{
    static const double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,
                                    1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19};
    const char *p = s;
    bool negative = p < end && *p == '-';
    p += p < end && (*p == '-' || *p == '+');
    const char *whole = p;
    /* 19 digits fit in 64 bits; more make the sum wrap, and are refused. */
    uint64_t mantissa = 0;
    for (unsigned d; p < end && (d = (unsigned char)*p - '0') < 10; p++)
        mantissa = mantissa * 10 + d;
    size_t digits = (size_t)(p - whole), fraction = 0;
    if (p < end && *p == '.') {
        const char *first = ++p;
        for (unsigned d; p < end && (d = (unsigned char)*p - '0') < 10; p++)
            mantissa = mantissa * 10 + d;
        fraction = (size_t)(p - first);
        digits += fraction;
    }
    if (digits == 0 || digits > 19 || mantissa > (1ULL << 53) || (p < end && (*p == 'e' || *p == 'E')))
        return NULL;
    /* Both operands are exact doubles: one correctly rounded division. */
    double x = (double)mantissa / powers[fraction];
    *out = negative ? -x : x;
    return p;
}

int scan_plain_numbers(scan_line *l, double *out, int least, int most)
{
    const char *p = l->p, *end = l->end;
    int n = 0;
    while (scan_plain_start(p = scan_skip_blanks(p, end), end))
        if (n == most || !(p = plain_decimal(p, end, &out[n++])) || !scan_plain_stop(p, end))
            return -1;
    if (n < least)
        return -1;
    l->p = p;
    return n;
}

const char *scan_decimal(const char *s, const char *end, double *out)
{
    const char *plain = plain_decimal(s, end, out);
    if (plain)
        return plain;
    static const double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char *p = s;
    bool negative = false;
    if (p < end && (*p == '+' || *p == '-'))
        negative = *p++ == '-';
    const char *body = p;
    uint64_t mantissa = 0;
    int kept = 0;             /* significant digits in mantissa, at most 19 */
    long exponent = 0;
    bool exact = true;        /* false once a digit is dropped */
    while (p < end && *p == '0')
        p++;
    for (; p < end && scan_is_digit(*p); p++) {
        if (kept < 19) {
            mantissa = mantissa * 10 + (uint64_t)(*p - '0');
            kept++;
        } else {
            exact = false;
        }
    }
    bool digits = p > body;
    if (p < end && *p == '.') {
        const char *fraction = ++p;
        if (mantissa == 0)
            for (; p < end && *p == '0'; p++)
                exponent--;
        for (; p < end && scan_is_digit(*p); p++) {
            if (kept < 19) {
                mantissa = mantissa * 10 + (uint64_t)(*p - '0');
                kept++;
                exponent--;
            } else {
                exact = false;
            }
        }
        digits |= p > fraction;
    }
    if (!digits) {
        const char *after = p == body ? special(p, end, out) : NULL;
        if (after && negative)
            *out = -*out;
        return after;
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        const char *q = p + 1;
        bool minus = false;
        if (q < end && (*q == '+' || *q == '-'))
            minus = *q++ == '-';
        if (q < end && scan_is_digit(*q)) {
            long e = 0;
            for (; q < end && scan_is_digit(*q); q++)
                e = e < MAX_EXPONENT ? e * 10 + (*q - '0') : e;
            exponent += minus ? -e : e;
            p = q;
        }
    }
    if (mantissa == 0) {
        *out = negative ? -0.0 : 0.0;
    } else if (exact && mantissa <= (1ULL << 53) && exponent >= -22 && exponent <= 22) {
        /* Both operands are exact doubles: one correctly rounded operation. */
        double m = (double)mantissa;
        *out = exponent < 0 ? m / powers[-exponent] : m * powers[exponent];
        if (negative)
            *out = -*out;
    } else {
        *out = slow_decimal(s, p);
    }
    return p;
}

void scan_quote(const char *s, size_t len, char *out, size_t size)
{
    size_t n = 0, limit = len > 24 ? 24 : len;
    for (size_t i = 0; i < limit && n + 4 < size; i++)
        out[n++] = s[i] >= 32 && s[i] < 127 ? s[i] : '?';
    if (limit < len && n + 4 < size)
        for (int i = 0; i < 3; i++)
            out[n++] = '.';
    out[n] = '\0';
}

glint_status scan_error(const scan_line *l, scan_pos at, glint_error *err, const char *fmt, ...)
{
    /* Whole here: error_set fits the message with its place, keeping the reason. */
    char body[MESSAGE_ROOM];
    va_list ap;
    va_start(ap, fmt);
    message_vformat(body, sizeof body, fmt, ap);
    va_end(ap);
    return error_set(err, GLINT_ERR_INVALID, "%s:%ld:%ld: %s", l->file, at.line, at.column, body);
}

glint_status scan_not_number(scan_line *l, glint_error *err)
{
    scan_pos at = scan_here(l);
    size_t len;
    const char *w = scan_word(l, &len);
    char q[32];
    scan_quote(w, len, q, sizeof q);
    return scan_error(l, at, err, "'%s' is not a number", q);
}
