/* message_fit.c - shortening a message in its middle, so that a long path
 * or name never pushes the reason out of a glint_error, nor the file the
 * message is about. */
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

/* Length of the word text starts with: what the message is about. */
static size_t first_word(const char *text)
{
    size_t n = 0;
    while (text[n] && is_word_byte(text[n]))
        n++;
    return n;
}

/* The longest word of text from `from` on: its start in *start, its
 * length returned. */
static size_t longest_word(const char *text, size_t from, size_t *start)
{
    size_t best = 0;
    for (size_t i = from; text[i];) {
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

/* Replaces text[head, tail) with "...", moving head back and tail on to
 * the starts of characters; returns the new length. */
static size_t elide(char *text, size_t len, size_t head, size_t tail, size_t floor)
{
    while (head > floor && is_continuation(text[head]))
        head--;
    while (tail < len && is_continuation(text[tail]))
        tail++;
    memmove(text + head + 3, text + tail, len - tail + 1);
    memcpy(text + head, "...", 3);
    return strlen(text);
}

void message_fit(char *text, size_t size)
{
    size_t len = strlen(text), start = 0, n;
    /* The first word, the file the message is about, keeps its middle
     * unless it is itself long: the words after it (a path the file
     * names, a quoted name) go first. */
    size_t subject = first_word(text);
    size_t from = subject > size / 4 ? 0 : subject;
    while (len >= size && (n = longest_word(text, from, &start)) > MIN_KEPT + 3) {
        size_t excess = len - (size - 1) + 3;
        size_t keep = n > excess + MIN_KEPT ? n - excess : MIN_KEPT;
        len = elide(text, len, start + keep / 3, start + n - (keep - keep / 3), start);
    }
    /* Many short words (a name with spaces in it): the text after the
     * first word loses its middle, a third of the room before the "..."
     * and two thirds after it, so that the reason at the end stays. */
    subject = first_word(text);
    if (len >= size && size > subject + 3 + 2) {
        size_t room = size - 1 - 3 - subject;
        len = elide(text, len, subject + room / 3, len - (room - room / 3), subject);
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
