/* read_objects.c - the scene file's objects: shapes of every registered
 * kind, groups with their transforms and materials, and model files. */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/file_log.h"
#include "core/array.h"
#include "core/transform.h"
#include "geometry/shape_kind.h"
#include "scenefile/loader.h"

#define MAX_GROUP_DEPTH 32

/* A matrix step's value: three rows of four numbers, the glint_transform
 * that maps (x, y, z, 1). */
static bool read_matrix(loader *l, const ynode *v, glint_transform *m)
{
    if (v->kind == YNODE_SEQUENCE && v->count == 3) {
        bool good = true;
        for (int i = 0; i < 3 && good; i++) {
            const ynode *row = v->items[i];
            good = row->kind == YNODE_SEQUENCE && row->count == 4;
            for (int j = 0; j < 4 && good; j++)
                good = yr_number(&l->r, row->items[j], "matrix", &m->m[i][j]);
        }
        if (good)
            return true;
    }
    diag_at(&l->d, v, "'matrix' must be 3 rows of 4 numbers, [[a, b, c, d], [e, f, g, h], [i, j, k, l]]");
    return false;
}

/* t followed by m. With the identity on either side it is the other, bit
 * for bit, as the product could turn a -0 into a 0: a scene written back as
 * a file (glint_scene_write_yaml) must place its objects exactly. */
static glint_transform then(const glint_transform *t, const glint_transform *m)
{
    return xf_is_identity(t) ? *m : xf_is_identity(m) ? *t : xf_mul(m, t);
}

/* The value v of a transform step's `key`, a number or a vector (type),
 * keyed or not. */
static bool step_value(loader *l, const ynode *v, const char *key, param_type type, void *out)
{
    const param p = {.key = key, .type = type, .lo = -DBL_MAX, .hi = DBL_MAX};
    return read_param(l, v, &p, out);
}

/* A step's scale: one number for all three axes, or a vector; keyed, the
 * first key's value says which. */
static bool step_scale(loader *l, const ynode *v, vec3 *out)
{
    const ynode *first = v;
    if (is_keyed(l, v)) {
        const ynode *keys = yr_get(&l->r, v, "keys");
        if (keys->kind == YNODE_SEQUENCE && keys->count > 0 && keys->items[0]->kind == YNODE_SEQUENCE &&
            keys->items[0]->count == 2)
            first = keys->items[0]->items[1];
    }
    if (first->kind != YNODE_SCALAR)
        return step_value(l, v, "scale", PARAM_VEC3, out);
    double a;
    if (!step_value(l, v, "scale", PARAM_NUMBER, &a))
        return false;
    *out = v3(a, a, a);
    return true;
}

/* One step of a transform, applied to *t, with keyed values as they are at
 * the loader's time; false after a report. */
static bool read_step(loader *l, const ynode *step, glint_transform *t)
{
    static const char *const steps[] = {"translate", "rotate", "rotate_x", "rotate_y", "rotate_z", "scale", "matrix"};
    static const char *const rotate_keys[] = {"axis", "angle"};
    if (step->kind != YNODE_MAPPING || step->count != 2) {
        diag_at(&l->d, step, "each transform step is a map with one key: translate, rotate, rotate_x, "
                             "rotate_y, rotate_z, scale or matrix");
        return false;
    }
    const ynode *key = step->items[0], *v = step->items[1];
    int k = word(l, key, "transform step", steps, COUNT(steps));
    vec3 vec;
    double a;
    if (k == 0) {
        if (!step_value(l, v, "translate", PARAM_VEC3, &vec))
            return false;
        *t = glint_transform_translate(*t, vec.x, vec.y, vec.z);
    } else if (k == 1) {
        if (!yr_is_map(&l->r, v, "'rotate'"))
            return false;
        yr_check_keys(&l->r, v, "rotate", rotate_keys, COUNT(rotate_keys));
        const ynode *axis = yr_need(&l->r, v, "axis", "rotate"), *angle = yr_need(&l->r, v, "angle", "rotate");
        bool good = axis && step_value(l, axis, "axis", PARAM_VEC3, &vec);
        if (good && v3_length(vec) == 0) {
            diag_at(&l->d, axis, "'axis' must not be zero");
            good = false;
        }
        if (!(angle && step_value(l, angle, "angle", PARAM_NUMBER, &a)) || !good)
            return false;
        *t = glint_transform_rotate(*t, vec, a);
    } else if (k >= 2 && k <= 4) {
        if (!step_value(l, v, steps[k], PARAM_NUMBER, &a))
            return false;
        vec3 axis = v3(k == 2, k == 3, k == 4);
        *t = glint_transform_rotate(*t, axis, a);
    } else if (k == 5) {
        if (!step_scale(l, v, &vec))
            return false;
        if (vec.x == 0 || vec.y == 0 || vec.z == 0) {
            diag_at(&l->d, v, "'scale' must not be zero");
            return false;
        }
        *t = glint_transform_scale(*t, vec.x, vec.y, vec.z);
    } else if (k == 6) {
        glint_transform m;
        if (is_keyed(l, v)) {
            diag_at(&l->d, v, "'matrix' cannot change with time: key its steps (translate, rotate, scale)");
            return false;
        }
        if (!read_matrix(l, v, &m))
            return false;
        *t = then(t, &m);
    }
    return k >= 0;
}

bool read_transform(loader *l, const ynode *n, glint_transform *t)
{
    if (!yr_is_list(&l->r, n, "'transform'"))
        return false;
    bool good = true;
    for (int i = 0; i < n->count && ok(l); i++)
        good = read_step(l, n->items[i], t) && good;
    return good;
}

void read_objects(loader *l, const ynode *list, const context *ctx);

/* The mesh of a model file, imported on first use. */
static int import_model(loader *l, const ynode *file, const char *path, double crease)
{
    char canonical[PATH_MAX];
    if (!file_realpath(path, canonical)) {
        diag_at(&l->d, file, "cannot read model '%s': %s", path, strerror(errno));
        return -1;
    }
    for (int i = 0; i < l->import_count; i++)
        if (l->imports[i].crease_angle == crease && strcmp(l->imports[i].path, canonical) == 0)
            return l->imports[i].mesh;
    glint_import_options o = {.crease_angle = crease, .default_material = -1};
    glint_error err;
    int mesh_index = glint_scene_import_mesh(l->scene, path, &o, &err);
    if (mesh_index < 0) {
        diag_error(&l->d, file, &err);
        return -1;
    }
    /* Without room to remember it, a later object imports the file again. */
    if (!array_reserve((void **)&l->imports, &l->import_cap, (size_t)l->import_count + 1, sizeof *l->imports))
        return mesh_index;
    char *copy = strdup(canonical);
    if (copy)
        l->imports[l->import_count++] = (struct imported){copy, crease, mesh_index};
    return mesh_index;
}

void place_mesh_object(loader *l, const ynode *n, int csg, int mesh_index, int look,
                       const glint_transform *to_world)
{
    glint_error err;
    int made = csg >= 0 ? glint_scene_add_mesh_part(l->scene, csg, mesh_index, look, to_world, &err)
                        : glint_scene_add_instance(l->scene, mesh_index, look, to_world, &err);
    if (made < 0)
        diag_error(&l->d, n, &err);
}

/* A mesh object: its model file's triangles, placed. `look` (>= 0), its
 * own material or its group's, replaces the file's materials when it is
 * its own (`own`) or the file gives none. The file is read (and a file
 * that cannot be is reported) even when the object has other problems,
 * but placed only when it has none: when the count of problems is still
 * `before` and its material was not a bad one. */
static void place_mesh(loader *l, const ynode *n, int csg, int look, bool own, const glint_transform *to_world,
                       int before)
{
    const ynode *file = yr_need(&l->r, n, "file", "mesh");
    const char *path;
    glint_import_options options;
    params_defaults(import_params(), &options);
    /* A bad crease angle leaves the default, with which the file is read. */
    read_params(l, n, import_params(), "mesh", &options);
    if (!file || !yr_text(&l->r, file, "file", &path))
        return;
    char *full = relative_to(n->file, path);
    if (!full) {
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return;
    }
    int mesh_index = import_model(l, file, full, options.crease_angle);
    free(full);
    int override = own || glint_scene_mesh_is_bare(l->scene, mesh_index) ? look : -1;
    if (mesh_index >= 0 && l->d.count == before && override != MATERIAL_REPORTED)
        place_mesh_object(l, n, csg, mesh_index, override, to_world);
}

/* The object types that are not shapes. */
enum { OBJECT_GROUP, OBJECT_MESH, OBJECT_HEIGHTFIELD, OBJECT_SHAPE };
static const char *const NOT_SHAPES[] = {"group", "mesh", "heightfield"};
static const char *const GROUP_KEYS[] = {"objects"};
static const char *const MESH_KEYS[] = {"file", "crease_angle", "vertices", "normals", "uvs", "faces"};
static const char *const HEIGHTFIELD_KEYS[] = {"file", "heights", "min", "max"};

/* The type of object map n: a group, a mesh or (with *kind set) a shape;
 * -1 after a report. */
static int object_type(loader *l, const ynode *n, const shape_kind **kind)
{
    const char *names[32];
    int shapes = shape_kind_count(), count = 0;
    for (int i = 0; i < shapes && count < COUNT(names); i++)
        names[count++] = shape_kind_at(i)->name;
    for (int i = 0; i < COUNT(NOT_SHAPES) && count < COUNT(names); i++)
        names[count++] = NOT_SHAPES[i];
    int k = typed_map(l, n, "an object", names, count);
    if (k < 0 || k >= shapes)
        return k < 0 ? -1 : k - shapes;
    *kind = shape_kind_at(k);
    return OBJECT_SHAPE;
}

/* Adds shape s with ctx's material to the scene, or to the combination
 * ctx->csg. */
static int add_to(loader *l, const context *ctx, const glint_shape *s, const glint_transform *xf, glint_error *err)
{
    if (ctx->csg >= 0)
        return glint_scene_add_part(l->scene, ctx->csg, s, ctx->material, xf, err);
    return glint_scene_add_shape(l->scene, s, ctx->material, xf, err);
}

/* Adds a combination of `kind` for object n, which its objects are read
 * into: ctx->csg becomes it. False after a report (or a problem before). */
static bool add_combination(loader *l, const ynode *n, const shape_kind *kind, context *ctx, int before)
{
    if (l->d.count != before || ctx->material == MATERIAL_REPORTED)
        return false;
    glint_shape s = glint_shape_default(kind->id);
    glint_error err;
    int index = add_to(l, ctx, &s, NULL, &err);
    if (index < 0) {
        diag_error(&l->d, n, &err);
        return false;
    }
    ctx->csg = index;
    return true;
}

void read_object(loader *l, const ynode *n, const context *outer)
{
    static const char *const common[] = {"type", "material", "transform"};
    const shape_kind *kind = NULL;
    int type = object_type(l, n, &kind);
    if (type < 0)
        return;
    /* Whatever else comes adds after the spheres before it. */
    if (kind != &sphere_kind)
        spheres_flush(l);
    const char *keys[24];
    int count = 0;
    if (type == OBJECT_SHAPE) {
        count = param_keys(kind->params, common, COUNT(common), keys, COUNT(keys));
        if (kind->csg)
            keys[count++] = GROUP_KEYS[0];
    } else {
        const char *const *extra = type == OBJECT_GROUP ? GROUP_KEYS : type == OBJECT_MESH ? MESH_KEYS : HEIGHTFIELD_KEYS;
        int extra_count = type == OBJECT_GROUP  ? COUNT(GROUP_KEYS)
                          : type == OBJECT_MESH ? COUNT(MESH_KEYS)
                                                : COUNT(HEIGHTFIELD_KEYS);
        for (int i = 0; i < COUNT(common); i++)
            keys[count++] = common[i];
        for (int i = 0; i < extra_count; i++)
            keys[count++] = extra[i];
    }
    const char *what = kind ? kind->name : NOT_SHAPES[type];
    yr_check_keys(&l->r, n, what, keys, count);

    /* Every key is read even after a bad one, so that one run reports all
     * of the object's problems; the object is added only when it has none. */
    int before = l->d.count;
    context ctx = *outer;
    glint_transform own = glint_transform_identity();
    const ynode *xf = yr_get(&l->r, n, "transform");
    if (xf)
        read_transform(l, xf, &own);
    ctx.to_world = then(&own, &outer->to_world);
    const ynode *mat = yr_get(&l->r, n, "material");
    if (mat && (ctx.material = object_material(l, mat)) < 0)
        ctx.material = MATERIAL_REPORTED;

    if (type == OBJECT_HEIGHTFIELD && ctx.csg >= 0) {
        diag_at(&l->d, n, "a heightfield is open at its sides, so it cannot be a part of a union, intersection or "
                "difference");
        return;
    }
    if (type == OBJECT_HEIGHTFIELD) {
        place_heightfield(l, n, ctx.material, &ctx.to_world, before);
        return;
    }
    if (type == OBJECT_MESH && yr_get(&l->r, n, "vertices")) {
        if (yr_get(&l->r, n, "file"))
            diag_at(&l->d, n, "a mesh takes a 'file' or its 'vertices' and 'faces', not both");
        else
            place_inline_mesh(l, n, ctx.csg, ctx.material, &ctx.to_world, before);
        return;
    }
    if (type == OBJECT_MESH) {
        place_mesh(l, n, ctx.csg, ctx.material, mat != NULL, &ctx.to_world, before);
        return;
    }
    if (type == OBJECT_GROUP || kind->csg) {
        if (outer->depth >= MAX_GROUP_DEPTH) {
            diag_at(&l->d, n, "groups nested too deep (limit %d)", MAX_GROUP_DEPTH);
            return;
        }
        const ynode *children = yr_need(&l->r, n, "objects", what);
        ctx.depth++;
        /* A group inside a combination is one part: the union of its objects. */
        if ((type != OBJECT_GROUP || ctx.csg >= 0) && !add_combination(l, n, kind ? kind : &union_kind, &ctx, before))
            return;
        if (children)
            read_objects(l, children, &ctx);
        if (children && ctx.csg != outer->csg && children->kind == YNODE_SEQUENCE && children->count == 0)
            diag_at(&l->d, children, "%s %s needs at least one object", object_article(what), what);
        return;
    }
    if (kind->id == GLINT_SHAPE_POLYGON && ctx.csg < 0 && many_point_polygon(l, n, ctx.material, &ctx.to_world, before))
        return;
    glint_shape s = glint_shape_default(kind->id);
    read_params(l, n, kind->params, kind->name, &s);
    if (ctx.material == -1)
        diag_at(&l->d, n, "%s needs 'material'", kind->name);
    if (ctx.material < 0 || l->d.count != before || spheres_gather(l, &s, &ctx))
        return;
    spheres_flush(l);
    glint_error err;
    if (add_to(l, &ctx, &s, &ctx.to_world, &err) < 0)
        diag_error(&l->d, n, &err);
}

void read_objects(loader *l, const ynode *list, const context *ctx)
{
    if (!yr_is_list(&l->r, list, "'objects'"))
        return;
    for (int i = 0; i < list->count && ok(l); i++)
        read_object(l, list->items[i], ctx);
}

