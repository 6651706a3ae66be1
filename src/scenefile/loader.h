/* loader.h - the scene-file loader's state and the readers its files share:
 * scene_file.c reads files, includes and the root, each file's objects
 * while the file is parsed when it can; read_values.c typed
 * values and parameter tables; read_sections.c settings, camera and fog;
 * read_looks.c textures, materials and lights; read_objects.c objects,
 * groups, transforms and models. The reference for every key is
 * docs/scene-format.md. */
#ifndef GLINT_SCENEFILE_LOADER_H
#define GLINT_SCENEFILE_LOADER_H

#include "core/params.h"
#include "scene/scene.h"
#include "scenefile/sphere_list.h"
#include "scenefile/yaml_read.h"

#define MAX_INCLUDE_DEPTH 16
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

typedef struct loader {
    glint_scene *scene;
    diag d;
    reader r;
    glint_settings settings;
    glint_camera camera;
    glint_fog fog;
    const ynode *settings_node, *camera_node, *fog_node;  /* the last file's, for messages */
    const ynode *focus_on_node;                          /* the camera's focus_on, if given, */
    glint_vec3 focus_on;                                 /* and the point it names */
    unsigned fog_keys;                                   /* FOG_* keys given in any file */
    const char *output;
    const char *chain[MAX_INCLUDE_DEPTH + 1];   /* canonical paths of the files being read */
    int depth;
    ydoc *docs;                                  /* kept until the end: nodes name their file */
    int doc_count;
    size_t doc_cap;
    int files;                                   /* files read so far */
    struct imported *imports;                    /* models read so far: each once */
    int import_count;
    size_t import_cap;
    long bytes;                                  /* bytes read so far, all files */
    long alias_nodes;                            /* nodes the aliases of all files add */
    char **paths;                                /* files named by keys, resolved: freed at the end */
    size_t path_count, path_cap;
    double time;                                 /* seconds: keyed values are read as they are then */
    bool keyed;                                  /* some value was keyed */
    bool streaming;                              /* objects read while parsed: an attempt, silent,
                                                    given up at any problem (scene_file.c) */
    sphere_list spheres;                         /* plain spheres not yet added (read_spheres.c) */
} loader;

/* A model file already imported, so that every object placing it shares
 * one mesh. */
struct imported {
    char *path;               /* canonical */
    double crease_angle;
    int mesh;
};

enum { FOG_TYPE = 1, FOG_START = 2, FOG_END = 4, FOG_DENSITY = 8 };

/* A group's material that was wrong and reported: the objects inside it
 * are not reported again as having no material. */
#define MATERIAL_REPORTED (-2)

/* What an object inherits from the groups around it. */
typedef struct context {
    glint_transform to_world;
    int material;             /* -1: none yet; MATERIAL_REPORTED: a bad one */
    int depth;
    int csg;                  /* the combination objects are parts of, or -1 */
} context;

/* Whether the walk goes on: the problem limit is not reached. */
static inline bool ok(const loader *l)
{
    return !diag_full(&l->d);
}

/* ------------------------------------------------------ read_values.c */

/* Whether n is a keyed value: a map with 'keys' (read_param reads it as
 * it is at the loader's time). */
bool is_keyed(loader *l, const ynode *n);

/* Reads n, the value of parameter p, into its field of obj (at p->offset),
 * checked against p; as it is at the loader's time when keyed. */
bool read_param(loader *l, const ynode *n, const param *p, void *obj);

/* A required number, reported where it is missing or not a number. */
bool need_number(loader *l, const ynode *map, const char *key, const char *what, double *out);

/* A required vector. */
bool need_vec3(loader *l, const ynode *map, const char *key, const char *what, vec3 *out);

/* Matches a scalar against a list of words; reports with a hint. */
int word(loader *l, const ynode *n, const char *key, const char *const *words, int count);

/* The kind of a map that must say its `type`: the index of that word among
 * `kinds`, or -1 after a report. `what` names the map ("a light"). */
int typed_map(loader *l, const ynode *n, const char *what, const char *const *kinds, int count);

/* Joins a path named in file `from` to that file's directory. */
char *relative_to(const char *from, const char *path);

/* Reads every key of table t that map gives into the fields of obj (which
 * holds the defaults), reporting each value of the wrong type or out of
 * range, and each required key that is missing ("<what> needs 'key'").
 * True when all were good. */
bool read_params(loader *l, const ynode *map, param_table t, const char *what, void *obj);

/* A map of table t's keys under `key` of map parent (settings'
 * ambient_occlusion, a material's absorption): when given, obj's fields of
 * t start from their defaults and take its keys. Returns whether it was
 * given and read without a problem. */
bool read_sub_map(loader *l, const ynode *parent, const char *key, param_table t, void *obj);

/* The keys of table t after `common`, into keys (room for `room`); returns
 * how many, for yr_check_keys. */
int param_keys(param_table t, const char *const *common, int common_count, const char **keys, int room);

/* ---------------------------------------------------- read_sections.c */

void read_settings(loader *l, const ynode *n);
void read_camera(loader *l, const ynode *n);
void read_fog(loader *l, const ynode *n);

/* The camera's focus_on, once every file has had its say: a thin lens's
 * focus_distance becomes the depth of that point along the view; false
 * after a report (another camera type, both keys, a point behind). */
bool focus_on_resolve(loader *l);

/* The root's `environment` map: a texture (by name) seen by rays that
 * miss everything, its intensity and rotation. */
void read_environment(loader *l, const ynode *n);

/* The keys fog needs, checked once every file has had its say. */
bool fog_complete(loader *l);

/* ------------------------------------------------------- read_looks.c */

/* A texture or material named `name` in its section, defined from map n. */
void read_texture(loader *l, const char *name, const ynode *n);
void read_material(loader *l, const char *name, const ynode *n);

/* An object's material: a name, or an inline map. -1 when it is wrong. */
int object_material(loader *l, const ynode *n);

/* One item of the lights list. */
void read_light(loader *l, const ynode *n);

/* ----------------------------------------------------- read_objects.c */

/* Adds each object of the list, inside context ctx. */
void read_objects(loader *l, const ynode *list, const context *ctx);

/* Places mesh `mesh_index` for object n with material `look` (-1: the mesh's
 * own) through to_world: in the world, or with csg >= 0 as a part of that
 * combination; reports a failure at n. */
void place_mesh_object(loader *l, const ynode *n, int csg, int mesh_index, int look,
                       const glint_transform *to_world);

/* A mesh object given by its arrays (vertices, optional normals and uvs,
 * faces of 3 or more vertices, split into triangles), placed with material
 * look (-1: none, reported) through to_world, as place_mesh_object does,
 * when no problem came after `before` (read_arrays.c). */
void place_inline_mesh(loader *l, const ynode *n, int csg, int look, const glint_transform *to_world, int before);

/* A heightfield object: its grid from a greyscale image `file` (8 bits a
 * sample, black 0 and white 1) or a list of rows `heights`, in the box
 * min..max, placed with material look (-1: none, reported) through
 * to_world when no problem came after `before` (read_arrays.c). */
void place_heightfield(loader *l, const ynode *n, int look, const glint_transform *to_world, int before);

/* A polygon object n of more than 4 points, or of 4 that are not convex:
 * added as triangles (glint_scene_add_polygon), or its problems reported;
 * true when it was such a polygon (or its points could not be read), false
 * when it is for the polygon shape to take. */
bool many_point_polygon(loader *l, const ynode *n, int look, const glint_transform *to_world, int before);

/* A `transform`, a list of steps (translate, rotate, scale, matrix...),
 * applied to *t in order; every step is read, so each bad one is reported. */
bool read_transform(loader *l, const ynode *n, glint_transform *t);

/* Adds one object (a shape, a group or a mesh), inside context outer. */
void read_object(loader *l, const ynode *n, const context *outer);

/* ----------------------------------------------------- read_spheres.c */

/* Takes sphere s, read for an object inside ctx, into the run of plain
 * spheres when it is one (no transform, not a part of a combination, a
 * material that does not glow, nothing keyed so far); false when the
 * caller adds it as a shape, after spheres_flush. */
bool spheres_gather(loader *l, const glint_shape *s, const context *ctx);

/* Adds the run of plain spheres gathered so far, in file order: a run of
 * SPHERE_RUN or more as one sphere set (glint_scene_add_spheres), a
 * shorter one a shape each. Called before any other object is added and
 * at the end of the objects. */
void spheres_flush(loader *l);


#endif
