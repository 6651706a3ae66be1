/* error.c - message formatting for glint_error. */
#include <stdarg.h>
#include <stdio.h>
#include "core/error.h"

glint_status error_set(glint_error *err, glint_status status, const char *fmt, ...)
{
    if (err) {
        err->status = status;
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}
