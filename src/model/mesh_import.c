/* mesh_import.c - glint_scene_import_mesh: a model file into one glint mesh
 * with its materials and textures, built with the public API only
 * (docs/meshes.md). OBJ (with MTL) goes to glint's own reader
 * (obj_import.c); PLY, STL, glTF and GLB go through Assimp's C API.
 *
 * Assimp triangulates, flattens the node hierarchy into world positions,
 * generates missing normals, drops points and lines and validates; here its
 * meshes are merged into one and everything glint relies on is checked
 * again, so a malformed file is an error value naming it, never a crash.
 * Assimp's C API attaches no logger unless asked, so nothing is printed. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include "core/error.h"
#include "model/mesh_import.h"

#define DEFAULT_CREASE_DEGREES 80.0

/* Assimp's C API keeps the last error message in one global string. */
static pthread_mutex_t assimp_lock = PTHREAD_MUTEX_INITIALIZER;

/* Debian builds Assimp with its internal assertions on, and a failed one
 * prints to stderr and aborts the process: a malformed file can reach some.
 * This definition takes the place of Assimp's own reporting function (its
 * code calls it through the PLT), so that a failed assertion only marks the
 * import failed and Assimp goes on as its release builds, where the checks
 * are compiled out, do. */
void mesh_import_assert_failed(const char *expression, const char *file, int line)
    __asm__("_ZN6Assimp17aiAssertViolationEPKcS1_i");
static _Thread_local const char *failed_assertion;

void mesh_import_assert_failed(const char *expression, const char *file, int line)
{
    if (!failed_assertion)
        failed_assertion = expression;
}

/* Assimp's meshes merged into arrays for glint_mesh_data. */
typedef struct merged {
    float *positions, *normals, *uvs;
    uint32_t *indices;
    int *materials;           /* Assimp's material index per triangle, then glint's */
    long long vertices, triangles;
} merged;

static void merged_free(merged *m)
{
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    free(m->materials);
}

static long long triangle_faces(const struct aiMesh *m)
{
    long long n = 0;
    for (unsigned f = 0; m->mFaces && f < m->mNumFaces; f++)
        n += m->mFaces[f].mNumIndices == 3 && m->mFaces[f].mIndices;
    return m->mVertices ? n : 0;
}

/* Counts what the merged mesh will hold and allocates it. */
static glint_status merge_alloc(const struct aiScene *ai, const char *file, merged *out, glint_error *err)
{
    bool normals = false, uvs = false;
    for (unsigned i = 0; i < ai->mNumMeshes; i++) {
        const struct aiMesh *m = ai->mMeshes[i];
        long long tris = m ? triangle_faces(m) : 0;
        if (!tris)
            continue;
        if (m->mMaterialIndex >= ai->mNumMaterials)
            return error_set(err, GLINT_ERR_INVALID, "%s: a part uses material %u of %u", file, m->mMaterialIndex,
                             ai->mNumMaterials);
        out->vertices += m->mNumVertices;
        out->triangles += tris;
        normals |= m->mNormals != NULL;
        uvs |= m->mTextureCoords[0] != NULL;
        if (out->vertices > MESH_IMPORT_MAX_COUNT || out->triangles > MESH_IMPORT_MAX_COUNT)
            return error_set(err, GLINT_ERR_INVALID, "%s: too many %s (more than %lld)", file,
                             out->vertices > MESH_IMPORT_MAX_COUNT ? "vertices" : "triangles", MESH_IMPORT_MAX_COUNT);
    }
    if (out->triangles == 0)
        return error_set(err, GLINT_ERR_INVALID, "%s: no triangles", file);
    size_t nv = (size_t)out->vertices, nt = (size_t)out->triangles;
    out->positions = malloc(nv * 3 * sizeof(float));
    out->normals = normals ? calloc(nv * 3, sizeof(float)) : NULL;
    out->uvs = uvs ? calloc(nv * 2, sizeof(float)) : NULL;
    out->indices = malloc(nt * 3 * sizeof(uint32_t));
    out->materials = malloc(nt * sizeof(int));
    if (!out->positions || (normals && !out->normals) || (uvs && !out->uvs) || !out->indices || !out->materials)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory for %lld vertices and %lld triangles", file,
                         out->vertices, out->triangles);
    return GLINT_OK;
}

static float finite_or_zero(float x)
{
    return isfinite(x) ? x : 0.0f;
}

/* Copies mesh m's vertices to index v0 on. Normals and texture coordinates
 * that are not finite become zero (a zero normal falls back to the
 * triangle's own); v is flipped, as Assimp's v = 0 is the image's bottom
 * row and glint's its top. */
static glint_status copy_vertices(const struct aiMesh *m, long long v0, const char *file, merged *out,
                                  glint_error *err)
{
    for (unsigned v = 0; v < m->mNumVertices; v++) {
        size_t o = (size_t)(v0 + v);
        struct aiVector3D p = m->mVertices[v];
        if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z))
            return error_set(err, GLINT_ERR_INVALID, "%s: vertex %lld is not finite", file, v0 + v);
        out->positions[3 * o] = p.x;
        out->positions[3 * o + 1] = p.y;
        out->positions[3 * o + 2] = p.z;
        if (out->normals && m->mNormals) {
            out->normals[3 * o] = finite_or_zero(m->mNormals[v].x);
            out->normals[3 * o + 1] = finite_or_zero(m->mNormals[v].y);
            out->normals[3 * o + 2] = finite_or_zero(m->mNormals[v].z);
        }
        if (out->uvs && m->mTextureCoords[0]) {
            out->uvs[2 * o] = finite_or_zero(m->mTextureCoords[0][v].x);
            out->uvs[2 * o + 1] = finite_or_zero(1.0f - m->mTextureCoords[0][v].y);
        }
    }
    return GLINT_OK;
}

/* Merges every triangle of every mesh into one, marking the materials used. */
static glint_status merge(const struct aiScene *ai, const char *file, merged *out, bool *used, glint_error *err)
{
    glint_status s = merge_alloc(ai, file, out, err);
    long long v0 = 0, t = 0;
    for (unsigned i = 0; !s && i < ai->mNumMeshes; i++) {
        const struct aiMesh *m = ai->mMeshes[i];
        if (!m || !triangle_faces(m))
            continue;
        if ((s = copy_vertices(m, v0, file, out, err)))
            break;
        for (unsigned f = 0; !s && f < m->mNumFaces; f++) {
            const struct aiFace *face = &m->mFaces[f];
            if (face->mNumIndices != 3 || !face->mIndices)
                continue;
            for (int k = 0; k < 3 && !s; k++) {
                if (face->mIndices[k] >= m->mNumVertices)
                    s = error_set(err, GLINT_ERR_INVALID, "%s: a triangle uses vertex %u of a part with %u", file,
                                  face->mIndices[k], m->mNumVertices);
                else
                    out->indices[3 * t + k] = (uint32_t)(v0 + face->mIndices[k]);
            }
            out->materials[t++] = (int)m->mMaterialIndex;
        }
        used[m->mMaterialIndex] = true;
        v0 += m->mNumVertices;
    }
    return s;
}

/* Assimp's message, on one line of printable characters. */
static void assimp_message(char *out, size_t size)
{
    const char *msg = aiGetErrorString();
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
static const struct aiScene *assimp_read(mesh_source *src, const char *file, double crease, glint_error *err)
{
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                           aiProcess_GenSmoothNormals | aiProcess_SortByPType | aiProcess_ValidateDataStructure |
                           aiProcess_FindInvalidData;
    struct aiPropertyStore *props = aiCreatePropertyStore();
    aiSetImportPropertyFloat(props, AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, (float)crease);
    aiSetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    aiSetImportPropertyInteger(props, AI_CONFIG_IMPORT_NO_SKELETON_MESHES, 1);
    struct aiFileIO io;
    mesh_import_io(&io, src);
    char msg[400] = "";
    glint_status s = GLINT_OK;
    pthread_mutex_lock(&assimp_lock);
    failed_assertion = NULL;
    const struct aiScene *ai = aiImportFileExWithProperties(src->name, aiProcess_ValidateDataStructure, &io, props);
    if (ai) {
        if (!failed_assertion)
            s = check_read(ai, file, err);
        aiReleaseImport(ai);
        ai = NULL;
        if (!failed_assertion && !s)
            ai = aiImportFileExWithProperties(src->name, flags, &io, props);
    }
    if (!ai && !s)
        assimp_message(msg, sizeof msg);
    const char *assertion = failed_assertion;
    pthread_mutex_unlock(&assimp_lock);
    aiReleasePropertyStore(props);
    if (ai && !assertion && !(ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) && ai->mNumMeshes > 0)
        return ai;
    bool empty = ai != NULL;
    if (ai)
        aiReleaseImport(ai);
    if (s)
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
    else
        error_set(err, strstr(msg, "bad_alloc") ? GLINT_ERR_NOMEM : GLINT_ERR_INVALID, "%s: %s", file, msg);
    return NULL;
}

int mesh_import_add_mesh(glint_scene *scene, const mesh_import_ctx *ctx, const glint_mesh_data *d, glint_error *err)
{
    glint_error inner;
    int mesh = glint_scene_add_mesh(scene, ctx->stem, d, &inner);
    if (mesh < 0)
        error_set(err, inner.status, "%s: %s", ctx->file, inner.message);
    return mesh;
}

/* Builds the mesh of a model Assimp read: materials first, then the mesh. */
static int build(glint_scene *scene, const struct aiScene *ai, const mesh_import_ctx *ctx, glint_error *err)
{
    merged mg = {0};
    size_t nm = ai->mNumMaterials ? ai->mNumMaterials : 1;
    bool *used = calloc(nm, sizeof *used);
    int *index = calloc(nm, sizeof *index);
    glint_status s = used && index ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", ctx->file);
    if (!s)
        s = merge(ai, ctx->file, &mg, used, err);
    if (!s)
        s = mesh_import_materials(scene, ai, used, index, ctx, err);
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
        mesh = mesh_import_add_mesh(scene, ctx, &d, err);
    }
    merged_free(&mg);
    free(used);
    free(index);
    return mesh;
}

/* Checks the options; fills crease and ctx->default_material. */
static glint_status read_options(const glint_scene *scene, const glint_import_options *o, const char *file,
                                 double *crease, mesh_import_ctx *ctx, glint_error *err)
{
    *crease = o && o->crease_angle != 0 ? o->crease_angle : DEFAULT_CREASE_DEGREES;
    if (!(*crease > 0 && *crease <= 180))
        return error_set(err, GLINT_ERR_INVALID, "%s: crease angle must be in (0, 180] degrees, got %g", file,
                         *crease);
    ctx->default_material = o ? o->default_material : -1;
    if (ctx->default_material < -1 || ctx->default_material >= glint_scene_get_counts(scene).materials)
        return error_set(err, GLINT_ERR_INVALID, "%s: default material %d does not exist", file,
                         ctx->default_material);
    return GLINT_OK;
}

/* Sets ctx->stem to the file name less directory and extension, and, when
 * texture files may be read, ctx->dir to its directory. */
static glint_status name_parts(const char *file, bool disk, mesh_import_ctx *ctx, glint_error *err)
{
    const char *slash = strrchr(file, '/');
    const char *base = slash ? slash + 1 : file;
    const char *dot = strrchr(base, '.');
    ctx->stem = strndup(base, dot && dot != base ? (size_t)(dot - base) : strlen(base));
    ctx->dir = !disk ? NULL : slash == file ? strdup("/") : strndup(file, slash ? (size_t)(slash - file) : 0);
    if (!ctx->stem || (disk && !ctx->dir))
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    return GLINT_OK;
}

/* Reads it through Assimp: the bytes of the file, checked, then read. */
static int import_assimp(glint_scene *scene, int fd, const unsigned char *data, size_t size,
                         const mesh_import_ctx *ctx, double crease, glint_error *err)
{
    unsigned char *read = NULL;
    glint_status s = fd >= 0 ? mesh_import_read_fd(fd, size, ctx->file, &read, err) : GLINT_OK;
    if (read)
        data = read;
    if (!s)
        s = mesh_import_check(ctx->format, data, size, ctx->file, err);
    char hint[32];
    snprintf(hint, sizeof hint, "$glint-memory$.%s", mesh_import_extension(ctx->format));
    mesh_source src = {.name = ctx->dir ? ctx->file : hint, .data = data, .size = size, .disk = ctx->dir != NULL};
    const struct aiScene *ai = s ? NULL : assimp_read(&src, ctx->file, crease, err);
    int mesh = -1;
    if (ai) {
        mesh = build(scene, ai, ctx, err);
        aiReleaseImport(ai);
    }
    free(read);
    return mesh;
}

/* Imports the model in the open file fd, of `size` bytes, or, when fd is
 * -1, in the `size` bytes at data; `file` names it. Only a model from a
 * file may read the files it names. */
static int import(glint_scene *scene, int fd, const unsigned char *data, size_t size, const char *file,
                  const glint_import_options *options, glint_error *err)
{
    mesh_import_ctx ctx = {.file = file, .format = mesh_import_format(file)};
    double crease;
    glint_status s = read_options(scene, options, file, &crease, &ctx, err);
    if (!s && ctx.format == MESH_FORMAT_NONE)
        s = error_set(err, GLINT_ERR_INVALID, "%s: unsupported format (glint imports .obj, .ply, .stl, .gltf and .glb)",
                      file);
    if (!s)
        s = name_parts(file, fd >= 0, &ctx, err);
    int mesh = -1;
    if (!s && ctx.format == MESH_FORMAT_OBJ)
        mesh = mesh_import_obj(scene, &ctx, fd, data, size, crease, err);
    else if (!s)
        mesh = import_assimp(scene, fd, data, size, &ctx, crease, err);
    free(ctx.stem);
    free(ctx.dir);
    return mesh;
}

int glint_scene_import_mesh(glint_scene *scene, const char *path, const glint_import_options *options,
                            glint_error *err)
{
    if (!scene || !path) {
        error_set(err, GLINT_ERR_INVALID, "import needs a scene and a file name");
        return -1;
    }
    int fd;
    size_t size;
    if (mesh_import_open(path, &fd, &size, err))
        return -1;
    int mesh = import(scene, fd, NULL, size, path, options, err);
    close(fd);
    return mesh;
}

int glint_scene_import_mesh_memory(glint_scene *scene, const void *data, size_t size, const char *name,
                                   const glint_import_options *options, glint_error *err)
{
    if (!scene || !name || (!data && size > 0)) {
        error_set(err, GLINT_ERR_INVALID, "import needs a scene, a name and data");
        return -1;
    }
    return import(scene, -1, data ? data : "", size, name, options, err);
}
