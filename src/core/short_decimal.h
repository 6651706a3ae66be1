/* short_decimal.h - the numbers scene files are mostly written with, read
 * without strtod: a generated scene of a million objects holds five million
 * of them, and strtod takes some 500 instructions for each. */
#ifndef GLINT_CORE_SHORT_DECIMAL_H
#define GLINT_CORE_SHORT_DECIMAL_H

#include <stdbool.h>

/* Reads a short decimal: a sign or none, then at most 15 digits with at
 * most one '.' among them, no exponent, nothing else. Sets *out to exactly
 * the double strtod gives for the text (the digits and the power of ten
 * are both exact doubles, so their quotient is rounded once, correctly)
 * and returns true; returns false, *out untouched, for any other text. */
bool short_decimal(const char *text, double *out);

#endif
