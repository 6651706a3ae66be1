/* gltf_nodes.c - the size of a glTF's node hierarchy as Assimp will build
 * it, counted before Assimp reads the file. A glTF node names its children
 * by index, and nothing stops two children, or two nodes, naming the same
 * node: the hierarchy is a graph, and Assimp's importer makes a node of its
 * own (about 1 KB) for every path to a node from a scene's root, while it
 * reads, before glint sees anything. A 1.8 KB file whose node i has the
 * children [i+1, i+1] asks for 2^40 of them. So the graph is read from the
 * JSON here and its paths counted, each node's count once; a cycle (whose
 * paths never end) is refused too. The scan is lenient: JSON it cannot
 * follow is left to Assimp's parser, which refuses it; what valid JSON
 * holds it reads as that parser does (the first of two equal keys, escapes
 * decoded). glTF 1 names its nodes (an object of them, children and roots
 * given by name) where glTF 2 numbers them (an array): names are decoded
 * and turned into numbers once the file is read. The same walk, each node
 * weighted by the vertices and indices of the mesh it places (glTF 2:
 * its accessors' counts), bounds what Assimp copies for every placement
 * of a mesh (PreTransformVertices) before it copies it. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "model/assimp_check.h"
#include "model/json_char.h"
#include "model/model_file.h"

/* Where the scan is in the JSON text. */
typedef struct reader {
    const unsigned char *t;
    size_t size, i;
    bool nomem;               /* memory ran out (the scan stops as for broken JSON) */
    char *names;              /* glTF 1's names, decoded, each ended by a NUL: no more than the text */
    size_t names_used;
} reader;

/* A glTF 1 reference, by name: NAMED | the name's offset in reader.names,
 * until resolve_names makes it a node's number. */
#define NAMED (1ULL << 63)
/* A reference to no node (a number or name out of range). */
#define NO_NODE (NAMED - 1)

/* The hierarchy as the file gives it: node n's children are
 * child[first[n]] to child[first[n + 1] - 1]. */
typedef struct graph {
    size_t nodes, *first, first_cap;
    uint64_t *child;
    size_t children, child_cap;
    uint64_t *roots;          /* every scene's root nodes, all scenes together */
    size_t root_count, root_cap;
    uint64_t *node_names;     /* glTF 1: node n's name (an offset in reader.names) */
    size_t node_name_cap;
    uint64_t *node_mesh;      /* glTF 2: node n's mesh, or NO_NODE */
    size_t node_mesh_cap;
    /* glTF 2: mesh m's accessors (its primitives' POSITION and indices)
     * are accessor[mesh_first[m]] to accessor[mesh_first[m + 1] - 1]. */
    size_t meshes, *mesh_first, mesh_first_cap;
    uint64_t *accessor;
    size_t accessor_refs, accessor_ref_cap;
    uint64_t *accessor_count; /* glTF 2: each accessor's count, or NO_NODE */
    size_t accessors, accessor_count_cap;
} graph;

static void skip_space(reader *r)
{
    while (r->i < r->size && (r->t[r->i] == ' ' || r->t[r->i] == '\t' || r->t[r->i] == '\n' || r->t[r->i] == '\r'))
        r->i++;
}

/* True, the reader past it, when `c` comes next. */
static bool take(reader *r, unsigned char c)
{
    skip_space(r);
    if (r->i >= r->size || r->t[r->i] != c)
        return false;
    r->i++;
    return true;
}

/* Decodes the string at the reader into key (its first size - 1
 * characters; a longer one is cut to size - 1 and marked with a final
 * 0x01, so that it equals no short key). False at a broken string. */
static bool read_string(reader *r, char *key, size_t size)
{
    if (!take(r, '"'))
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

/* Decodes the string at the reader into r->names, its offset there in
 * *at: the decoded characters are never more than the text's. */
static bool read_name(reader *r, uint64_t *at)
{
    if (!r->names && !(r->names = malloc(r->size + 1))) {
        r->nomem = true;
        return false;
    }
    skip_space(r);
    size_t start = r->i;
    char none[2];
    if (!read_string(r, none, sizeof none))
        return false;
    *at = r->names_used;
    size_t k = start + 1;
    int c;
    while ((c = json_next_char(r->t, r->size, &k)) >= 0)
        r->names[r->names_used++] = (char)c;
    r->names[r->names_used++] = '\0';
    return true;
}

/* Skips one value of any kind; nesting is counted, never recursed into. */
static bool skip_value(reader *r)
{
    size_t depth = 0;
    char none[2];
    do {
        skip_space(r);
        if (r->i >= r->size)
            return false;
        unsigned char c = r->t[r->i];
        if (c == '"') {
            if (!read_string(r, none, sizeof none))
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

/* Moves to the next item of an array or object whose opening bracket has
 * been read: 1 when one follows (the reader at it), 0 past the closing
 * bracket, -1 at broken JSON. */
static int next_item(reader *r, bool *first, unsigned char close)
{
    if (take(r, close))
        return 0;
    if (!*first && !take(r, ','))
        return -1;
    *first = false;
    return 1;
}

/* next_item for an object, its key decoded into key and the reader at its
 * value. */
static int next_member(reader *r, bool *first, char *key, size_t size)
{
    int n = next_item(r, first, '}');
    if (n <= 0)
        return n;
    return read_string(r, key, size) && take(r, ':') ? 1 : -1;
}

/* Reads an array of node indices, appending each to *list: numbers, or
 * names (NAMED). A value that is neither an unsigned integer nor a string
 * is skipped, as Assimp skips it; one too large for any node is kept, and
 * found out of range by the count. */
static bool read_indices(reader *r, uint64_t **list, size_t *count, size_t *cap)
{
    if (!take(r, '['))
        return skip_value(r);
    bool first = true;
    int n;
    while ((n = next_item(r, &first, ']')) > 0) {
        skip_space(r);
        size_t start = r->i;
        uint64_t v = 0;
        if (r->i < r->size && r->t[r->i] == '"') {
            if (!read_name(r, &v))
                return false;
            v |= NAMED;
            r->i = start;
        }
        bool negative = r->i < r->size && r->t[r->i] == '-';
        r->i += negative;
        /* Every digit is passed over, a number too large for a node included. */
        for (; r->i < r->size && r->t[r->i] >= '0' && r->t[r->i] <= '9'; r->i++)
            v = v > NO_NODE / 10 - 1 ? NO_NODE : v * 10 + (uint64_t)(r->t[r->i] - '0');
        bool integer = v & NAMED || (r->i > start + negative && (r->i >= r->size || !strchr(".eE", r->t[r->i])));
        r->i = start;
        if (!skip_value(r))
            return false;
        if (!integer || (negative && v != 0))
            continue;
        if (!array_reserve((void **)list, cap, *count + 1, sizeof **list)) {
            r->nomem = true;
            return false;
        }
        (*list)[(*count)++] = v;
    }
    return n == 0;
}

/* Reads one value into *v: its number when it is an unsigned integer
 * (capped at NO_NODE), NO_NODE when it is anything else. False at broken
 * JSON. */
static bool read_number(reader *r, uint64_t *v)
{
    skip_space(r);
    size_t start = r->i;
    uint64_t n = 0;
    for (; r->i < r->size && r->t[r->i] >= '0' && r->t[r->i] <= '9'; r->i++)
        n = n > NO_NODE / 10 - 1 ? NO_NODE : n * 10 + (uint64_t)(r->t[r->i] - '0');
    bool integer = r->i > start && (r->i >= r->size || !strchr(".eE", r->t[r->i]));
    r->i = start;
    *v = integer ? n : NO_NODE;
    return skip_value(r);
}

/* Appends v to *list; false (r->nomem) when memory runs out. */
static bool append(reader *r, uint64_t **list, size_t *count, size_t *cap, uint64_t v)
{
    if (!array_reserve((void **)list, cap, *count + 1, sizeof **list)) {
        r->nomem = true;
        return false;
    }
    (*list)[(*count)++] = v;
    return true;
}

/* Calls on(r, g, key) for each member of the object at the reader, the
 * reader at its value, which on must read; the first of two equal keys
 * is the one JSON parsers keep, so each key is handed over once. A value
 * that is not an object is skipped. */
typedef bool (*member_fn)(reader *r, graph *g, const char *key);

static bool each_member(reader *r, graph *g, member_fn on, const char *const *keys, int key_count)
{
    if (!take(r, '{'))
        return skip_value(r);
    bool first = true;
    unsigned seen = 0;
    char member[16];
    int m;
    while ((m = next_member(r, &first, member, sizeof member)) > 0) {
        int k = 0;
        while (k < key_count && strcmp(member, keys[k]) != 0)
            k++;
        bool wanted = k < key_count && !(seen >> k & 1);
        seen |= wanted ? 1u << k : 0;
        if (!(wanted ? on(r, g, member) : skip_value(r)))
            return false;
    }
    return m == 0;
}

/* Calls on(r, g) for each item of the array at the reader, which on must
 * read; a value that is not an array is skipped. */
static bool each_item(reader *r, graph *g, bool (*on)(reader *r, graph *g))
{
    if (!take(r, '['))
        return skip_value(r);
    bool first = true;
    int n;
    while ((n = next_item(r, &first, ']')) > 0)
        if (!on(r, g))
            return false;
    return n == 0;
}

/* A primitive's attribute POSITION, or its indices: an accessor of the
 * current mesh. */
static bool on_accessor_ref(reader *r, graph *g, const char *key)
{
    (void)key;
    uint64_t v;
    return read_number(r, &v) && append(r, &g->accessor, &g->accessor_refs, &g->accessor_ref_cap, v);
}

static bool on_attributes(reader *r, graph *g, const char *key)
{
    static const char *const keys[] = {"POSITION"};
    (void)key;
    return each_member(r, g, on_accessor_ref, keys, 1);
}

static bool on_primitive_member(reader *r, graph *g, const char *key)
{
    return strcmp(key, "attributes") == 0 ? on_attributes(r, g, key) : on_accessor_ref(r, g, key);
}

static bool on_primitive(reader *r, graph *g)
{
    static const char *const keys[] = {"attributes", "indices"};
    return each_member(r, g, on_primitive_member, keys, 2);
}

static bool on_primitives(reader *r, graph *g, const char *key)
{
    (void)key;
    return each_item(r, g, on_primitive);
}

static bool on_mesh(reader *r, graph *g)
{
    static const char *const keys[] = {"primitives"};
    if (!array_reserve((void **)&g->mesh_first, &g->mesh_first_cap, g->meshes + 2, sizeof *g->mesh_first)) {
        r->nomem = true;
        return false;
    }
    g->mesh_first[g->meshes++] = g->accessor_refs;
    bool ok = each_member(r, g, on_primitives, keys, 1);
    g->mesh_first[g->meshes] = g->accessor_refs;
    return ok;
}

static bool on_accessor_count(reader *r, graph *g, const char *key)
{
    (void)key;
    uint64_t v;
    return read_number(r, &v) && append(r, &g->accessor_count, &g->accessors, &g->accessor_count_cap, v);
}

static bool on_accessor(reader *r, graph *g)
{
    static const char *const keys[] = {"count"};
    size_t before = g->accessors;
    if (!each_member(r, g, on_accessor_count, keys, 1))
        return false;
    /* An accessor without a count counts for nothing: Assimp refuses it. */
    return g->accessors > before || append(r, &g->accessor_count, &g->accessors, &g->accessor_count_cap, 0);
}

/* Reads each object of an array, or (glTF 1) of an object by name, the
 * value of "nodes" or "scenes": the value of its member `key` through
 * read_indices into *list; with nodes set, also where each node's children
 * start, and its name. */
static bool read_objects(reader *r, const char *key, graph *g, bool nodes, uint64_t **list, size_t *count,
                         size_t *cap)
{
    bool named = take(r, '{');
    if (!named && !take(r, '['))
        return skip_value(r);
    bool first = true;
    int n;
    while ((n = next_item(r, &first, named ? '}' : ']')) > 0) {
        uint64_t name = 0;
        if (named && !(read_name(r, &name) && take(r, ':')))
            return false;
        if (nodes) {
            if (!array_reserve((void **)&g->first, &g->first_cap, g->nodes + 2, sizeof *g->first) ||
                !array_reserve((void **)&g->node_names, &g->node_name_cap, g->nodes + 1, sizeof *g->node_names) ||
                !array_reserve((void **)&g->node_mesh, &g->node_mesh_cap, g->nodes + 1, sizeof *g->node_mesh)) {
                r->nomem = true;
                return false;
            }
            g->node_mesh[g->nodes] = NO_NODE;
            g->node_names[g->nodes] = named ? name | NAMED : 0;
            g->first[g->nodes++] = *count;
        }
        if (!take(r, '{')) {
            if (!skip_value(r))
                return false;
            continue;
        }
        bool first_member = true, seen = false;
        char member[16];
        int m;
        bool mesh_seen = false;
        while ((m = next_member(r, &first_member, member, sizeof member)) > 0) {
            bool wanted = !seen && strcmp(member, key) == 0;
            bool mesh = nodes && !named && !mesh_seen && strcmp(member, "mesh") == 0;
            seen |= wanted;
            mesh_seen |= mesh;
            if (!(wanted ? read_indices(r, list, count, cap)
                  : mesh ? read_number(r, &g->node_mesh[g->nodes - 1])
                         : skip_value(r)))
                return false;
        }
        if (m < 0)
            return false;
    }
    if (nodes && g->first)
        g->first[g->nodes] = *count;
    return n == 0;
}

/* Reads the graph from the top-level "nodes" and "scenes". False at JSON
 * the scan cannot follow or when memory runs out (r->nomem). */
static bool read_graph(reader *r, graph *g)
{
    if (!take(r, '{'))
        return false;
    bool first = true, nodes_seen = false, scenes_seen = false, meshes_seen = false, accessors_seen = false;
    char key[16];
    int n;
    while ((n = next_member(r, &first, key, sizeof key)) > 0) {
        bool ok;
        if (!nodes_seen && strcmp(key, "nodes") == 0) {
            nodes_seen = true;
            ok = read_objects(r, "children", g, true, &g->child, &g->children, &g->child_cap);
        } else if (!scenes_seen && strcmp(key, "scenes") == 0) {
            scenes_seen = true;
            ok = read_objects(r, "nodes", g, false, &g->roots, &g->root_count, &g->root_cap);
        } else if (!meshes_seen && strcmp(key, "meshes") == 0) {
            meshes_seen = true;
            ok = each_item(r, g, on_mesh);
        } else if (!accessors_seen && strcmp(key, "accessors") == 0) {
            accessors_seen = true;
            ok = each_item(r, g, on_accessor);
        } else {
            ok = skip_value(r);
        }
        if (!ok)
            return false;
    }
    return n == 0;
}

/* A node's name and number, for finding names by bsearch. */
typedef struct named_node {
    const char *name;
    size_t node;
} named_node;

static int by_name(const void *a, const void *b)
{
    return strcmp(((const named_node *)a)->name, ((const named_node *)b)->name);
}

/* Turns each reference by name in list into the number of the node of that
 * name (the first, as Assimp's table keeps the first), or NO_NODE. */
static void resolve(const reader *r, const named_node *sorted, size_t nodes, uint64_t *list, size_t count)
{
    for (size_t k = 0; k < count; k++) {
        if (!(list[k] & NAMED))
            continue;
        named_node key = {r->names + (list[k] & ~NAMED), 0};
        const named_node *found = bsearch(&key, sorted, nodes, sizeof *sorted, by_name);
        list[k] = found ? found->node : NO_NODE;
    }
}

/* glTF 1: every reference by name becomes a number. False when memory runs
 * out. */
static bool resolve_names(const reader *r, graph *g)
{
    if (!r->names)
        return true;
    named_node *sorted = array_alloc(g->nodes, sizeof *sorted);
    if (!sorted)
        return false;
    size_t named = 0;
    for (size_t n = 0; n < g->nodes; n++)
        if (g->node_names[n] & NAMED)
            sorted[named++] = (named_node){r->names + (g->node_names[n] & ~NAMED), n};
    /* Equal names keep the first node: a stable order by number breaks ties. */
    qsort(sorted, named, sizeof *sorted, by_name);
    size_t kept = 0;
    for (size_t k = 0; k < named; k++)
        if (kept == 0 || strcmp(sorted[kept - 1].name, sorted[k].name) != 0)
            sorted[kept++] = sorted[k];
        else if (sorted[k].node < sorted[kept - 1].node)
            sorted[kept - 1] = sorted[k];
    resolve(r, sorted, kept, g->child, g->children);
    resolve(r, sorted, kept, g->roots, g->root_count);
    free(sorted);
    return true;
}

/* a + b, or cap when that is more (a and b at most cap each). */
static uint64_t add_capped(uint64_t a, uint64_t b, uint64_t cap)
{
    return a + b > cap ? cap : a + b;
}

/* A node on the walk's stack: the next of its children to visit, and the
 * nodes of its expansion counted so far. */
typedef struct frame {
    size_t node, next;
    uint64_t sum;
} frame;

/* Counts the expansion of every node into paths[]: its own weight (own[n],
 * or 1 when own is NULL) and each child's expansion once per time it is
 * named, capped at `cap`, walking the graph depth first with a stack of
 * its own. Sets *cycle to a node on a cycle, or to SIZE_MAX. */
static glint_status count_paths(const graph *g, const uint64_t *own, uint64_t cap, uint64_t *paths, size_t *cycle,
                                glint_error *err, const char *file)
{
    unsigned char *state = calloc(g->nodes, 1); /* 0 not reached, 1 on the stack, 2 counted */
    frame *stack = array_alloc(g->nodes, sizeof *stack);
    *cycle = SIZE_MAX;
    glint_status s = state && stack ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    for (size_t start = 0; !s && start < g->nodes && *cycle == SIZE_MAX; start++) {
        if (state[start])
            continue;
        size_t depth = 0;
        stack[depth++] = (frame){start, g->first[start], own ? own[start] : 1};
        state[start] = 1;
        while (depth > 0 && *cycle == SIZE_MAX) {
            frame *f = &stack[depth - 1];
            if (f->next == g->first[f->node + 1]) {
                paths[f->node] = f->sum;
                state[f->node] = 2;
                if (--depth > 0)
                    stack[depth - 1].sum = add_capped(stack[depth - 1].sum, f->sum, cap);
                continue;
            }
            uint64_t c = g->child[f->next++];
            if (c >= g->nodes)
                continue; /* Assimp refuses the index */
            if (state[c] == 1)
                *cycle = (size_t)c;
            else if (state[c] == 2)
                f->sum = add_capped(f->sum, paths[c], cap);
            else {
                state[c] = 1;
                stack[depth++] = (frame){(size_t)c, g->first[c], own ? own[c] : 1};
            }
        }
    }
    free(state);
    free(stack);
    return s;
}

/* The largest expansion of any node, and of all scenes' roots together,
 * each capped at cap. */
static uint64_t largest_expansion(const graph *g, const uint64_t *paths, uint64_t cap)
{
    uint64_t largest = 0, roots = 0;
    for (size_t n = 0; n < g->nodes; n++)
        largest = paths[n] > largest ? paths[n] : largest;
    for (size_t k = 0; k < g->root_count; k++)
        if (g->roots[k] < g->nodes)
            roots = add_capped(roots, paths[g->roots[k]], cap);
    return roots > largest ? roots : largest;
}

/* Each node's own weight for placing: the counts of its mesh's accessors
 * (vertices and indices), capped at cap; NULL when out of memory. */
static uint64_t *placed_weights(const graph *g, uint64_t cap)
{
    uint64_t *own = array_alloc(g->nodes, sizeof *own);
    for (size_t n = 0; own && n < g->nodes; n++) {
        own[n] = 0;
        uint64_t m = g->node_mesh[n];
        for (size_t k = m < g->meshes ? g->mesh_first[m] : 0; m < g->meshes && k < g->mesh_first[m + 1]; k++) {
            uint64_t a = g->accessor[k];
            uint64_t count = a < g->accessors && g->accessor_count[a] != NO_NODE ? g->accessor_count[a] : 0;
            own[n] = add_capped(own[n], count > cap ? cap : count, cap);
        }
    }
    return own;
}

glint_status gltf_check_nodes(const unsigned char *text, size_t size, const char *file, glint_error *err)
{
    reader r = {.t = text, .size = size};
    graph g = {0};
    glint_status s = GLINT_OK;
    if (!read_graph(&r, &g)) {
        if (r.nomem)
            s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
        g.nodes = 0; /* left to Assimp's parser */
    } else if (!resolve_names(&r, &g)) {
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    }
    uint64_t *paths = g.nodes ? array_alloc(g.nodes, sizeof *paths) : NULL;
    if (!s && g.nodes && !paths)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    size_t cycle = SIZE_MAX;
    if (!s && g.nodes)
        s = count_paths(&g, NULL, GLTF_MAX_NODES + 1, paths, &cycle, err, file);
    if (!s && cycle != SIZE_MAX)
        s = error_set(err, GLINT_ERR_INVALID, "%s: node %zu is among its own children's descendants (the node hierarchy has a cycle)",
                      file, cycle);
    /* Every node's own expansion is bounded, whichever becomes a root, and
     * so are all scenes' roots together. */
    if (!s && g.nodes && largest_expansion(&g, paths, GLTF_MAX_NODES + 1) > GLTF_MAX_NODES)
        s = error_set(err, GLINT_ERR_INVALID,
                      "%s: the node hierarchy expands to more than %d nodes (a node counts once for each path to it "
                      "from a root), too many to import",
                      file, GLTF_MAX_NODES);
    /* Assimp copies a mesh's vertices and indices for each placement of
     * it, before glint sees any: bounded the same way, weighted. */
    uint64_t limit = model_file_memory_limit() / GLTF_PLACED_BYTES, *own = NULL;
    if (!s && g.nodes && limit && !(own = placed_weights(&g, limit + 1)))
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    if (own && !s)
        s = count_paths(&g, own, limit + 1, paths, &cycle, err, file);
    if (own && !s && largest_expansion(&g, paths, limit + 1) > limit)
        s = error_set(err, GLINT_ERR_INVALID,
                      "%s: its nodes place their meshes' vertices and indices more times than half of this "
                      "machine's memory holds (about %d bytes each once placed)",
                      file, GLTF_PLACED_BYTES);
    free(own);
    free(paths);
    free(g.first);
    free(g.child);
    free(g.roots);
    free(g.node_names);
    free(g.node_mesh);
    free(g.mesh_first);
    free(g.accessor);
    free(g.accessor_count);
    free(r.names);
    return s;
}
