/* json_char.c - decoding the characters of JSON strings (json_char.h). */
#include "model/json_char.h"

static int hex_digit(unsigned char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    c = (unsigned char)(c | 0x20);
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

int json_next_char(const unsigned char *text, size_t size, size_t *i)
{
    if (*i >= size)
        return -2;
    unsigned char c = text[(*i)++];
    if (c == '"')
        return -1;
    if (c != '\\')
        return c < 0x80 ? c : 0x80;
    if (*i >= size)
        return -2;
    c = text[(*i)++];
    switch (c) {
    case 'b': return '\b';
    case 'f': return '\f';
    case 'n': return '\n';
    case 'r': return '\r';
    case 't': return '\t';
    case 'u': {
        int v = 0;
        for (int k = 0; k < 4; k++) {
            int d = *i < size ? hex_digit(text[(*i)++]) : -1;
            if (d < 0)
                return -2;
            v = v * 16 + d;
        }
        return v < 0x80 ? v : 0x80;
    }
    default:
        return c; /* \" \\ \/ and, leniently, anything else */
    }
}
