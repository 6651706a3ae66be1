/* message_fit.c - shortening a message's longest word in the middle, so
 * that a long path never pushes the reason out of a glint_error. */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include "core/message_fit.h"

/* Bytes of a word kept at the least, around the "...". */
#define MIN_KEPT 24

static bool is_word_byte(char c)
{
    return c != ' ' && c != '\t' && c != '\n' && c != '\'' && c != '"';
}

static bool is_continuation(char c)
{
    return ((unsigned char)c & 0xC0) == 0x80;
}

/* The longest word of text: its start in *start, its length returned. */
static size_t longest_word(const char *text, size_t *start)
{
    size_t best = 0;
    for (size_t i = 0; text[i];) {
        size_t j = i;
        while (text[j] && is_word_byte(text[j]))
            j++;
        if (j - i > best) {
            best = j - i;
            *start = i;
        }
        i = text[j] ? j + 1 : j;
    }
    return best;
}

void message_fit(char *text, size_t size)
{
    size_t len = strlen(text), start = 0, n;
    while (len >= size && (n = longest_word(text, &start)) > MIN_KEPT + 3) {
        size_t excess = len - (size - 1) + 3;
        size_t keep = n > excess + MIN_KEPT ? n - excess : MIN_KEPT;
        size_t head = start + keep / 3, tail = start + n - (keep - keep / 3);
        while (head > start && is_continuation(text[head]))
            head--;
        while (tail < start + n && is_continuation(text[tail]))
            tail++;
        memmove(text + head + 3, text + tail, len - tail + 1);
        memcpy(text + head, "...", 3);
        len = strlen(text);
    }
    if (len >= size && size > 0) {
        len = size - 1;
        while (len > 0 && is_continuation(text[len]))
            len--;
        text[len] = '\0';
    }
}

void message_vformat(char *text, size_t size, const char *fmt, va_list ap)
{
    vsnprintf(text, MESSAGE_ROOM, fmt, ap);
    message_fit(text, size);
}
