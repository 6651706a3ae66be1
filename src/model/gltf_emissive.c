/* gltf_emissive.c - KHR_materials_emissive_strength, which Debian's Assimp
 * (5.2.5) drops: without it a glTF lamp exported with emissiveStrength 5
 * would glow at a fifth of its brightness. Each material's strength is read
 * from the JSON here, and the scene's nodes, meshes and primitives too, to
 * number the materials as Assimp will (gltf_emissive.h): Assimp makes a
 * material only for each one its reading of the scene reaches, in that
 * order, so a glTF's material i is seldom Assimp's material i. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "model/gltf_emissive.h"
#include "model/json_scan.h"
#include "model/text_scan.h"

/* Lists of indices, one after another: list k is item[first[k]] to
 * item[first[k + 1] - 1]. */
typedef struct index_lists {
    size_t *first, lists, first_cap;
    uint64_t *item;
    size_t items, item_cap;
} index_lists;

/* What the JSON says of the scene's materials. */
typedef struct gltf_doc {
    uint64_t scene;           /* the scene Assimp reads */
    index_lists scene_nodes;  /* per scene, its root nodes */
    index_lists children;     /* per node */
    uint64_t *node_mesh;      /* per node: its mesh, or JSON_NO_INDEX */
    size_t node_mesh_cap;
    index_lists mesh_materials; /* per mesh, its primitives' materials */
    double *strength;         /* per material */
    size_t materials, strength_cap;
    const char *file;
    glint_error *err;
    glint_status refused;     /* a strength refused (the scan stops) */
} gltf_doc;

/* Starts a new, empty list. False (r->nomem) when memory runs out. */
static bool start_list(json_scan *r, index_lists *l)
{
    if (!array_reserve((void **)&l->first, &l->first_cap, l->lists + 2, sizeof *l->first)) {
        r->nomem = true;
        return false;
    }
    l->first[l->lists++] = l->items;
    l->first[l->lists] = l->items;
    return true;
}

/* Reads an index (json_read_index) onto the last list, ctx. */
static bool on_index(json_scan *r, void *ctx)
{
    index_lists *l = ctx;
    uint64_t v;
    if (!json_read_index(r, &v))
        return false;
    if (!array_reserve((void **)&l->item, &l->item_cap, l->items + 1, sizeof *l->item)) {
        r->nomem = true;
        return false;
    }
    l->item[l->items++] = v;
    l->first[l->lists] = l->items;
    return true;
}

static bool on_scene_nodes(json_scan *r, void *ctx, const char *key)
{
    (void)key;
    return json_each_item(r, &((gltf_doc *)ctx)->scene_nodes, on_index);
}

static bool on_scene(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"nodes"};
    gltf_doc *d = ctx;
    return start_list(r, &d->scene_nodes) && json_each_member(r, d, on_scene_nodes, keys, 1);
}

static bool on_node_member(json_scan *r, void *ctx, const char *key)
{
    gltf_doc *d = ctx;
    if (strcmp(key, "mesh") == 0)
        return json_read_index(r, &d->node_mesh[d->children.lists - 1]);
    return json_each_item(r, &d->children, on_index);
}

static bool on_node(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"children", "mesh"};
    gltf_doc *d = ctx;
    if (!start_list(r, &d->children) ||
        !array_reserve((void **)&d->node_mesh, &d->node_mesh_cap, d->children.lists, sizeof *d->node_mesh)) {
        r->nomem = true;
        return false;
    }
    d->node_mesh[d->children.lists - 1] = JSON_NO_INDEX;
    return json_each_member(r, d, on_node_member, keys, 2);
}

static bool on_primitive_material(json_scan *r, void *ctx, const char *key)
{
    (void)key;
    return on_index(r, &((gltf_doc *)ctx)->mesh_materials);
}

static bool on_primitive(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"material"};
    return json_each_member(r, ctx, on_primitive_material, keys, 1);
}

static bool on_primitives(json_scan *r, void *ctx, const char *key)
{
    (void)key;
    return json_each_item(r, ctx, on_primitive);
}

static bool on_mesh(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"primitives"};
    gltf_doc *d = ctx;
    return start_list(r, &d->mesh_materials) && json_each_member(r, d, on_primitives, keys, 1);
}

/* materials[i].extensions.KHR_materials_emissive_strength.emissiveStrength */
static bool on_strength(json_scan *r, void *ctx, const char *key)
{
    gltf_doc *d = ctx;
    (void)key;
    json_skip_space(r);
    size_t start = r->i;
    bool number;
    double v;
    if (!json_read_number(r, &number, &v))
        return false;
    if (!number)
        return true; /* left at 1, as a material without the extension */
    if (v < 0 || !isfinite(v)) {
        char quoted[32];
        scan_quote((const char *)r->t + start, r->i - start, quoted, sizeof quoted);
        d->refused = error_set(d->err, GLINT_ERR_INVALID,
                               "%s: material %zu: emissiveStrength %s (KHR_materials_emissive_strength) is %s",
                               d->file, d->materials - 1, quoted, v < 0 ? "negative" : "not finite");
        return false;
    }
    d->strength[d->materials - 1] = v == 0 ? 0 : fmin(v, GLTF_MAX_EMISSIVE_STRENGTH); /* -0 as 0 */
    return true;
}

static bool on_extension(json_scan *r, void *ctx, const char *key)
{
    static const char *const keys[] = {"emissiveStrength"};
    (void)key;
    return json_each_member(r, ctx, on_strength, keys, 1);
}

static bool on_extensions(json_scan *r, void *ctx, const char *key)
{
    static const char *const keys[] = {"KHR_materials_emissive_strength"};
    (void)key;
    return json_each_member(r, ctx, on_extension, keys, 1);
}

static bool on_material(json_scan *r, void *ctx)
{
    static const char *const keys[] = {"extensions"};
    gltf_doc *d = ctx;
    if (!array_reserve((void **)&d->strength, &d->strength_cap, d->materials + 1, sizeof *d->strength)) {
        r->nomem = true;
        return false;
    }
    d->strength[d->materials++] = 1;
    return json_each_member(r, d, on_extensions, keys, 1);
}

static bool on_top_member(json_scan *r, void *ctx, const char *key)
{
    gltf_doc *d = ctx;
    if (strcmp(key, "scene") == 0)
        return json_read_index(r, &d->scene);
    json_item_fn on = strcmp(key, "scenes") == 0 ? on_scene
                      : strcmp(key, "nodes") == 0 ? on_node
                      : strcmp(key, "meshes") == 0 ? on_mesh
                                                   : on_material;
    return json_each_item(r, d, on);
}

/* A node on the walk's stack, and the next of its children to visit. */
typedef struct frame {
    size_t node, next;
} frame;

/* Numbers mesh m's materials not numbered yet, as Assimp meets them. */
static void number_materials(const gltf_doc *d, uint64_t m, bool *mesh_read, bool *numbered, double *out,
                             size_t *count)
{
    if (m >= d->mesh_materials.lists || mesh_read[m])
        return;
    mesh_read[m] = true;
    for (size_t k = d->mesh_materials.first[m]; k < d->mesh_materials.first[m + 1]; k++) {
        uint64_t g = d->mesh_materials.item[k];
        if (g < d->materials && !numbered[g]) {
            numbered[g] = true;
            out[(*count)++] = d->strength[g];
        }
    }
}

/* Walks the scene as Assimp reads it: each root, depth first, a node's
 * children before its mesh, each node and mesh once. Indices out of range
 * are passed over (Assimp refuses the file). */
static bool walk(const gltf_doc *d, double *out, size_t *count)
{
    size_t nodes = d->children.lists;
    bool *node_read = calloc(nodes + 1, sizeof *node_read);
    bool *mesh_read = calloc(d->mesh_materials.lists + 1, sizeof *mesh_read);
    bool *numbered = calloc(d->materials + 1, sizeof *numbered);
    frame *stack = array_alloc(nodes + 1, sizeof *stack);
    bool ok = node_read && mesh_read && numbered && stack;
    const index_lists *roots = &d->scene_nodes;
    for (size_t k = roots->first[d->scene]; ok && k < roots->first[d->scene + 1]; k++) {
        uint64_t root = roots->item[k];
        if (root >= nodes || node_read[root])
            continue;
        node_read[root] = true;
        size_t depth = 0;
        stack[depth++] = (frame){(size_t)root, d->children.first[root]};
        while (depth > 0) {
            frame *f = &stack[depth - 1];
            if (f->next < d->children.first[f->node + 1]) {
                uint64_t c = d->children.item[f->next++];
                if (c < nodes && !node_read[c]) {
                    node_read[c] = true;
                    stack[depth++] = (frame){(size_t)c, d->children.first[c]};
                }
                continue;
            }
            number_materials(d, d->node_mesh[f->node], mesh_read, numbered, out, count);
            depth--;
        }
    }
    free(node_read);
    free(mesh_read);
    free(numbered);
    free(stack);
    return ok;
}

glint_status gltf_emissive_strengths(const unsigned char *text, size_t size, const char *file, double **strengths,
                                     size_t *count, glint_error *err)
{
    static const char *const keys[] = {"scene", "scenes", "nodes", "meshes", "materials"};
    json_scan r = {.t = text, .size = size};
    gltf_doc d = {.file = file, .err = err};
    *strengths = NULL;
    *count = 0;
    json_skip_space(&r);
    bool read = r.i < size && text[r.i] == '{' && json_each_member(&r, &d, on_top_member, keys, 5);
    glint_status s = d.refused;
    if (!s && read && d.scene < d.scene_nodes.lists && d.materials > 0) {
        *strengths = array_alloc(d.materials, sizeof **strengths);
        if (!*strengths || !walk(&d, *strengths, count))
            r.nomem = true;
    }
    if (!s && r.nomem) {
        free(*strengths);
        *strengths = NULL;
        *count = 0;
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    }
    free(d.scene_nodes.first);
    free(d.scene_nodes.item);
    free(d.children.first);
    free(d.children.item);
    free(d.node_mesh);
    free(d.mesh_materials.first);
    free(d.mesh_materials.item);
    free(d.strength);
    return s;
}
