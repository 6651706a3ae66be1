/* json_scan.c - reading a glTF's JSON a value at a time (json_scan.h). */
#include <string.h>
#include "model/json_char.h"
#include "model/json_scan.h"
#include "model/text_scan.h"

void json_skip_space(json_scan *r)
{
    while (r->i < r->size && (r->t[r->i] == ' ' || r->t[r->i] == '\t' || r->t[r->i] == '\n' || r->t[r->i] == '\r'))
        r->i++;
}

bool json_take(json_scan *r, unsigned char c)
{
    json_skip_space(r);
    if (r->i >= r->size || r->t[r->i] != c)
        return false;
    r->i++;
    return true;
}

bool json_read_string(json_scan *r, char *key, size_t size)
{
    if (!json_take(r, '"'))
        return false;
    size_t n = 0;
    int c;
    while ((c = json_next_char(r->t, r->size, &r->i)) >= 0) {
        if (n + 1 < size)
            key[n++] = (char)c;
        else
            key[size - 2] = 1;
    }
    key[n] = '\0';
    return c == -1;
}

bool json_skip_value(json_scan *r)
{
    size_t depth = 0;
    char none[2];
    do {
        json_skip_space(r);
        if (r->i >= r->size)
            return false;
        unsigned char c = r->t[r->i];
        if (c == '"') {
            if (!json_read_string(r, none, sizeof none))
                return false;
        } else if (c == '{' || c == '[') {
            depth++;
            r->i++;
        } else if (c == '}' || c == ']' || c == ',' || c == ':') {
            if (depth == 0)
                return false;
            depth -= c == '}' || c == ']';
            r->i++;
        } else {
            size_t start = r->i;
            while (r->i < r->size && strchr("0123456789+-.eEtruefalsn", r->t[r->i]) && r->t[r->i])
                r->i++;
            if (r->i == start)
                return false;
        }
    } while (depth > 0);
    return true;
}

int json_next_item(json_scan *r, bool *first, unsigned char close)
{
    if (json_take(r, close))
        return 0;
    if (!*first && !json_take(r, ','))
        return -1;
    *first = false;
    return 1;
}

int json_next_member(json_scan *r, bool *first, char *key, size_t size)
{
    int n = json_next_item(r, first, '}');
    if (n <= 0)
        return n;
    return json_read_string(r, key, size) && json_take(r, ':') ? 1 : -1;
}

bool json_read_index(json_scan *r, uint64_t *v)
{
    json_skip_space(r);
    size_t start = r->i;
    bool negative = r->i < r->size && r->t[r->i] == '-';
    r->i += negative;
    uint64_t n = 0;
    /* Every digit is passed over, a number too large for an index included. */
    for (; r->i < r->size && r->t[r->i] >= '0' && r->t[r->i] <= '9'; r->i++)
        n = n > JSON_NO_INDEX / 10 - 1 ? JSON_NO_INDEX : n * 10 + (uint64_t)(r->t[r->i] - '0');
    bool integer = r->i > start + negative && (r->i >= r->size || !strchr(".eE", r->t[r->i]));
    r->i = start;
    *v = integer && !(negative && n != 0) ? n : JSON_NO_INDEX;
    return json_skip_value(r);
}

bool json_read_number(json_scan *r, bool *is_number, double *v)
{
    json_skip_space(r);
    size_t start = r->i;
    if (!json_skip_value(r))
        return false;
    /* scan_decimal reads more forms than JSON has ("+1", ".5", "inf"): the
     * value must start as a JSON number and be one number to its end. */
    const char *s = (const char *)r->t + start, *end = (const char *)r->t + r->i;
    bool starts = (s[0] >= '0' && s[0] <= '9') || (s[0] == '-' && end - s > 1 && s[1] >= '0' && s[1] <= '9');
    *is_number = starts && scan_decimal(s, end, v) == end;
    return true;
}

bool json_each_member(json_scan *r, void *ctx, json_member_fn on, const char *const *keys, int key_count)
{
    if (!json_take(r, '{'))
        return json_skip_value(r);
    bool first = true;
    uint32_t seen = 0;
    char member[48];
    int m;
    while ((m = json_next_member(r, &first, member, sizeof member)) > 0) {
        int k = 0;
        while (k < key_count && strcmp(member, keys[k]) != 0)
            k++;
        bool wanted = k < key_count && !(seen >> k & 1);
        seen |= wanted ? 1u << k : 0;
        if (!(wanted ? on(r, ctx, member) : json_skip_value(r)))
            return false;
    }
    return m == 0;
}

bool json_each_item(json_scan *r, void *ctx, json_item_fn on)
{
    if (!json_take(r, '['))
        return json_skip_value(r);
    bool first = true;
    int n;
    while ((n = json_next_item(r, &first, ']')) > 0)
        if (!on(r, ctx))
            return false;
    return n == 0;
}
