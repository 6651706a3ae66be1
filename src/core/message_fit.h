/* message_fit.h - a message too long for its buffer keeps its subject and
 * its reason: the longest word in it (a path, mostly) loses its middle
 * instead of the message losing its end. */
#ifndef GLINT_CORE_MESSAGE_FIT_H
#define GLINT_CORE_MESSAGE_FIT_H

#include <stdarg.h>
#include <stddef.h>

/* Room to format a message in before fitting it: two paths of PATH_MAX and
 * the words around them. */
#define MESSAGE_ROOM 10240

/* Shortens the NUL-terminated text in place to fewer than `size` bytes:
 * while it is too long, the middle of its longest word (a run without
 * spaces or quotes) becomes "...", keeping the word's first third and last
 * two thirds (a file's name and its line:column). The first word, the
 * file the message is about, is spared unless it is longer than a quarter
 * of `size`. When no word left is longer than 27 bytes, the text after the
 * first word loses its middle instead, so that the message still starts
 * with what it is about and ends with its reason. Never splits a UTF-8
 * character. */
void message_fit(char *text, size_t size);

/* Formats fmt with ap into text, MESSAGE_ROOM bytes, then fits it to
 * fewer than `size` bytes (message_fit). */
void message_vformat(char *text, size_t size, const char *fmt, va_list ap);

#endif
