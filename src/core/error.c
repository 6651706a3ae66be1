/* error.c - message formatting for glint_error: formatted whole first,
 * then fitted, so that a long path loses its middle, not the reason. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "core/error.h"
#include "core/message_fit.h"

glint_status error_set(glint_error *err, glint_status status, const char *fmt, ...)
{
    if (err) {
        err->status = status;
        char text[MESSAGE_ROOM];
        va_list ap;
        va_start(ap, fmt);
        message_vformat(text, sizeof err->message, fmt, ap);
        va_end(ap);
        memcpy(err->message, text, strlen(text) + 1);
    }
    return status;
}
