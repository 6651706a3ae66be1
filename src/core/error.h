/* error.h - filling a glint_error: the one way the library reports failures. */
#ifndef GLINT_CORE_ERROR_H
#define GLINT_CORE_ERROR_H

#include "glint.h"

/* Formats a message into err (when err is not NULL) and returns status, so
 * callers can write `return error_set(err, GLINT_ERR_INVALID, "...")`. */
glint_status error_set(glint_error *err, glint_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
