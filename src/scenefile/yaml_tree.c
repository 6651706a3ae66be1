/* yaml_tree.c - libyaml's events folded into a tree of positioned nodes. */
#include <stdlib.h>
#include <string.h>
#include <yaml.h>
#include "core/array.h"
#include "core/error.h"
#include "scenefile/yaml_tree.h"

/* Deeper nesting than this is refused: nothing in a scene needs it, and the
 * walkers recurse. */
#define YAML_MAX_DEPTH 64
#define YAML_MAX_NODES 2000000
#define YAML_MAX_ANCHORS 100000

typedef struct anchor {
    char *name;
    ynode *node;
} anchor;

typedef struct builder {
    ydoc *doc;
    ynode *stack[YAML_MAX_DEPTH];
    int depth;
    anchor *anchors;
    int anchor_count;
    size_t anchor_cap;
    int documents;
    glint_error *err;
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

static glint_status remember_anchor(builder *b, const yaml_char_t *name, ynode *n)
{
    if (!name)
        return GLINT_OK;
    if (b->anchor_count >= YAML_MAX_ANCHORS)
        return error_set(b->err, GLINT_ERR_INVALID, "%s:%d:%d: too many anchors (limit %d)", b->doc->name, n->line,
                         n->column, YAML_MAX_ANCHORS);
    if (!array_reserve((void **)&b->anchors, &b->anchor_cap, (size_t)b->anchor_count + 1, sizeof *b->anchors))
        return out_of_memory(b);
    char *copy = strdup((const char *)name);
    if (!copy)
        return out_of_memory(b);
    /* A later anchor of the same name hides the earlier one, as in YAML. */
    b->anchors[b->anchor_count++] = (anchor){copy, n};
    return GLINT_OK;
}

static ynode *find_anchor(const builder *b, const char *name)
{
    for (int i = b->anchor_count - 1; i >= 0; i--)
        if (strcmp(b->anchors[i].name, name) == 0)
            return b->anchors[i].node;
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

static glint_status on_scalar(builder *b, const yaml_event_t *ev)
{
    ynode *n = new_node(b, YNODE_SCALAR, ev->start_mark);
    if (!n)
        return b->doc->node_count >= YAML_MAX_NODES ? fail_at(b, ev->start_mark, "too many nodes in one file")
                                                    : out_of_memory(b);
    n->value = malloc(ev->data.scalar.length + 1);
    if (!n->value)
        return out_of_memory(b);
    memcpy(n->value, ev->data.scalar.value, ev->data.scalar.length);
    n->value[ev->data.scalar.length] = '\0';
    if (strlen(n->value) != ev->data.scalar.length)
        return fail_at(b, ev->start_mark, "a NUL character inside a value");
    n->quoted = ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE;
    n->complete = true;
    glint_status s = remember_anchor(b, ev->data.scalar.anchor, n);
    return s ? s : attach(b, n, ev->start_mark);
}

static glint_status on_start(builder *b, const yaml_event_t *ev, ynode_kind kind, const yaml_char_t *anchor_name)
{
    if (b->depth >= YAML_MAX_DEPTH)
        return fail_at(b, ev->start_mark, "nesting too deep (limit 64 levels)");
    ynode *n = new_node(b, kind, ev->start_mark);
    if (!n)
        return b->doc->node_count >= YAML_MAX_NODES ? fail_at(b, ev->start_mark, "too many nodes in one file")
                                                    : out_of_memory(b);
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
        snprintf(msg, sizeof msg, "unknown alias '*%.200s'", name);
        return fail_at(b, ev->start_mark, msg);
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
        return on_start(b, ev, YNODE_SEQUENCE, ev->data.sequence_start.anchor);
    case YAML_MAPPING_START_EVENT:
        return on_start(b, ev, YNODE_MAPPING, ev->data.mapping_start.anchor);
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT:
        b->stack[--b->depth]->complete = true;
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
    builder b = {.doc = doc, .err = err};
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
            if (parser.context)
                snprintf(msg, sizeof msg, "syntax error: %s %s", parser.problem ? parser.problem : "",
                         parser.context);
            else
                snprintf(msg, sizeof msg, "syntax error: %s", parser.problem ? parser.problem : "unknown");
            s = fail_at(&b, parser.problem_mark, msg);
            break;
        }
        s = on_event(&b, &ev, &done);
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&parser);
    for (int i = 0; i < b.anchor_count; i++)
        free(b.anchors[i].name);
    free(b.anchors);
    if (s)
        ydoc_free(doc);
    return s;
}

void ydoc_free(ydoc *doc)
{
    for (int i = 0; i < doc->node_count; i++) {
        free(doc->nodes[i]->value);
        free(doc->nodes[i]->items);
        free(doc->nodes[i]);
    }
    free(doc->nodes);
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
