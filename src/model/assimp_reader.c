/* assimp_reader.c - the Assimp reader: PLY, STL, glTF and GLB through
 * Assimp's C API, from the model's bytes, which have passed their
 * format's check (ply_check.c, gltf_check.c) so that only the readers
 * glint documents ever see them. Assimp triangulates, flattens the node
 * hierarchy into world positions, generates missing normals, drops points
 * and lines and validates; its meshes are then merged into one
 * (assimp_merge.c), and its materials become glint's (assimp_material.c),
 * with the emissive strength of a glTF's, which Assimp does not read
 * (gltf_emissive.c).
 * Assimp's C API attaches no logger unless asked, so nothing is printed. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include "core/error.h"
#include "model/assimp_calls.h"
#include "model/assimp_check.h"
#include "model/assimp_io.h"
#include "model/assimp_material.h"
#include "model/assimp_merge.h"
#include "model/gltf_emissive.h"
#include "model/model_build.h"

/* Assimp's C API keeps the last error message in one global string. */
static pthread_mutex_t assimp_lock = PTHREAD_MUTEX_INITIALIZER;

/* Debian builds Assimp with its internal assertions on, and a failed one
 * prints to stderr and aborts the process: a malformed file can reach some.
 * This definition takes the place of Assimp's own reporting function (its
 * code calls it through the PLT), so that a failed assertion only marks the
 * import failed and Assimp goes on as its release builds, where the checks
 * are compiled out, do. */
void assimp_assert_failed(const char *expression, const char *file, int line)
    __asm__("_ZN6Assimp17aiAssertViolationEPKcS1_i");
static _Thread_local const char *failed_assertion;

void assimp_assert_failed(const char *expression, const char *file, int line)
{
    if (!failed_assertion)
        failed_assertion = expression;
}

/* Assimp's message, on one line of printable characters. */
static void assimp_message(char *out, size_t size)
{
    const char *msg = assimp->GetErrorString();
    size_t n = 0;
    for (; msg && msg[n] && msg[n] != '\n' && msg[n] != '\r' && n + 1 < size; n++)
        out[n] = (unsigned char)msg[n] < 32 || msg[n] == 127 ? '?' : msg[n];
    while (n > 0 && out[n - 1] == ' ')
        n--;
    out[n] = '\0';
    if (n == 0)
        snprintf(out, size, "Assimp could not read it");
}

/* Checks what Assimp's reader makes of the file, before its post-processing,
 * which trusts it: a face without vertices, or naming one out of range,
 * sends some of its steps outside their arrays. Non-finite positions are
 * refused here too, where Assimp would silently drop their parts. */
static glint_status check_read(const struct aiScene *ai, const char *file, glint_error *err)
{
    for (unsigned i = 0; i < ai->mNumMeshes; i++) {
        const struct aiMesh *m = ai->mMeshes[i];
        if (!m || !m->mVertices || (m->mNumFaces && !m->mFaces))
            return error_set(err, GLINT_ERR_INVALID, "%s: a part is incomplete", file);
        for (unsigned v = 0; v < m->mNumVertices; v++) {
            struct aiVector3D p = m->mVertices[v];
            if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z))
                return error_set(err, GLINT_ERR_INVALID, "%s: a vertex is not finite (%g %g %g)", file, p.x, p.y,
                                 p.z);
        }
        for (unsigned f = 0; f < m->mNumFaces; f++) {
            const struct aiFace *face = &m->mFaces[f];
            if (face->mNumIndices == 0 || !face->mIndices)
                return error_set(err, GLINT_ERR_INVALID, "%s: a face has no vertices", file);
            for (unsigned k = 0; k < face->mNumIndices; k++)
                if (face->mIndices[k] >= m->mNumVertices)
                    return error_set(err, GLINT_ERR_INVALID, "%s: a face uses vertex %u of a part with %u", file,
                                     face->mIndices[k], m->mNumVertices);
        }
    }
    return GLINT_OK;
}

/* Reads src with Assimp twice: once without post-processing for
 * check_read, then, when that passes, with it. (Applying the post-processing
 * to the first reading, aiApplyPostProcessing, frees the scene twice when a
 * step fails in Assimp 5.2.5.) On failure fills err. */
static const struct aiScene *assimp_read(assimp_source *src, const char *file, glint_error *err)
{
    /* Normals are glint's own (assimp_make_normals): Assimp's smoothing
     * is quadratic in the vertices that share a point. */
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                           aiProcess_SortByPType | aiProcess_ValidateDataStructure | aiProcess_FindInvalidData;
    glint_error load;
    if (!assimp_calls_load(&load)) {
        if (load.status == GLINT_ERR_NOMEM)
            error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
        else
            *err = load;
        return NULL;
    }
    struct aiPropertyStore *props = assimp->CreatePropertyStore();
    assimp->SetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    assimp->SetImportPropertyInteger(props, AI_CONFIG_IMPORT_NO_SKELETON_MESHES, 1);
    struct aiFileIO io;
    assimp_io_init(&io, src);
    char msg[400] = "";
    glint_status s = GLINT_OK;
    pthread_mutex_lock(&assimp_lock);
    failed_assertion = NULL;
    src->read = src->size;
    const struct aiScene *ai = assimp->ImportFileExWithProperties(src->name, aiProcess_ValidateDataStructure, &io, props);
    if (ai) {
        if (!failed_assertion)
            s = check_read(ai, file, err);
        assimp->ReleaseImport(ai);
        ai = NULL;
        src->read = src->size;
        if (!failed_assertion && !s)
            ai = assimp->ImportFileExWithProperties(src->name, flags, &io, props);
    }
    if (!ai && !s)
        assimp_message(msg, sizeof msg);
    const char *assertion = failed_assertion;
    pthread_mutex_unlock(&assimp_lock);
    assimp->ReleasePropertyStore(props);
    if (ai && !assertion && !src->refused && !(ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) && ai->mNumMeshes > 0)
        return ai;
    bool empty = ai != NULL;
    if (ai)
        assimp->ReleaseImport(ai);
    /* A file refused says why before anything Assimp made of its absence. */
    if (src->refused)
        *err = src->refusal;
    if (s || src->refused)
        return NULL;
    if (assertion)
        error_set(err, GLINT_ERR_INVALID, "%s: Assimp failed its own check '%s'", file, assertion);
    /* Assimp drops points and lines, and fails when that leaves nothing. */
    else if (empty || strcmp(msg, "No meshes remaining") == 0 || strstr(msg, "mNumMeshes is 0"))
        error_set(err, GLINT_ERR_INVALID, "%s: no triangles", file);
    /* Assimp says this when the reader its name calls for refuses the
     * bytes: "no reader for the format" would mislead. */
    else if (strncmp(msg, "No suitable reader found", 24) == 0)
        error_set(err, GLINT_ERR_INVALID,
                  "%s: no model reader accepts it (a damaged file, or another format under this name)", file);
    /* Assimp is C++: running out of memory reaches its C API as the
     * exception's name, which means nothing to a user. */
    else if (strstr(msg, "bad_alloc"))
        error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    else
        error_set(err, GLINT_ERR_INVALID, "%s: %s", file, msg);
    return NULL;
}

/* Builds the mesh of a model Assimp read: materials first (Assimp's
 * material i with emissive strength strengths[i], when i < strength_count),
 * then the mesh. */
static int build(glint_scene *scene, const struct aiScene *ai, const double *strengths, size_t strength_count,
                 const model_import *job, glint_error *err)
{
    assimp_merged mg = {0};
    size_t nm = ai->mNumMaterials ? ai->mNumMaterials : 1;
    bool *used = calloc(nm, sizeof *used);
    int *index = calloc(nm, sizeof *index);
    glint_status s = used && index ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", job->file);
    if (!s)
        s = assimp_merge(ai, job->file, &mg, used, err);
    if (!s && mg.unnormalled)
        s = assimp_make_normals(&mg, job->crease, job->file, err);
    if (!s)
        s = assimp_add_materials(scene, ai, used, index, strengths, strength_count, job, err);
    int mesh = -1;
    if (!s) {
        bool one = true;
        for (long long t = 0; t < mg.triangles; t++) {
            mg.materials[t] = index[mg.materials[t]];
            one &= mg.materials[t] == mg.materials[0];
        }
        glint_mesh_data d = {
            .positions = mg.positions, .normals = mg.normals, .uvs = mg.uvs, .vertex_count = (int)mg.vertices,
            .indices = mg.indices, .triangle_count = (int)mg.triangles, .materials = one ? NULL : mg.materials,
            .material = mg.materials[0],
        };
        mesh = model_add_mesh(scene, job, &d, err);
    }
    assimp_merged_free(&mg);
    free(used);
    free(index);
    return mesh;
}

/* The JSON of a glTF or GLB model, into *json and *json_size; false for
 * the other formats, and for a GLB too short to have any. */
static bool gltf_json_of(const unsigned char *data, size_t size, const model_import *job,
                         const unsigned char **json, size_t *json_size)
{
    if (job->format->check == glb_check)
        return glb_json(data, size, json, json_size);
    *json = data;
    *json_size = size;
    return job->format->check == gltf_check;
}

static int import_memory(glint_scene *scene, const unsigned char *data, size_t size, const model_import *job,
                         glint_error *err)
{
    /* What Assimp does not read of a glTF's materials is read first. */
    const unsigned char *json;
    size_t json_size, strength_count = 0;
    double *strengths = NULL;
    if (gltf_json_of(data, size, job, &json, &json_size) &&
        gltf_emissive_strengths(json, json_size, job->file, &strengths, &strength_count, err))
        return -1;

    /* Assimp picks its reader by the name's extension: a model from a file
     * goes by its own name, the files it names beside it; one from memory
     * by a name made of its format's extension. */
    char hint[32];
    snprintf(hint, sizeof hint, "$glint-memory$.%s", job->format->extension);
    assimp_source src = {.name = job->dir ? job->file : hint, .data = data, .size = size, .dir = job->dir,
                         .file = job->file, .scene = scene};
    const struct aiScene *ai = assimp_read(&src, job->file, err);
    int mesh = -1;
    if (ai) {
        mesh = build(scene, ai, strengths, strength_count, job, err);
        assimp->ReleaseImport(ai);
    }
    free(strengths);
    return mesh;
}

/* Each format's check keeps bytes away from Assimp that it would go
 * astray on. */
static const model_format formats[] = {
    {.extension = "ply", .check = ply_check},
    {.extension = "stl"},
    {.extension = "gltf", .check = gltf_check, .names_materials = true},
    {.extension = "glb", .check = glb_check, .names_materials = true},
    {0},
};

const model_reader assimp_reader = {.formats = formats, .import_memory = import_memory};
