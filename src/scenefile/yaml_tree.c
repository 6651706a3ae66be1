/* yaml_tree.c - libyaml's events folded into a tree of positioned nodes,
 * kept in one arena: a scene of a million objects is some twelve million
 * nodes, so each costs only its own bytes; and with a ystream, the root's
 * list handed over item by item, each item's nodes given back once read. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>
#include "core/array.h"
#include "core/error.h"
#include "core/id_table.h"
#include "scenefile/yaml_hints.h"
#include "scenefile/yaml_quick.h"
#include "scenefile/yaml_tree.h"

/* Deeper nesting than this is refused: nothing in a scene needs it, and the
 * walkers recurse. */
#define YAML_MAX_DEPTH 64
/* Nodes of one file held at once: a million spheres written one a line
 * take 12 million, or, their list streamed (ystream), those before the
 * list and one sphere's. About 60 bytes each, so a 64 MiB file of
 * one-digit numbers stops here at about 1 GB; a streamed list's items
 * given back no longer count, so what stops is only what is held. */
#define YAML_MAX_NODES (1L << 24)
#define YAML_MAX_ANCHORS 100000

typedef struct builder {
    ydoc *doc;
    ynode *stack[YAML_MAX_DEPTH];
    size_t base[YAML_MAX_DEPTH];   /* where each open node's items start in pending */
    int depth;
    ynode **pending;           /* the items of the open nodes, innermost last */
    size_t pending_count, pending_cap;
    long *alias_nodes;         /* nodes the aliases of the scene add */
    long alias_start;          /* and how many before this document */
    id_table anchor_ids;       /* the first anchor of each name, by name */
    uint32_t *latest;          /* for each first anchor: the last of its name */
    size_t latest_cap;
    int documents;
    glint_error *err;
    const char *data;          /* the text, for the hints of yaml_hints.h */
    size_t size;
    int flow_level;            /* depth of the outermost open {...} or [...], or -1 */
    yaml_mark_t flow_start;    /* and where it starts */
    const ystream *stream;     /* or NULL */
    enum { LIST_AHEAD, LIST_OPEN, LIST_READ } list;  /* the streamed list */
    arena_point item_start;    /* where its next item's nodes will start */
    long item_nodes;           /* and the counts before that item */
    int item_anchors, item_unknown;
} builder;

/* The nodes of a streamed list's items (ystream) sit at depth 2: in the
 * list, in the root mapping. */
#define ITEM_DEPTH 2

static glint_status fail_at(builder *b, yaml_mark_t mark, const char *what)
{
    return error_set(b->err, GLINT_ERR_INVALID, "%s:%zu:%zu: %s", b->doc->name, mark.line + 1, mark.column + 1,
                     what);
}

static glint_status out_of_memory(builder *b)
{
    return error_set(b->err, GLINT_ERR_NOMEM, "%s: out of memory reading the scene", b->doc->name);
}

/* A copy of len bytes of text in the document's arena, NUL-terminated. */
static char *arena_text(ydoc *d, const void *text, size_t len)
{
    char *copy = len < SIZE_MAX ? arena_alloc(&d->mem, len + 1) : NULL;
    if (copy) {
        memcpy(copy, text, len);
        copy[len] = '\0';
    }
    return copy;
}

static ynode *new_node(builder *b, ynode_kind kind, yaml_mark_t mark)
{
    ydoc *d = b->doc;
    if (d->node_count >= YAML_MAX_NODES)
        return NULL;
    ynode *n = arena_alloc(&d->mem, sizeof *n);
    if (!n)
        return NULL;
    *n = (ynode){.kind = kind, .file = d->name, .line = (int)mark.line + 1, .column = (int)mark.column + 1,
                 .expanded = 1};
    d->node_count++;
    return n;
}

/* Why new_node gave no node. */
static glint_status no_node(builder *b, yaml_mark_t mark)
{
    return b->doc->node_count >= YAML_MAX_NODES ? fail_at(b, mark, "too many nodes in one file") : out_of_memory(b);
}

/* Adds name and n to a list of anchors or unknown aliases. */
static glint_status add_anchor(builder *b, yanchor **list, int *count, size_t *cap, const char *name, ynode *n)
{
    if (*count >= YAML_MAX_ANCHORS)
        return error_set(b->err, GLINT_ERR_INVALID, "%s:%d:%d: too many anchors (limit %d)", b->doc->name, n->line,
                         n->column, YAML_MAX_ANCHORS);
    if (!array_reserve((void **)list, cap, (size_t)*count + 1, sizeof **list))
        return out_of_memory(b);
    char *copy = strdup(name);
    if (!copy)
        return out_of_memory(b);
    (*list)[(*count)++] = (yanchor){copy, n};
    return GLINT_OK;
}

/* The anchor table's comparison of a stored anchor with a name. */
static bool anchor_equal(const void *keys, uint32_t id, const void *name)
{
    return strcmp(((const yanchor *)keys)[id].name, name) == 0;
}

/* Lists anchor `name` of n, and indexes it by name: a hostile file of
 * 100,000 anchors and a million aliases is looked up in linear time. */
static glint_status remember_anchor(builder *b, const yaml_char_t *name, ynode *n)
{
    ydoc *d = b->doc;
    if (!name)
        return GLINT_OK;
    glint_status s = add_anchor(b, &d->anchors, &d->anchor_count, &d->anchor_cap, (const char *)name, n);
    if (s)
        return s;
    uint32_t id = (uint32_t)d->anchor_count - 1, first;
    if (!id_table_intern(&b->anchor_ids, id_hash_text((const char *)name), name, id, anchor_equal, d->anchors, &first) ||
        !array_reserve((void **)&b->latest, &b->latest_cap, (size_t)id + 1, sizeof *b->latest))
        return out_of_memory(b);
    /* A later anchor of the same name hides the earlier one, as in YAML. */
    b->latest[first] = id;
    return GLINT_OK;
}

static ynode *find_anchor(const builder *b, const char *name)
{
    uint32_t first;
    if (!id_table_find(&b->anchor_ids, id_hash_text(name), name, anchor_equal, b->doc->anchors, &first))
        return NULL;
    return b->doc->anchors[b->latest[first]].node;
}

/* Stops a streamed parse at node n: a hook asked, or the file goes on
 * where the hooks cannot follow. */
static glint_status stopped(builder *b, const ynode *n, const char *why)
{
    return error_set(b->err, GLINT_ERR_CANCELLED, "%s:%d:%d: %s", b->doc->name, n->line, n->column, why);
}

/* Where the streamed list's next item starts: the arena and the counts. */
static void mark_item_start(builder *b)
{
    ydoc *d = b->doc;
    b->item_start = arena_mark(&d->mem);
    b->item_nodes = d->node_count;
    b->item_anchors = d->anchor_count;
    b->item_unknown = d->unknown_count;
}

/* Whether the sequence about to start, with anchor `anchor`, is the list
 * to stream: the value of the root mapping's key, the first such. */
static bool starts_list(const builder *b, const yaml_char_t *anchor)
{
    if (!b->stream || b->list != LIST_AHEAD || anchor || b->depth != 1 || b->stack[0]->kind != YNODE_MAPPING ||
        (b->pending_count - b->base[0]) % 2 == 0)
        return false;
    const ynode *key = b->pending[b->pending_count - 1];
    return key->kind == YNODE_SCALAR && strcmp(key->value, b->stream->key) == 0;
}

/* The streamed list has just opened: its begin hook sees the root so far,
 * whose items are still gathering in pending. */
static glint_status open_list(builder *b)
{
    ynode *root = b->stack[0], *list = b->stack[1];
    root->items = b->pending + b->base[0];
    root->count = (int)(b->base[1] - b->base[0]);
    bool go_on = b->stream->begin(b->stream->user, root);
    root->items = NULL;
    root->count = 0;
    b->list = LIST_OPEN;
    mark_item_start(b);
    return go_on ? GLINT_OK : stopped(b, list, "the reader stopped at the list");
}

/* An item of the streamed list, the last of pending, is complete: the item
 * hook reads it, then it leaves the list, and its nodes are given back
 * unless something outside it points into them (ystream). */
static glint_status item_read(builder *b)
{
    ydoc *d = b->doc;
    ynode *item = b->pending[--b->pending_count];
    bool go_on = b->stream->item(b->stream->user, item);
    if (!go_on)
        return stopped(b, item, "the reader stopped at this item");
    if (d->anchor_count == b->item_anchors && d->unknown_count == b->item_unknown) {
        arena_rollback(&d->mem, b->item_start);
        d->node_count = b->item_nodes;
    } else {
        mark_item_start(b);
    }
    return GLINT_OK;
}

/* Hangs n under the open container, or makes it the root. */
static glint_status attach(builder *b, ynode *n, yaml_mark_t mark)
{
    (void)mark;
    if (b->depth == 0) {
        b->doc->root = n;
        return GLINT_OK;
    }
    if (b->list == LIST_READ && b->depth == 1)
        return stopped(b, n, "a key of the root after the streamed list");
    if (!array_reserve((void **)&b->pending, &b->pending_cap, b->pending_count + 1, sizeof *b->pending))
        return out_of_memory(b);
    b->pending[b->pending_count++] = n;
    /* A scalar or an alias is complete at once; a map or list at its end. */
    if (b->list == LIST_OPEN && b->depth == ITEM_DEPTH && n->complete)
        return item_read(b);
    return GLINT_OK;
}

/* Closes the innermost open node: its items, gathered in pending, move to
 * a list of their own, and its size with aliases copied out is summed. */
static glint_status on_end(builder *b)
{
    ynode *n = b->stack[--b->depth];
    size_t base = b->base[b->depth], count = b->pending_count - base;
    if (count) {
        n->items = arena_alloc(&b->doc->mem, count * sizeof *n->items);
        if (!n->items)
            return out_of_memory(b);
        memcpy(n->items, b->pending + base, count * sizeof *n->items);
    }
    n->count = (int)count;
    b->pending_count = base;
    long expanded = 1;
    for (size_t i = 0; i < count && expanded < INT_MAX; i++)
        expanded += n->items[i]->expanded;
    n->expanded = expanded < INT_MAX ? (int)expanded : INT_MAX;
    n->complete = true;
    if (b->depth == b->flow_level)
        b->flow_level = -1;
    if (b->list == LIST_OPEN && b->depth == ITEM_DEPTH)
        return item_read(b);
    if (b->list == LIST_OPEN && b->depth == ITEM_DEPTH - 1)
        b->list = LIST_READ;
    return GLINT_OK;
}

/* An empty value followed by "#0000ff" on its line: the colour became a
 * comment. Notes it at the '#'; true when out of memory. */
static bool note_hidden_colour(builder *b, ynode *n, yaml_mark_t mark)
{
    char msg[256];
    long at = yaml_hidden_colour(b->data, b->size, mark.index, msg, sizeof msg);
    if (at < 0)
        return false;
    n->column += (int)at;
    n->note = arena_text(b->doc, msg, strlen(msg));
    return !n->note;
}

/* The message and place of a byte libyaml's reader refuses (NUL, control
 * characters, text not in UTF-8): the reader sets only the byte offset,
 * its mark stays at 1:1. A bad byte after a UTF-8 lead byte is placed at
 * the lead, the character the user wrote. */
static void reader_message(const builder *b, const yaml_parser_t *p, yaml_mark_t *mark, char *msg, size_t size)
{
    const unsigned char *data = (const unsigned char *)b->data;
    const char *problem = p->problem ? p->problem : "";
    size_t at = p->problem_offset;
    bool utf8 = strstr(problem, "UTF-8") || strstr(problem, "Unicode");
    if (strstr(problem, "trailing"))
        for (int back = 0; back < 3 && at > 0 && data[at] < 0xC0; back++)
            at--;
    *mark = (yaml_mark_t){.index = at};
    yaml_advance(b->data, 0, at, &mark->line, &mark->column);
    if (utf8)
        snprintf(msg, size, "the file is not UTF-8 text (byte 0x%02x): save it as UTF-8", data[at]);
    else if (data[at] == 0)
        snprintf(msg, size, "a NUL byte: scene files are text");
    else
        snprintf(msg, size, "control character 0x%02x: scene files are text", data[at]);
}

/* libyaml's message for a syntax error, in plain words where it would
 * puzzle; sets *mark to where the mistake is. */
static void syntax_message(const builder *b, const yaml_parser_t *p, yaml_mark_t *mark, char *msg, size_t size)
{
    const char *problem = p->problem ? p->problem : "unknown";
    *mark = p->problem_mark;
    if (p->error == YAML_READER_ERROR && p->problem_offset < b->size) {
        reader_message(b, p, mark, msg, size);
        return;
    }
    if (strstr(problem, "cannot start any token") && yaml_tab_indent(b->data, b->size, mark->index)) {
        snprintf(msg, size, "YAML forbids tabs for indentation: indent with spaces");
        return;
    }
    long hash = b->flow_level < 0 || mark->index > b->size ? -1
                : yaml_hidden_colour_between(b->data, b->flow_start.index, mark->index, msg, size);
    if (hash >= 0) {
        *mark = b->flow_start;
        yaml_advance(b->data, b->flow_start.index, b->flow_start.index + (size_t)hash, &mark->line, &mark->column);
        return;
    }
    if (p->context)
        snprintf(msg, size, "syntax error: %s %s", problem, p->context);
    else
        snprintf(msg, size, "syntax error: %s", problem);
}

static glint_status on_scalar(builder *b, const yaml_event_t *ev)
{
    ynode *n = new_node(b, YNODE_SCALAR, ev->start_mark);
    if (!n)
        return no_node(b, ev->start_mark);
    n->value = arena_text(b->doc, ev->data.scalar.value, ev->data.scalar.length);
    if (!n->value)
        return out_of_memory(b);
    if (strlen(n->value) != ev->data.scalar.length)
        return fail_at(b, ev->start_mark, "a NUL character inside a value");
    n->quoted = ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE;
    n->complete = true;
    if (!n->quoted && !n->value[0] && note_hidden_colour(b, n, ev->start_mark))
        return out_of_memory(b);
    glint_status s = remember_anchor(b, ev->data.scalar.anchor, n);
    return s ? s : attach(b, n, ev->start_mark);
}

static glint_status on_start(builder *b, const yaml_event_t *ev, ynode_kind kind, const yaml_char_t *anchor_name,
                             bool flow)
{
    if (b->depth >= YAML_MAX_DEPTH)
        return fail_at(b, ev->start_mark, "nesting too deep (limit 64 levels)");
    if (flow && b->flow_level < 0) {
        b->flow_level = b->depth;
        b->flow_start = ev->start_mark;
    }
    bool list = kind == YNODE_SEQUENCE && starts_list(b, anchor_name);
    ynode *n = new_node(b, kind, ev->start_mark);
    if (!n)
        return no_node(b, ev->start_mark);
    glint_status s = remember_anchor(b, anchor_name, n);
    if (!s)
        s = attach(b, n, ev->start_mark);
    if (!s) {
        b->stack[b->depth] = n;
        b->base[b->depth++] = b->pending_count;
    }
    return !s && list ? open_list(b) : s;
}

static glint_status on_alias(builder *b, const yaml_event_t *ev)
{
    const char *name = (const char *)ev->data.alias.anchor;
    ynode *target = find_anchor(b, name);
    char msg[256];
    if (!target) {
        /* An empty node stands in, listed for the caller to explain. */
        ynode *n = new_node(b, YNODE_SCALAR, ev->start_mark);
        if (!n)
            return no_node(b, ev->start_mark);
        if (!(n->value = arena_text(b->doc, "", 0)))
            return out_of_memory(b);
        n->complete = true;
        ydoc *d = b->doc;
        glint_status s = add_anchor(b, &d->unknown, &d->unknown_count, &d->unknown_cap, name, n);
        return s ? s : attach(b, n, ev->start_mark);
    }
    if (!target->complete) {
        snprintf(msg, sizeof msg, "alias '*%.200s' is inside the node it names", name);
        return fail_at(b, ev->start_mark, msg);
    }
    /* The alias stands for a copy of its node: count what that copy adds. */
    *b->alias_nodes += target->expanded;
    if (*b->alias_nodes > YAML_MAX_ALIAS_NODES) {
        snprintf(msg, sizeof msg, "scene too large after alias expansion (limit %ld nodes)", YAML_MAX_ALIAS_NODES);
        return fail_at(b, ev->start_mark, msg);
    }
    return attach(b, target, ev->start_mark);
}

static glint_status on_event(builder *b, const yaml_event_t *ev, bool *done)
{
    switch (ev->type) {
    case YAML_DOCUMENT_START_EVENT:
        if (++b->documents > 1)
            return fail_at(b, ev->start_mark, "only one YAML document per file");
        return GLINT_OK;
    case YAML_SCALAR_EVENT:
        return on_scalar(b, ev);
    case YAML_ALIAS_EVENT:
        return on_alias(b, ev);
    case YAML_SEQUENCE_START_EVENT:
        return on_start(b, ev, YNODE_SEQUENCE, ev->data.sequence_start.anchor,
                        ev->data.sequence_start.style == YAML_FLOW_SEQUENCE_STYLE);
    case YAML_MAPPING_START_EVENT:
        return on_start(b, ev, YNODE_MAPPING, ev->data.mapping_start.anchor,
                        ev->data.mapping_start.style == YAML_FLOW_MAPPING_STYLE);
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT:
        return on_end(b);
    case YAML_STREAM_END_EVENT:
        *done = true;
        return GLINT_OK;
    default:
        return GLINT_OK;
    }
}

/* libyaml's events, each to the builder, up to the stream's end or the
 * first problem. */
static glint_status parse_with_libyaml(builder *b, const char *data, size_t size)
{
    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser))
        return out_of_memory(b);
    yaml_parser_set_input_string(&parser, (const unsigned char *)data, size);
    glint_status s = GLINT_OK;
    bool done = false;
    while (!s && !done) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&parser, &ev)) {
            if (parser.error == YAML_MEMORY_ERROR) {
                s = out_of_memory(b);
                break;
            }
            char msg[400];
            yaml_mark_t mark;
            syntax_message(b, &parser, &mark, msg, sizeof msg);
            s = fail_at(b, mark, msg);
            break;
        }
        s = on_event(b, &ev, &done);
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&parser);
    return s;
}

/* yaml_quick_parse's sink: the builder. */
static int take_quick_event(void *user, const yaml_event_t *ev)
{
    bool done = false;
    return (int)on_event(user, ev, &done);
}

static bool quick_reader = true;

void ydoc_use_quick_reader(bool on)
{
    quick_reader = on;
}

glint_status ydoc_parse(ydoc *doc, const char *data, size_t size, const char *name, long *alias_nodes,
                        const ystream *stream, glint_error *err)
{
    memset(doc, 0, sizeof *doc);
    builder b = {.doc = doc, .err = err, .data = data, .size = size, .flow_level = -1, .alias_nodes = alias_nodes,
                 .alias_start = *alias_nodes, .stream = stream};
    doc->name = strdup(name);
    if (!doc->name)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory reading '%s'", name);
    /* The quick reader's dry run says whether the text is all its own, so
     * that the builder never sees half a file from it; given the same text
     * its second run cannot then refuse it, and only the builder's status
     * can come back. */
    glint_status s = quick_reader && yaml_quick_parse(data, size, NULL, NULL) == 0
                         ? (glint_status)yaml_quick_parse(data, size, take_quick_event, &b)
                         : parse_with_libyaml(&b, data, size);
    free(b.pending);
    free(b.latest);
    id_table_free(&b.anchor_ids);
    if (s) {
        *alias_nodes = b.alias_start;
        ydoc_free(doc);
    }
    return s;
}

static bool same_text(const char *a, const char *b)
{
    return a == b || (a && b && strcmp(a, b) == 0);
}

bool ynode_same(const ynode *a, const ynode *b)
{
    if (!a || !b)
        return a == b;
    bool same = a->kind == b->kind && a->quoted == b->quoted && a->line == b->line && a->column == b->column &&
                a->count == b->count && a->expanded == b->expanded && same_text(a->value, b->value) &&
                same_text(a->note, b->note);
    for (int i = 0; same && i < a->count; i++)
        same = ynode_same(a->items[i], b->items[i]);
    return same;
}

void ydoc_free(ydoc *doc)
{
    arena_free(&doc->mem);
    for (int i = 0; i < doc->anchor_count; i++)
        free(doc->anchors[i].name);
    free(doc->anchors);
    for (int i = 0; i < doc->unknown_count; i++)
        free(doc->unknown[i].name);
    free(doc->unknown);
    free(doc->name);
    memset(doc, 0, sizeof *doc);
}

const char *ynode_describe(const ynode *n)
{
    if (n->kind == YNODE_SEQUENCE)
        return "a list";
    if (n->kind == YNODE_MAPPING)
        return "a map";
    if (!n->quoted && (n->value[0] == '\0' || strcmp(n->value, "~") == 0 || strcmp(n->value, "null") == 0))
        return "nothing";
    char *end;
    strtod(n->value, &end);
    if (!n->quoted && end != n->value && *end == '\0')
        return "a number";
    return "text";
}
