/* yaml_quick.c - the subset reader of yaml_quick.h: a recursive descent over
 * lines. Wherever it is not sure that libyaml reads the text the same way,
 * it stops with "not in the subset" and libyaml reads the file;
 * tests/fuzz/fuzz_scene.c checks on every input it takes that the tree is
 * libyaml's, node for node and mark for mark. */
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include "scenefile/yaml_quick.h"

#define NOT_OURS (-1)
/* Deeper text goes to libyaml and the tree builder, which report it; this
 * reader recurses, so it stops well before its stack would matter. */
#define MAX_NESTING 60
/* libyaml's simple keys end at 1024 characters. */
#define MAX_KEY 1000

typedef struct quick {
    const char *text;
    size_t size, pos;          /* pos: the byte being read */
    size_t line, line_start;   /* pos's line (0-based) and where that line starts */
    long indent;               /* the column of the current line's first character; -1 at the end */
    int depth;
    yaml_quick_sink sink;
    void *user;
    int status;                /* the sink's stop, or NOT_OURS */
} quick;

static bool not_ours(quick *q)
{
    if (!q->status)
        q->status = NOT_OURS;
    return false;
}

/* The byte at i, with the end of the text read as the end of a line. */
static char at(const quick *q, size_t i)
{
    return i < q->size ? q->text[i] : '\n';
}

static void skip_spaces(quick *q)
{
    while (at(q, q->pos) == ' ' && q->pos < q->size)
        q->pos++;
}

static bool give(quick *q, yaml_event_t *ev)
{
    int s = q->sink ? q->sink(q->user, ev) : 0;
    if (s)
        q->status = s;
    return !s;
}

static yaml_mark_t mark_at(const quick *q, size_t index)
{
    return (yaml_mark_t){.index = index, .line = q->line, .column = index - q->line_start};
}

/* A map or list starts at byte `index`; nesting past MAX_NESTING is not ours. */
static bool give_start(quick *q, bool map, bool flow)
{
    if (++q->depth > MAX_NESTING)
        return not_ours(q);
    if (!q->sink)
        return true;
    yaml_event_t ev = {.start_mark = mark_at(q, q->pos), .end_mark = mark_at(q, q->pos)};
    if (map) {
        ev.type = YAML_MAPPING_START_EVENT;
        ev.data.mapping_start.implicit = 1;
        ev.data.mapping_start.style = flow ? YAML_FLOW_MAPPING_STYLE : YAML_BLOCK_MAPPING_STYLE;
    } else {
        ev.type = YAML_SEQUENCE_START_EVENT;
        ev.data.sequence_start.implicit = 1;
        ev.data.sequence_start.style = flow ? YAML_FLOW_SEQUENCE_STYLE : YAML_BLOCK_SEQUENCE_STYLE;
    }
    return give(q, &ev);
}

static bool give_end(quick *q, bool map)
{
    q->depth--;
    if (!q->sink)
        return true;
    yaml_event_t ev = {.type = map ? YAML_MAPPING_END_EVENT : YAML_SEQUENCE_END_EVENT,
                       .start_mark = mark_at(q, q->pos), .end_mark = mark_at(q, q->pos)};
    return give(q, &ev);
}

static bool give_plain(quick *q, yaml_event_type_t type)
{
    yaml_event_t ev = {.type = type, .start_mark = mark_at(q, q->pos), .end_mark = mark_at(q, q->pos)};
    if (type == YAML_DOCUMENT_START_EVENT || type == YAML_DOCUMENT_END_EVENT)
        ev.data.document_start.implicit = 1;
    return give(q, &ev);
}

/* A scalar written from byte `start` (its quote, if any) whose value is
 * the `length` bytes at `value`. */
static bool give_scalar(quick *q, size_t start, size_t value, size_t length, yaml_scalar_style_t style)
{
    if (!q->sink)
        return true;
    yaml_event_t ev = {.type = YAML_SCALAR_EVENT, .start_mark = mark_at(q, start),
                       .end_mark = mark_at(q, value + length)};
    ev.data.scalar.value = (yaml_char_t *)(q->text + value);
    ev.data.scalar.length = length;
    ev.data.scalar.plain_implicit = style == YAML_PLAIN_SCALAR_STYLE;
    ev.data.scalar.quoted_implicit = style != YAML_PLAIN_SCALAR_STYLE;
    ev.data.scalar.style = style;
    return give(q, &ev);
}

/* From the start of a line on, to the first character of a line that is
 * not blank or a comment: sets indent to its column, or -1 at the end. */
static void find_content(quick *q)
{
    for (;;) {
        skip_spaces(q);
        if (at(q, q->pos) == '#')
            while (at(q, q->pos) != '\n')
                q->pos++;
        if (q->pos >= q->size) {
            q->indent = -1;
            return;
        }
        if (q->text[q->pos] != '\n') {
            q->indent = (long)(q->pos - q->line_start);
            return;
        }
        q->line++;
        q->line_start = ++q->pos;
    }
}

/* After a node's text: only spaces and a comment may end its line. Moves
 * to the next line's content. */
static bool end_line(quick *q)
{
    skip_spaces(q);
    if (at(q, q->pos) == '#' && q->pos > 0 && q->text[q->pos - 1] == ' ')
        while (at(q, q->pos) != '\n')
            q->pos++;
    if (at(q, q->pos) != '\n')
        return not_ours(q);
    if (q->pos >= q->size) {
        q->indent = -1;
        return true;
    }
    q->line++;
    q->line_start = ++q->pos;
    find_content(q);
    return true;
}

/* A block list's entry: '-' and a space or the line's end. */
static bool is_entry(const quick *q)
{
    return at(q, q->pos) == '-' && (at(q, q->pos + 1) == ' ' || at(q, q->pos + 1) == '\n');
}

static bool is_alnum(char c)
{
    return (unsigned)((c | 32) - 'a') < 26 || (unsigned)(c - '0') < 10;
}

/* A character of a key after its first: a letter, a digit, '_', '-', '.'
 * or a space. */
static bool is_key_char(char c)
{
    return is_alnum(c) || c == '_' || c == '-' || c == '.' || c == ' ';
}

/* The length of the plain key at byte i: a word (letters, digits, '_',
 * and after its first character also '-', '.' and inner spaces) followed
 * by ':' and a space (in a flow) or a space or the line's end (in a
 * block); 0 when there is none. */
static size_t key_length(const quick *q, size_t i, bool flow)
{
    size_t p = i;
    if (!is_alnum(at(q, p)) && at(q, p) != '_')
        return 0;
    while (is_key_char(at(q, p)))
        p++;
    char after = at(q, p + 1);
    if (p - i > MAX_KEY || at(q, p) != ':' || q->text[p - 1] == ' ' || (after != ' ' && (flow || after != '\n')))
        return 0;
    return p - i;
}

/* The plain key at pos (key_length) as a scalar, the reader moved past
 * its ':'; not ours when there is none. */
static bool give_key(quick *q, bool flow)
{
    size_t length = key_length(q, q->pos, flow);
    if (!length)
        return not_ours(q);
    if (!give_scalar(q, q->pos, q->pos, length, YAML_PLAIN_SCALAR_STYLE))
        return false;
    q->pos += length + 1;
    return true;
}

/* Whether a plain scalar may start with the byte at i: not with an
 * indicator, and with '-' only before a digit, a letter or a '.'. */
static bool plain_start(const quick *q, size_t i)
{
    char c = at(q, i);
    if (is_alnum(c) || c == '.' || c == '_' || c == '+')
        return true;
    if (c == '-')
        return is_alnum(at(q, i + 1)) || at(q, i + 1) == '.';
    switch (c) {
    case ' ': case '\n': case '?': case ':': case ',': case '[': case ']': case '{': case '}': case '#':
    case '&': case '*': case '!': case '|': case '>': case '\'': case '"': case '%': case '@': case '`':
        return false;
    default:
        return true;
    }
}

/* A quoted scalar on one line, without escapes. */
static bool quoted(quick *q)
{
    size_t start = q->pos, p = start + 1;
    char quote = q->text[start];
    while (at(q, p) != quote && at(q, p) != '\n' && !(quote == '"' && at(q, p) == '\\'))
        p++;
    if (at(q, p) != quote || p >= q->size || (quote == '\'' && at(q, p + 1) == '\''))
        return not_ours(q);
    q->pos = p + 1;
    return give_scalar(q, start, start + 1, p - start - 1,
                       quote == '"' ? YAML_DOUBLE_QUOTED_SCALAR_STYLE : YAML_SINGLE_QUOTED_SCALAR_STYLE);
}

/* A plain scalar in a block: the rest of its line, before a comment. */
static bool block_plain(quick *q)
{
    size_t start = q->pos, p = start, end = start;
    if (!plain_start(q, start))
        return not_ours(q);
    for (; at(q, p) != '\n'; p++) {
        char c = q->text[p];
        if (c == ':' && (at(q, p + 1) == ' ' || at(q, p + 1) == '\n'))
            return not_ours(q);
        if (c == '#' && q->text[p - 1] == ' ')
            break;
        if (c != ' ')
            end = p + 1;
    }
    q->pos = end;
    return give_scalar(q, start, start, end - start, YAML_PLAIN_SCALAR_STYLE);
}

/* A plain scalar in a flow, up to the ',', ']' or '}' after it. */
static bool flow_plain(quick *q)
{
    size_t start = q->pos, p = start, end = start;
    if (!plain_start(q, start))
        return not_ours(q);
    for (;; p++) {
        char c = at(q, p);
        if (is_alnum(c) || c == '.') {
            end = p + 1;
            continue;
        }
        switch (c) {
        case ',': case ']': case '}':
            q->pos = end;
            return give_scalar(q, start, start, end - start, YAML_PLAIN_SCALAR_STYLE);
        case '\n': case ':': case '[': case '{':
            return not_ours(q);
        case '#':
            if (q->text[p - 1] == ' ')
                return not_ours(q);
            break;
        case ' ':
            continue;
        }
        end = p + 1;
    }
}

/* Between the parts of a flow: spaces, line ends, and comments after a
 * space or at a line's start. */
static bool flow_space(quick *q)
{
    for (;;) {
        skip_spaces(q);
        if (at(q, q->pos) == '#') {
            if (q->pos == 0 || (q->text[q->pos - 1] != ' ' && q->text[q->pos - 1] != '\n'))
                return not_ours(q);
            while (at(q, q->pos) != '\n')
                q->pos++;
        }
        if (at(q, q->pos) != '\n' || q->pos >= q->size)
            return true;
        q->line++;
        q->line_start = ++q->pos;
    }
}

static bool flow_collection(quick *q);

static bool flow_value(quick *q)
{
    char c = at(q, q->pos);
    if (c == '{' || c == '[')
        return flow_collection(q);
    if (c == '"' || c == '\'')
        return quoted(q);
    return flow_plain(q);
}

/* A flow map or list; it may go on over lines, each part of it on one. */
static bool flow_collection(quick *q)
{
    bool map = q->text[q->pos] == '{';
    char close = map ? '}' : ']';
    if (!give_start(q, map, true))
        return false;
    q->pos++;
    if (!flow_space(q))
        return false;
    while (at(q, q->pos) != close) {
        if (map) {
            if (!give_key(q, true) || !flow_space(q))
                return false;
        }
        if (!flow_value(q) || !flow_space(q))
            return false;
        if (at(q, q->pos) == ',') {
            q->pos++;
            if (!flow_space(q))
                return false;
            if (at(q, q->pos) == close)
                return not_ours(q);
        } else if (at(q, q->pos) != close) {
            return not_ours(q);
        }
    }
    q->pos++;
    return give_end(q, map);
}

/* A node that starts after "key: " or "- " and ends its line. */
static bool inline_node(quick *q)
{
    char c = q->text[q->pos];
    bool good = c == '{' || c == '[' ? flow_collection(q) : c == '"' || c == '\'' ? quoted(q) : block_plain(q);
    return good && end_line(q);
}

static bool block_node(quick *q);
static bool block_list(quick *q, long indent);

/* The value of a block map's key at column `indent`, from just after its
 * ':': on its line, or on the lines below (more indented, or a list at
 * the key's own column). */
static bool block_value(quick *q, long indent)
{
    skip_spaces(q);
    if (at(q, q->pos) != '\n' && at(q, q->pos) != '#')
        return inline_node(q);
    if (!end_line(q))
        return false;
    if (q->indent > indent)
        return block_node(q);
    if (q->indent == indent && is_entry(q))
        return block_list(q, indent);
    return not_ours(q);
}

/* A block map whose keys are at column `indent`, from its first key. */
static bool block_map(quick *q, long indent)
{
    if (!give_start(q, true, false))
        return false;
    do {
        if (!give_key(q, false) || !block_value(q, indent))
            return false;
    } while (q->indent == indent);
    return q->indent < indent ? give_end(q, true) : not_ours(q);
}

/* One entry of a block list whose '-' is at column `indent`, from after
 * the '-'. */
static bool block_entry(quick *q, long indent)
{
    skip_spaces(q);
    if (at(q, q->pos) == '\n' || at(q, q->pos) == '#') {
        if (!end_line(q))
            return false;
        return q->indent > indent ? block_node(q) : not_ours(q);
    }
    if (is_entry(q))
        return not_ours(q);
    if (key_length(q, q->pos, false))
        return block_map(q, (long)(q->pos - q->line_start));
    return inline_node(q);
}

/* A block list whose '-' are at column `indent`, from its first '-'. */
static bool block_list(quick *q, long indent)
{
    if (!give_start(q, false, false))
        return false;
    do {
        q->pos++;
        if (!block_entry(q, indent))
            return false;
    } while (q->indent == indent && is_entry(q));
    return q->indent <= indent ? give_end(q, false) : not_ours(q);
}

/* A map or a list starting a line; anything else on a line of its own is
 * not ours. */
static bool block_node(quick *q)
{
    if (is_entry(q))
        return block_list(q, q->indent);
    if (key_length(q, q->pos, false))
        return block_map(q, q->indent);
    return not_ours(q);
}

static bool unprintable(char c)
{
    return ((unsigned char)c < 0x20 || (unsigned char)c > 0x7e) && c != '\n';
}

/* Whether every byte is printable ASCII or a line end: eight at a time,
 * and one at a time where eight hold a line end or anything else. */
static bool printable(const char *data, size_t size)
{
    const uint64_t ones = 0x0101010101010101u, highs = 0x8080808080808080u;
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        uint64_t w;
        memcpy(&w, data + i, 8);
        /* A byte below 0x20, or above 0x7e, sets its high bit here. */
        if ((((w - ones * 0x20) & ~w) | ((w + ones * (0x7f - 0x7e)) | w)) & highs) {
            for (size_t k = i; k < i + 8; k++)
                if (unprintable(data[k]))
                    return false;
        }
    }
    for (; i < size; i++)
        if (unprintable(data[i]))
            return false;
    return true;
}

int yaml_quick_parse(const char *data, size_t size, yaml_quick_sink sink, void *user)
{
    if (!printable(data, size))
        return NOT_OURS;
    quick q = {.text = data, .size = size, .sink = sink, .user = user};
    if (!give_plain(&q, YAML_STREAM_START_EVENT))
        return q.status;
    find_content(&q);
    /* An empty text, and a root indented, are libyaml's. */
    if (q.indent != 0)
        return NOT_OURS;
    bool good = give_plain(&q, YAML_DOCUMENT_START_EVENT) && block_node(&q);
    if (good && q.indent != -1)
        good = not_ours(&q);
    good = good && give_plain(&q, YAML_DOCUMENT_END_EVENT) && give_plain(&q, YAML_STREAM_END_EVENT);
    return good ? 0 : q.status;
}
