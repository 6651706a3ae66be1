/* yaml_tree.c - libyaml's events folded into a tree of positioned nodes. */
#include <stdlib.h>
#include <string.h>
#include <yaml.h>
#include "core/array.h"
#include "core/error.h"
#include "scenefile/yaml_hints.h"
#include "scenefile/yaml_tree.h"

/* Deeper nesting than this is refused: nothing in a scene needs it, and the
 * walkers recurse. */
#define YAML_MAX_DEPTH 64
#define YAML_MAX_NODES 2000000
#define YAML_MAX_ANCHORS 100000

typedef struct builder {
    ydoc *doc;
    ynode *stack[YAML_MAX_DEPTH];
    int depth;
    int documents;
    glint_error *err;
    const char *data;          /* the text, for the hints of yaml_hints.h */
    size_t size;
    int flow_level;            /* depth of the outermost open {...} or [...], or -1 */
    yaml_mark_t flow_start;    /* and where it starts */
} builder;

static glint_status fail_at(builder *b, yaml_mark_t mark, const char *what)
{
    return error_set(b->err, GLINT_ERR_INVALID, "%s:%zu:%zu: %s", b->doc->name, mark.line + 1, mark.column + 1,
                     what);
}

static glint_status out_of_memory(builder *b)
{
    return error_set(b->err, GLINT_ERR_NOMEM, "%s: out of memory reading the scene", b->doc->name);
}

static bool push_item(ynode *parent, ynode *child)
{
    if (!array_reserve((void **)&parent->items, &parent->cap, (size_t)parent->count + 1, sizeof *parent->items))
        return false;
    parent->items[parent->count++] = child;
    return true;
}

static ynode *new_node(builder *b, ynode_kind kind, yaml_mark_t mark)
{
    ydoc *d = b->doc;
    if (d->node_count >= YAML_MAX_NODES)
        return NULL;
    if (!array_reserve((void **)&d->nodes, &d->node_cap, (size_t)d->node_count + 1, sizeof *d->nodes))
        return NULL;
    ynode *n = calloc(1, sizeof *n);
    if (!n)
        return NULL;
    n->kind = kind;
    n->file = d->name;
    n->line = (int)mark.line + 1;
    n->column = (int)mark.column + 1;
    d->nodes[d->node_count++] = n;
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

static glint_status remember_anchor(builder *b, const yaml_char_t *name, ynode *n)
{
    ydoc *d = b->doc;
    return name ? add_anchor(b, &d->anchors, &d->anchor_count, &d->anchor_cap, (const char *)name, n) : GLINT_OK;
}

static ynode *find_anchor(const builder *b, const char *name)
{
    /* A later anchor of the same name hides the earlier one, as in YAML. */
    for (int i = b->doc->anchor_count - 1; i >= 0; i--)
        if (strcmp(b->doc->anchors[i].name, name) == 0)
            return b->doc->anchors[i].node;
    return NULL;
}

/* Hangs n under the open container, or makes it the root. */
static glint_status attach(builder *b, ynode *n, yaml_mark_t mark)
{
    if (b->depth == 0) {
        b->doc->root = n;
        return GLINT_OK;
    }
    return push_item(b->stack[b->depth - 1], n) ? GLINT_OK : out_of_memory(b);
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
    n->note = strdup(msg);
    return !n->note;
}

/* libyaml's message for a syntax error, in plain words where it would
 * puzzle; sets *mark to where the mistake is. */
static void syntax_message(const builder *b, const yaml_parser_t *p, yaml_mark_t *mark, char *msg, size_t size)
{
    const char *problem = p->problem ? p->problem : "unknown";
    *mark = p->problem_mark;
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
    n->value = malloc(ev->data.scalar.length + 1);
    if (!n->value)
        return out_of_memory(b);
    memcpy(n->value, ev->data.scalar.value, ev->data.scalar.length);
    n->value[ev->data.scalar.length] = '\0';
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
    ynode *n = new_node(b, kind, ev->start_mark);
    if (!n)
        return no_node(b, ev->start_mark);
    glint_status s = remember_anchor(b, anchor_name, n);
    if (!s)
        s = attach(b, n, ev->start_mark);
    if (!s)
        b->stack[b->depth++] = n;
    return s;
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
        if (!(n->value = strdup("")))
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
        b->stack[--b->depth]->complete = true;
        if (b->depth == b->flow_level)
            b->flow_level = -1;
        return GLINT_OK;
    case YAML_STREAM_END_EVENT:
        *done = true;
        return GLINT_OK;
    default:
        return GLINT_OK;
    }
}

glint_status ydoc_parse(ydoc *doc, const char *data, size_t size, const char *name, glint_error *err)
{
    memset(doc, 0, sizeof *doc);
    builder b = {.doc = doc, .err = err, .data = data, .size = size, .flow_level = -1};
    doc->name = strdup(name);
    if (!doc->name)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory reading '%s'", name);
    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser))
        return out_of_memory(&b);
    yaml_parser_set_input_string(&parser, (const unsigned char *)data, size);
    glint_status s = GLINT_OK;
    bool done = false;
    while (!s && !done) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&parser, &ev)) {
            char msg[400];
            yaml_mark_t mark;
            syntax_message(&b, &parser, &mark, msg, sizeof msg);
            s = fail_at(&b, mark, msg);
            break;
        }
        s = on_event(&b, &ev, &done);
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&parser);
    if (s)
        ydoc_free(doc);
    return s;
}

void ydoc_free(ydoc *doc)
{
    for (int i = 0; i < doc->node_count; i++) {
        free(doc->nodes[i]->value);
        free(doc->nodes[i]->note);
        free(doc->nodes[i]->items);
        free(doc->nodes[i]);
    }
    free(doc->nodes);
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
