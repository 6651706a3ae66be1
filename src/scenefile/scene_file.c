/* scene_file.c - the YAML scene loader: reads each file (bounded, includes
 * followed once, cycles refused), walks its root through the section
 * readers of loader.h, which build the scene through the public API and
 * report every problem at its place. The reference for every key is
 * docs/scene-format.md.
 *
 * A file's objects are read while it is parsed, each object's nodes given
 * back once read (ystream), so that the tree of a million objects never
 * exists whole. That reading is an attempt, silent: when anything goes
 * otherwise than reading the whole tree would (any problem, a section
 * after the objects), the load starts again with whole trees, which makes
 * the reports. A load that succeeds streamed makes the same calls, in the
 * same order, as one with whole trees. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "core/file_log.h"
#include "core/array.h"
#include "core/error.h"
#include "core/message_fit.h"
#include "core/open_file.h"
#include "scene/scene.h"
#include "scenefile/loader.h"
#include "scenefile/scene_bytes.h"
#include "scenefile/scene_file.h"
#include "scenefile/scene_reader.h"

#define MAX_FILES 1000            /* files read for one scene, includes counted */

static scene_file_mode mode = SCENE_FILE_STREAMED;

void scene_file_set_mode(scene_file_mode m)
{
    mode = m;
}

static void read_file(loader *l, const char *path, const ynode *from);

static void read_includes(loader *l, const ynode *n)
{
    if (n->kind == YNODE_SCALAR) {
        const char *path;
        if (!yr_text(&l->r, n, "include", &path))
            return;
        char *full = relative_to(n->file, path);
        if (!full) {
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
            return;
        }
        read_file(l, full, n);
        free(full);
        return;
    }
    if (!yr_is_list(&l->r, n, "'include'"))
        return;
    for (int i = 0; i < n->count && ok(l); i++) {
        if (n->items[i]->kind != YNODE_SCALAR) {
            diag_at(&l->d, n->items[i], "'include' must name files, got %s", ynode_describe(n->items[i]));
            continue;
        }
        read_includes(l, n->items[i]);
    }
}

/* Applies each named item of a map section: textures and materials. */
static void read_named(loader *l, const ynode *section, const char *what,
                       void (*read_one)(loader *, const char *, const ynode *))
{
    if (!yr_is_map(&l->r, section, what))
        return;
    for (int i = 0; i + 1 < section->count && ok(l); i += 2) {
        const ynode *k = section->items[i];
        if (k->kind != YNODE_SCALAR || k->value[0] == '\0') {
            diag_at(&l->d, k, "a name in %s must be a word, got %s", what, ynode_describe(k));
            continue;
        }
        read_one(l, k->value, section->items[i + 1]);
    }
}

/* The keys of root mapping `root` and every section but the objects, in
 * their order; false when the format's version is not one this glint
 * reads, and nothing more is read. */
static bool read_head(loader *l, const ynode *root)
{
    static const char *const keys[] = {"glint",    "include",     "settings",  "camera", "fog",
                                       "textures", "environment", "materials", "lights", "objects"};
    yr_check_keys(&l->r, root, "the scene", keys, COUNT(keys));
    const ynode *n;
    double version;
    if ((n = yr_get(&l->r, root, "glint")) && yr_number(&l->r, n, "glint", &version) && version != 1) {
        diag_at(&l->d, n, "format version %g is not supported (this glint reads version 1)", version);
        return false;
    }
    if ((n = yr_get(&l->r, root, "include")))
        read_includes(l, n);
    if ((n = yr_get(&l->r, root, "settings")))
        read_settings(l, n);
    if ((n = yr_get(&l->r, root, "camera")))
        read_camera(l, n);
    if ((n = yr_get(&l->r, root, "fog")))
        read_fog(l, n);
    if ((n = yr_get(&l->r, root, "textures")))
        read_named(l, n, "'textures'", read_texture);
    if ((n = yr_get(&l->r, root, "environment")))
        read_environment(l, n);
    if ((n = yr_get(&l->r, root, "materials")))
        read_named(l, n, "'materials'", read_material);
    if ((n = yr_get(&l->r, root, "lights")) && yr_is_list(&l->r, n, "'lights'"))
        for (int i = 0; i < n->count && ok(l); i++)
            read_light(l, n->items[i]);
    return true;
}

/* What the objects of a file's root are inside: nothing. */
static context top_context(void)
{
    return (context){glint_transform_identity(), -1, 0, -1};
}

static void read_root(loader *l, const ynode *root)
{
    if (!yr_is_map(&l->r, root, "a scene file") || !read_head(l, root))
        return;
    const ynode *n = yr_get(&l->r, root, "objects");
    context top = top_context();
    if (n)
        read_objects(l, n, &top);
}

/* A file whose objects are read while it is parsed: the ystream hooks'
 * user. Each stops the parse at the first problem, which gives up the
 * attempt. */
typedef struct streamed_file {
    loader *l;
    bool begun;               /* the root before the objects has been read */
} streamed_file;

static bool stream_begin(void *user, const ynode *root)
{
    streamed_file *f = user;
    f->begun = true;
    read_head(f->l, root);
    return f->l->d.count == 0;
}

static bool stream_item(void *user, const ynode *item)
{
    loader *l = ((streamed_file *)user)->l;
    context top = top_context();
    read_object(l, item, &top);
    return l->d.count == 0;
}

/* Reports each alias of document docs[index] that names no anchor before
 * it, saying where that anchor is when a later line or another file has
 * one: anchors do not cross files. */
static void report_unknown_aliases(loader *l, int index)
{
    const ydoc *doc = &l->docs[index];
    for (int i = 0; i < doc->unknown_count && ok(l); i++) {
        const char *name = doc->unknown[i].name, *file = NULL;
        const ynode *later = NULL;
        for (int k = 0; k < doc->anchor_count && !later; k++)
            if (strcmp(doc->anchors[k].name, name) == 0)
                later = doc->anchors[k].node;
        for (int d = 0; d < l->doc_count && !file; d++)
            for (int k = 0; d != index && k < l->docs[d].anchor_count && !file; k++)
                if (strcmp(l->docs[d].anchors[k].name, name) == 0)
                    file = l->docs[d].name;
        const ynode *at = doc->unknown[i].node;
        if (later)
            diag_at(&l->d, at, "unknown anchor '%.100s': '&%.100s' comes later, at line %d, and an anchor must come "
                               "before its aliases", name, name, later->line);
        else if (file)
            diag_at(&l->d, at, "unknown anchor '%.100s': anchors do not cross files (it is defined in %.200s)", name,
                    file);
        else
            diag_at(&l->d, at, "unknown anchor '%.100s': no '&%.100s' comes before it%s", name, name,
                    l->doc_count > 1 ? " in this file (anchors do not cross files)" : "");
    }
}

/* Room in l for one more document; false after a report. */
static bool room_for_doc(loader *l)
{
    if (array_reserve((void **)&l->docs, &l->doc_cap, (size_t)l->doc_count + 1, sizeof *l->docs))
        return true;
    diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
    return false;
}

/* Parses bytes named `name` and walks them (their objects while they are
 * parsed, when streaming); the tree stays alive in l. root: whether they
 * are the scene's own, not an include's. */
static void read_bytes(loader *l, const char *data, size_t size, const char *name, bool root)
{
    if (!room_for_doc(l))
        return;
    /* Parsed outside l->docs: includes read while it is parsed (streaming)
     * add theirs, which may move the array. */
    glint_error err;
    ydoc doc;
    streamed_file file = {l, false};
    const ystream hooks = {"objects", stream_begin, stream_item, &file};
    glint_status s = ydoc_parse(&doc, data, size, name, &l->alias_nodes, l->streaming ? &hooks : NULL, &err);
    if (s) {
        diag_raw(&l->d, s, err.message);
        return;
    }
    if (!room_for_doc(l)) {
        ydoc_free(&doc);
        return;
    }
    l->docs[l->doc_count++] = doc;
    if (doc.unknown_count) {
        /* The includes first: an anchor in one of them is named in the message. */
        const ynode *include = doc.root ? yr_get(&l->r, doc.root, "include") : NULL;
        int index = l->doc_count - 1;
        if (include)
            read_includes(l, include);
        report_unknown_aliases(l, index);
        return;
    }
    bool empty = !doc.root || strcmp(ynode_describe(doc.root), "nothing") == 0;
    if (empty && root) {
        /* Rendering black for an empty scene hides a wrong path or an
         * editor's lost save. An empty include is fine: a placeholder. */
        char msg[MESSAGE_ROOM];
        snprintf(msg, sizeof msg, "%s: the file holds no scene", name);
        diag_raw(&l->d, GLINT_ERR_INVALID, msg);
        return;
    }
    if (!empty && !file.begun)
        read_root(l, doc.root);
}

static void read_file(loader *l, const char *path, const ynode *from)
{
    char canonical[PATH_MAX];
    if (!file_realpath(path, canonical)) {
        if (from)
            diag_at(&l->d, from, "cannot include '%s': %s", path, strerror(errno));
        else {
            char msg[MESSAGE_ROOM];
            snprintf(msg, sizeof msg, "cannot read scene '%s': %s", path, strerror(errno));
            diag_raw(&l->d, GLINT_ERR_IO, msg);
        }
        return;
    }
    for (int i = 0; i < l->depth; i++) {
        if (strcmp(l->chain[i], canonical) != 0)
            continue;
        char cycle[400] = "";
        for (int k = i; k < l->depth; k++) {
            strncat(cycle, strrchr(l->chain[k], '/') + 1, sizeof cycle - strlen(cycle) - 1);
            strncat(cycle, " -> ", sizeof cycle - strlen(cycle) - 1);
        }
        strncat(cycle, strrchr(canonical, '/') + 1, sizeof cycle - strlen(cycle) - 1);
        diag_at(&l->d, from, "include cycle: %s", cycle);
        return;
    }
    if (l->depth >= MAX_INCLUDE_DEPTH) {
        diag_at(&l->d, from, "includes nested too deep (limit %d)", MAX_INCLUDE_DEPTH);
        return;
    }
    /* Includes can fan out (a list of files each including a list...), so
     * the files and bytes of one scene are bounded as a whole. */
    if (++l->files > MAX_FILES) {
        diag_at(&l->d, from, "too many included files (limit %d)", MAX_FILES);
        l->d.closed = true;
        return;
    }
    glint_error err;
    size_t size = 0;
    struct stat st;
    char *data = scene_bytes_of_file(path, from != NULL, &size, &st, &err);
    if (data && scene_note_file(l->scene, &st, &err)) {
        free(data);
        data = NULL;
    }
    if (!data) {
        if (from)
            diag_error(&l->d, from, &err);
        else
            diag_raw(&l->d, err.status, err.message);
        return;
    }
    l->bytes += (long)size;
    if (l->bytes > SCENE_FILE_MAX_BYTES) {
        diag_at(&l->d, from, "scene files too large together (limit %ld bytes)", SCENE_FILE_MAX_BYTES);
        l->d.closed = true;
        free(data);
        return;
    }
    l->chain[l->depth++] = canonical;
    read_bytes(l, data, size, path, from == NULL);
    l->depth--;
    free(data);
}

/* Hands the gathered settings, camera and fog to the scene. */
static void finish(loader *l, const char *name)
{
    glint_error err;
    const ynode *where[] = {l->settings_node, l->camera_node, l->fog_node};
    glint_status s[] = {glint_scene_set_settings(l->scene, &l->settings, &err), GLINT_OK, GLINT_OK};
    for (int i = 0; i < 3; i++) {
        if (i == 1 && focus_on_resolve(l))
            s[1] = glint_scene_set_camera(l->scene, &l->camera, &err);
        if (i == 2 && (!l->fog_node || fog_complete(l)))
            s[2] = glint_scene_set_fog(l->scene, &l->fog, &err);
        if (s[i] && where[i])
            diag_error(&l->d, where[i], &err);
        else if (s[i]) {
            char msg[MESSAGE_ROOM];
            snprintf(msg, sizeof msg, "%s: %s", name, err.message);
            diag_raw(&l->d, s[i], msg);
        }
    }
    if (l->output && glint_scene_set_output(l->scene, l->output, &err))
        diag_raw(&l->d, GLINT_ERR_NOMEM, err.message);
}

/* Reads a scene through `body`, streaming or not; the scene, or NULL after
 * reporting. A streamed load reports to no one and stops at its first
 * problem: it is only an attempt. */
static glint_scene *load_once(const glint_load_options *o, glint_error *err, const char *name,
                              void (*body)(loader *, const void *, size_t, const char *), const void *data,
                              size_t size, bool streaming)
{
    loader l;
    memset(&l, 0, sizeof l);
    l.scene = glint_scene_new();
    if (!l.scene) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    if (streaming)
        l.d = (diag){.max = 1, .first = err};
    else
        l.d = (diag){.report = o ? o->report : NULL, .user = o ? o->report_user : NULL,
                     .max = o && o->max_errors > 0 ? o->max_errors : 20, .first = err};
    l.streaming = streaming;
    l.time = o ? o->time : 0;
    l.r.d = &l.d;
    l.settings = glint_scene_get_settings(l.scene);
    l.camera = glint_scene_get_camera(l.scene);
    l.fog = (glint_fog){.kind = GLINT_FOG_NONE, .color = {1, 1, 1}};
    body(&l, data, size, name);
    if (l.d.count == 0)
        spheres_flush(&l);
    sphere_list_free(&l.spheres);
    if (l.d.count == 0)
        finish(&l, name);
    for (int i = 0; i < l.doc_count; i++)
        ydoc_free(&l.docs[i]);
    free(l.docs);
    for (int i = 0; i < l.import_count; i++)
        free(l.imports[i].path);
    free(l.imports);
    for (size_t i = 0; i < l.path_count; i++)
        free(l.paths[i]);
    free(l.paths);
    if (l.d.count > 0) {
        glint_scene_free(l.scene);
        return NULL;
    }
    l.scene->animated = l.keyed;
    return l.scene;
}

/* Reads a scene streamed and, when that attempt gives up, again with whole
 * trees (scene_file_mode): the bytes of `data` are read twice then, and
 * a file's again. */
static glint_scene *load_at(const glint_load_options *o, glint_error *err, const char *name,
                            void (*body)(loader *, const void *, size_t, const char *), const void *data, size_t size)
{
    glint_error attempt;
    if (mode == SCENE_FILE_STREAMED_ONLY)
        return load_once(o, err, name, body, data, size, true);
    glint_scene *scene = mode == SCENE_FILE_STREAMED ? load_once(o, &attempt, name, body, data, size, true) : NULL;
    return scene ? scene : load_once(o, err, name, body, data, size, false);
}

/* Whether two transforms are the same, bit for bit. */
static bool same_transform(const glint_transform *a, const glint_transform *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

/* Gives an animated scene with a shutter its motion (docs/animation.md):
 * the scene read again at each of its shutter's poses, evenly spaced from
 * the opening to the closing, and each shape and placed mesh whose
 * transform changes, each light and a camera that do, moved through
 * them. The scene itself, or NULL after
 * a failure (reported, and in err), freed. */
static glint_scene *add_motion(glint_scene *scene, const glint_load_options *o, glint_error *err, const char *name,
                               void (*body)(loader *, const void *, size_t, const char *), const void *data,
                               size_t size)
{
    const glint_settings s = scene->settings;
    if (!scene->animated || !(s.shutter_close > s.shutter_open))
        return scene;
    int poses = s.shutter_steps, shapes = scene->shape_count, lights = scene->light_count;
    int placed = scene->instance_count;
    glint_transform *xf = malloc(sizeof *xf * (size_t)poses * (size_t)(shapes + placed + 1));
    glint_light *lamp = malloc(sizeof *lamp * (size_t)poses * (size_t)(lights ? lights : 1));
    glint_camera cameras[64];
    bool good = xf && lamp;
    if (!good)
        error_set(err, GLINT_ERR_NOMEM, "out of memory for the scene's motion");
    for (int k = 0; k < poses && good; k++) {
        glint_load_options at = o ? *o : (glint_load_options){0};
        at.time += (s.shutter_open + (s.shutter_close - s.shutter_open) * k / (poses - 1)) / s.fps;
        glint_scene *pose = load_at(&at, err, name, body, data, size);
        good = pose && pose->shape_count == shapes && pose->light_count == lights && pose->instance_count == placed;
        if (pose && !good)
            error_set(err, GLINT_ERR_INVALID, "'%s' has other shapes or lights at %g s than at %g s", name, at.time,
                      o ? o->time : 0);
        for (int i = 0; good && i < shapes + placed; i++)
            xf[(size_t)i * poses + k] = i < shapes ? pose->shapes[i].to_world : pose->instances[i - shapes].to_world;
        for (int i = 0; good && i < lights; i++)
            lamp[(size_t)i * poses + k] = pose->lights[i].desc;
        if (good)
            cameras[k] = pose->camera;
        glint_scene_free(pose);
    }
    for (int i = 0; good && i < shapes + placed; i++) {
        const glint_transform *mine = &xf[(size_t)i * poses];
        bool moves = false;
        for (int k = 1; k < poses; k++)
            moves |= !same_transform(&mine[k], &mine[0]);
        good = !moves || (i < shapes ? glint_scene_move_shape(scene, i, poses, mine, err)
                                     : glint_scene_move_instance(scene, i - shapes, poses, mine, err)) == GLINT_OK;
    }
    for (int i = 0; good && i < lights; i++) {
        const glint_light *mine = &lamp[(size_t)i * poses];
        bool moves = false;
        for (int k = 1; k < poses; k++)
            moves |= memcmp(&mine[k], &mine[0], sizeof mine[0]) != 0;
        good = !moves || glint_scene_move_light(scene, i, poses, mine, err) == GLINT_OK;
    }
    bool camera_moves = false;
    for (int k = 1; good && k < poses; k++)
        camera_moves |= memcmp(&cameras[k], &cameras[0], sizeof cameras[0]) != 0;
    if (good && camera_moves)
        good = glint_scene_move_camera(scene, poses, cameras, err) == GLINT_OK;
    free(xf);
    free(lamp);
    if (!good) {
        glint_scene_free(scene);
        return NULL;
    }
    return scene;
}

/* A scene as it is at o's time, with the motion over its shutter. */
static glint_scene *load(const glint_load_options *o, glint_error *err, const char *name,
                         void (*body)(loader *, const void *, size_t, const char *), const void *data, size_t size)
{
    if (o && !isfinite(o->time)) {
        error_set(err, GLINT_ERR_INVALID, "the time to load '%s' at must be a finite number of seconds", name);
        return NULL;
    }
    glint_scene *scene = load_at(o, err, name, body, data, size);
    return scene ? add_motion(scene, o, err, name, body, data, size) : NULL;
}

static void body_file(loader *l, const void *data, size_t size, const char *name)
{
    read_file(l, name, NULL);
}

static void body_memory(loader *l, const void *data, size_t size, const char *name)
{
    read_bytes(l, data, size, name, true);
}

/* A stream's bytes, read whole before loading (yaml_load_stream): they
 * count towards the limit of all files, as a file's do. */
static void body_stream(loader *l, const void *data, size_t size, const char *name)
{
    l->bytes = (long)size;
    read_bytes(l, data, size, name, true);
}

/* A stream that could not be read: err says why. */
static void body_unread(loader *l, const void *err, size_t unused, const char *name)
{
    const glint_error *e = err;
    diag_raw(&l->d, e->status, e->message);
}

static glint_scene *yaml_load_file(const char *path, const glint_load_options *options, glint_error *err)
{
    return load(options, err, path, body_file, NULL, 0);
}

static glint_scene *yaml_load_memory(const char *data, size_t size, const char *name,
                                     const glint_load_options *options, glint_error *err)
{
    return load(options, err, name ? name : "<memory>", body_memory, data, size);
}

/* The stream is read whole first: the tree's nodes point into the bytes,
 * the limit is a file's, and a load given up streamed reads them again. */
static glint_scene *yaml_load_stream(FILE *in, const char *name, const glint_load_options *options,
                                     glint_error *err)
{
    name = name ? name : "<stream>";
    glint_error unread;
    size_t size = 0;
    char *data = scene_bytes_of_stream(in, name, &size, &unread);
    glint_scene *scene = data ? load(options, err, name, body_stream, data, size)
                              : load(options, err, name, body_unread, &unread, 0);
    free(data);
    return scene;
}

static const char *const YAML_EXTENSIONS[] = {".yaml", ".yml", NULL};

const scene_reader yaml_scene_reader = {
    .name = "YAML", .extensions = YAML_EXTENSIONS, .load_file = yaml_load_file, .load_memory = yaml_load_memory,
    .load_stream = yaml_load_stream,
};

