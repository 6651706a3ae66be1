/* yaml_hints.c - finding, in a scene file's text, the YAML mistakes that
 * libyaml reports in its own terms (yaml_hints.h). */
#include <stdio.h>
#include <string.h>
#include "scenefile/yaml_hints.h"

static bool is_hex(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

static bool is_space(char c) { return c == ' ' || c == '\t'; }

/* The key written before the ':' that comes before data[at] (spaces
 * between), as "key: " into buf; "" when there is none. */
static void key_before(const char *data, size_t at, char *buf, size_t size)
{
    size_t i = at;
    while (i > 0 && is_space(data[i - 1]))
        i--;
    buf[0] = '\0';
    if (i == 0 || data[i - 1] != ':')
        return;
    i--;
    while (i > 0 && is_space(data[i - 1]))
        i--;
    size_t end = i;
    while (i > 0 && !is_space(data[i - 1]) && !strchr("{[,\n\r", data[i - 1]))
        i--;
    if (i < end)
        snprintf(buf, size, "%.*s: ", (int)(end - i < 80 ? end - i : 80), data + i);
}

long yaml_hidden_colour(const char *data, size_t size, size_t at, char *msg, size_t msg_size)
{
    size_t i = at;
    while (i < size && is_space(data[i]))
        i++;
    if (i >= size || data[i] != '#')
        return -1;
    size_t digits = 0;
    while (i + 1 + digits < size && is_hex(data[i + 1 + digits]))
        digits++;
    size_t end = i + 1 + digits;
    /* The colour ends its word: "#0000ff," is one, "#addition" is not. */
    bool ended = end == size || strchr(" \t\r\n,}]", data[end]);
    if (digits < 3 || digits > 8 || !ended)
        return -1;
    char key[100];
    key_before(data, i, key, sizeof key);
    snprintf(msg, msg_size, "'#' starts a comment in YAML: write the colour in quotes, %s\"%.*s\"", key,
             (int)(digits + 1), data + i);
    return (long)(i - at);
}

long yaml_hidden_colour_between(const char *data, size_t from, size_t to, char *msg, size_t msg_size)
{
    char quote = 0;
    for (size_t i = from; i < to; i++) {
        char c = data[i], before = i > from ? data[i - 1] : ' ';
        if (quote) {
            /* '' inside single quotes and \" inside double ones are not the end. */
            if (c == '\\' && quote == '"')
                i++;
            else if (c == quote && !(quote == '\'' && i + 1 < to && data[i + 1] == '\''))
                quote = 0;
            else if (c == quote)
                i++;
        } else if ((c == '"' || c == '\'') && (is_space(before) || strchr("{[,:\n\r", before))) {
            quote = c; /* a quote opens a scalar only where a token starts */
        } else if (c == '#' && (is_space(before) || before == '\n' || before == '\r') &&
                   yaml_hidden_colour(data, to, i, msg, msg_size) == 0) {
            return (long)(i - from);
        }
    }
    return -1;
}

void yaml_advance(const char *data, size_t from, size_t to, size_t *line, size_t *column)
{
    for (size_t i = from; i < to; i++) {
        if (data[i] == '\n') {
            ++*line;
            *column = 0;
        } else if (((unsigned char)data[i] & 0xC0) != 0x80) {
            ++*column; /* one for each character's first byte */
        }
    }
}

bool yaml_tab_indent(const char *data, size_t size, size_t at)
{
    if (at >= size || data[at] != '\t')
        return false;
    for (size_t i = at; i > 0 && data[i - 1] != '\n' && data[i - 1] != '\r'; i--)
        if (!is_space(data[i - 1]))
            return false;
    return true;
}
