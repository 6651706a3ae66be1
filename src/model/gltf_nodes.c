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
#include "model/json_scan.h"
#include "model/model_file.h"

/* A glTF 1 reference, by name: NAMED | the name's offset in graph.names,
 * until resolve_names makes it a node's number. */
#define NAMED (1ULL << 63)
/* A reference to no node (a number or name out of range). */
#define NO_NODE JSON_NO_INDEX

/* The hierarchy as the file gives it: node n's children are
 * child[first[n]] to child[first[n + 1] - 1]. */
typedef struct graph {
    size_t nodes, *first, first_cap;
    uint64_t *child;
    size_t children, child_cap;
    uint64_t *roots;          /* every scene's root nodes, all scenes together */
    size_t root_count, root_cap;
    char *names;              /* glTF 1's names, decoded, each ended by a NUL: no more than the text */
    size_t names_used;
    uint64_t *node_names;     /* glTF 1: node n's name (an offset in names) */
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

/* Decodes the string at the scan into g->names, its offset there in *at:
 * the decoded characters are never more than the text's. */
static bool read_name(json_scan *r, graph *g, uint64_t *at)
{
    if (!g->names && !(g->names = malloc(r->size + 1))) {
        r->nomem = true;
        return false;
    }
    json_skip_space(r);
    size_t start = r->i;
    char none[2];
    if (!json_read_string(r, none, sizeof none))
        return false;
    *at = g->names_used;
    size_t k = start + 1;
    int c;
    while ((c = json_next_char(r->t, r->size, &k)) >= 0)
        g->names[g->names_used++] = (char)c;
    g->names[g->names_used++] = '\0';
    return true;
}

/* Appends v to *list; false (r->nomem) when memory runs out. */
static bool append(json_scan *r, uint64_t **list, size_t *count, size_t *cap, uint64_t v)
{
    if (!array_reserve((void **)list, cap, *count + 1, sizeof **list)) {
        r->nomem = true;
        return false;
    }
    (*list)[(*count)++] = v;
    return true;
}

/* Reads an array of node indices, appending each to *list: numbers, or
 * names (NAMED). A value that is neither an unsigned integer nor a string
 * is skipped, as Assimp skips it. */
static bool read_indices(json_scan *r, graph *g, uint64_t **list, size_t *count, size_t *cap)
{
    if (!json_take(r, '['))
        return json_skip_value(r);
    bool first = true;
    int n;
    while ((n = json_next_item(r, &first, ']')) > 0) {
        json_skip_space(r);
        bool named = r->i < r->size && r->t[r->i] == '"';
        uint64_t v;
        if (!(named ? read_name(r, g, &v) : json_read_index(r, &v)))
            return false;
        if ((named || v != NO_NODE) && !append(r, list, count, cap, named ? v | NAMED : v))
            return false;
    }
    return n == 0;
}

/* A primitive's attribute POSITION, or its indices: an accessor of the
 * current mesh. */
static bool on_accessor_ref(json_scan *r, void *ctx, const char *key)
{
    graph *g = ctx;
    (void)key;
    uint64_t v;
    return json_read_index(r, &v) && append(r, &g->accessor, &g->accessor_refs, &g->accessor_ref_cap, v);
}

static bool on_attributes(json_scan *r, void *ctx, const char *key)
{
    static const char *const keys[] = {"POSITION"};
    (void)key;
    return json_each_member(r, ctx, on_accessor_ref, keys, 1);
}

static bool on_primitive_member(json_scan *r, void *ctx, const char *key)
{
    return strcmp(key, "attributes") == 0 ? on_attributes(r, ctx, key) : on_accessor_ref(r, ctx, key);
}

static bool on_primitive(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"attributes", "indices"};
    return json_each_member(r, ctx, on_primitive_member, keys, 2);
}

static bool on_primitives(json_scan *r, void *ctx, const char *key)
{
    (void)key;
    return json_each_item(r, ctx, on_primitive);
}

static bool on_mesh(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"primitives"};
    graph *g = ctx;
    if (!array_reserve((void **)&g->mesh_first, &g->mesh_first_cap, g->meshes + 2, sizeof *g->mesh_first)) {
        r->nomem = true;
        return false;
    }
    g->mesh_first[g->meshes++] = g->accessor_refs;
    bool ok = json_each_member(r, g, on_primitives, keys, 1);
    g->mesh_first[g->meshes] = g->accessor_refs;
    return ok;
}

static bool on_accessor_count(json_scan *r, void *ctx, const char *key)
{
    graph *g = ctx;
    (void)key;
    uint64_t v;
    return json_read_index(r, &v) && append(r, &g->accessor_count, &g->accessors, &g->accessor_count_cap, v);
}

static bool on_accessor(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"count"};
    graph *g = ctx;
    size_t before = g->accessors;
    if (!json_each_member(r, g, on_accessor_count, keys, 1))
        return false;
    /* An accessor without a count counts for nothing: Assimp refuses it. */
    return g->accessors > before || append(r, &g->accessor_count, &g->accessors, &g->accessor_count_cap, 0);
}

/* Reads each object of an array, or (glTF 1) of an object by name, the
 * value of "nodes" or "scenes": the value of its member `key` through
 * read_indices into *list; with nodes set, also where each node's children
 * start, and its name. */
static bool read_objects(json_scan *r, const char *key, graph *g, bool nodes, uint64_t **list, size_t *count,
                         size_t *cap)
{
    bool named = json_take(r, '{');
    if (!named && !json_take(r, '['))
        return json_skip_value(r);
    bool first = true;
    int n;
    while ((n = json_next_item(r, &first, named ? '}' : ']')) > 0) {
        uint64_t name = 0;
        if (named && !(read_name(r, g, &name) && json_take(r, ':')))
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
        if (!json_take(r, '{')) {
            if (!json_skip_value(r))
                return false;
            continue;
        }
        bool first_member = true, seen = false;
        char member[16];
        int m;
        bool mesh_seen = false;
        while ((m = json_next_member(r, &first_member, member, sizeof member)) > 0) {
            bool wanted = !seen && strcmp(member, key) == 0;
            bool mesh = nodes && !named && !mesh_seen && strcmp(member, "mesh") == 0;
            seen |= wanted;
            mesh_seen |= mesh;
            if (!(wanted ? read_indices(r, g, list, count, cap)
                  : mesh ? json_read_index(r, &g->node_mesh[g->nodes - 1])
                         : json_skip_value(r)))
                return false;
        }
        if (m < 0)
            return false;
    }
    if (nodes && g->first)
        g->first[g->nodes] = *count;
    return n == 0;
}

/* One of the top-level members read_graph reads. */
static bool on_top_member(json_scan *r, void *ctx, const char *key)
{
    graph *g = ctx;
    if (strcmp(key, "nodes") == 0)
        return read_objects(r, "children", g, true, &g->child, &g->children, &g->child_cap);
    if (strcmp(key, "scenes") == 0)
        return read_objects(r, "nodes", g, false, &g->roots, &g->root_count, &g->root_cap);
    return json_each_item(r, g, strcmp(key, "meshes") == 0 ? on_mesh : on_accessor);
}

/* Reads the graph from the top-level "nodes", "scenes", "meshes" and
 * "accessors". False at JSON the scan cannot follow or when memory runs
 * out (r->nomem). */
static bool read_graph(json_scan *r, graph *g)
{
    static const char *const keys[] = {"nodes", "scenes", "meshes", "accessors"};
    json_skip_space(r);
    return r->i < r->size && r->t[r->i] == '{' && json_each_member(r, g, on_top_member, keys, 4);
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
static void resolve(const graph *g, const named_node *sorted, size_t nodes, uint64_t *list, size_t count)
{
    for (size_t k = 0; k < count; k++) {
        if (!(list[k] & NAMED))
            continue;
        named_node key = {g->names + (list[k] & ~NAMED), 0};
        const named_node *found = bsearch(&key, sorted, nodes, sizeof *sorted, by_name);
        list[k] = found ? found->node : NO_NODE;
    }
}

/* glTF 1: every reference by name becomes a number. False when memory runs
 * out. */
static bool resolve_names(graph *g)
{
    if (!g->names)
        return true;
    named_node *sorted = array_alloc(g->nodes, sizeof *sorted);
    if (!sorted)
        return false;
    size_t named = 0;
    for (size_t n = 0; n < g->nodes; n++)
        if (g->node_names[n] & NAMED)
            sorted[named++] = (named_node){g->names + (g->node_names[n] & ~NAMED), n};
    /* Equal names keep the first node: a stable order by number breaks ties. */
    qsort(sorted, named, sizeof *sorted, by_name);
    size_t kept = 0;
    for (size_t k = 0; k < named; k++)
        if (kept == 0 || strcmp(sorted[kept - 1].name, sorted[k].name) != 0)
            sorted[kept++] = sorted[k];
        else if (sorted[k].node < sorted[kept - 1].node)
            sorted[kept - 1] = sorted[k];
    resolve(g, sorted, kept, g->child, g->children);
    resolve(g, sorted, kept, g->roots, g->root_count);
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
    json_scan r = {.t = text, .size = size};
    graph g = {0};
    glint_status s = GLINT_OK;
    if (!read_graph(&r, &g)) {
        if (r.nomem)
            s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
        g.nodes = 0; /* left to Assimp's parser */
    } else if (!resolve_names(&g)) {
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
    free(g.names);
    return s;
}
