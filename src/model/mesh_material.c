/* mesh_material.c - turning an imported model's materials into glint's: the
 * OBJ/MTL and glTF tables of docs/meshes.md, and their diffuse or
 * base-colour images as UV-mapped image textures, each added once. Values
 * out of glint's ranges are clamped into them, so a material never fails to
 * be added for what the file says. MTL materials come from glint's own
 * reader (mtl_read.c), glTF ones from Assimp. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include "core/error.h"
#include "model/mesh_import.h"
#include "scene/scene.h"

#define MAX_SHININESS 10000.0
#define MAX_NAME_TRIES 1000

/* The textures added so far, by the name the file gives them. */
typedef struct texture_cache {
    const char **refs;
    int *index;
    size_t count;
} texture_cache;

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

/* One float of a material property, or fallback when absent or not finite. */
static double get_float(const struct aiMaterial *m, const char *key, unsigned type, unsigned index, double fallback)
{
    ai_real v = 0;
    unsigned n = 1;
    if (aiGetMaterialFloatArray(m, key, type, index, &v, &n) != AI_SUCCESS || n < 1 || !isfinite(v))
        return fallback;
    return v;
}

static bool get_color(const struct aiMaterial *m, const char *key, unsigned type, unsigned index, glint_color *out)
{
    struct aiColor4D c;
    if (aiGetMaterialColor(m, key, type, index, &c) != AI_SUCCESS)
        return false;
    out->r = isfinite(c.r) ? fmax(c.r, 0) : 0;
    out->g = isfinite(c.g) ? fmax(c.g, 0) : 0;
    out->b = isfinite(c.b) ? fmax(c.b, 0) : 0;
    return true;
}

static bool get_string(const struct aiMaterial *m, const char *key, unsigned type, unsigned index,
                       struct aiString *out)
{
    return aiGetMaterialString(m, key, type, index, out) == AI_SUCCESS && out->length > 0;
}

/* True for a material Assimp made up because the file gave none: glTF's
 * unnamed last one, and every PLY and STL one. */
static bool is_made_up(const struct aiScene *ai, unsigned i, mesh_format f)
{
    struct aiString name;
    if (f == MESH_FORMAT_GLTF || f == MESH_FORMAT_GLB)
        return !get_string(ai->mMaterials[i], AI_MATKEY_NAME, &name) && i + 1 == ai->mNumMaterials;
    return true;
}

static glint_material grey(void)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){0.5, 0.5, 0.5};
    return m;
}

/* A colour channel of a file: finite and not negative, or 0. */
static double channel(double x)
{
    return isfinite(x) && x > 0 ? x : 0;
}

/* A number of a file, or fallback when it is not finite. */
static double finite_or(double x, double fallback)
{
    return isfinite(x) ? x : fallback;
}

/* MTL: Kd is a display (sRGB) colour; Ks, Ns, d, Ni as they are; illum picks
 * mirror (3, 5) or refracting (4, 6, 7; 7 with Fresnel) behaviour. */
glint_material mesh_import_from_mtl(const mtl_material *a)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){glint_srgb_to_linear(channel(a->kd[0])), glint_srgb_to_linear(channel(a->kd[1])),
                            glint_srgb_to_linear(channel(a->kd[2]))};
    double ks_max = fmax(channel(a->ks[0]), fmax(channel(a->ks[1]), channel(a->ks[2])));
    m.specular = ks_max;
    m.shininess = clamp(finite_or(a->ns, 0), 0, MAX_SHININESS);
    if (a->ni > 0 && isfinite(a->ni))
        m.ior = a->ni;
    double dissolved = 1 - clamp(finite_or(a->d, 1), 0, 1);
    switch (a->illum) {
    case 3:
    case 5:
        m.reflectivity = clamp(ks_max, 0, 1);
        m.transparency = dissolved;
        break;
    case 4:
    case 6:
    case 7:
        /* A refracting surface that the file leaves opaque (d 1, as some
         * exporters write glass) refracts fully. */
        m.refraction = dissolved > 0 ? dissolved : 1;
        m.fresnel = a->illum == 7;
        break;
    default:
        m.transparency = dissolved;
    }
    return m;
}

/* glTF metallic-roughness: base colour is linear already; metals mirror,
 * roughness widens and dims the highlight, transmission refracts. */
static glint_material from_gltf(const struct aiMaterial *a)
{
    glint_material m = glint_material_default();
    glint_color base = {1, 1, 1};
    if (!get_color(a, AI_MATKEY_BASE_COLOR, &base))
        get_color(a, AI_MATKEY_COLOR_DIFFUSE, &base);
    m.color = base;
    double metallic = clamp(get_float(a, AI_MATKEY_METALLIC_FACTOR, 0), 0, 1);
    double rough = clamp(get_float(a, AI_MATKEY_ROUGHNESS_FACTOR, 1), 0, 1);
    m.reflectivity = metallic;
    m.diffuse = 1 - metallic;
    m.ambient = 0.2 * (1 - metallic);
    m.specular = 1 - rough;
    /* The Phong exponent whose lobe matches a Beckmann roughness alpha = r^2. */
    double r4 = rough * rough * rough * rough;
    m.shininess = r4 > 0 ? clamp(2 / r4 - 2, 0, MAX_SHININESS) : MAX_SHININESS;
    m.refraction = clamp(get_float(a, AI_MATKEY_TRANSMISSION_FACTOR, 0), 0, 1);
    m.fresnel = m.refraction > 0;
    double ior = get_float(a, AI_MATKEY_REFRACTI, 1.5);
    m.ior = ior > 0 ? ior : 1.5;
    struct aiString mode;
    if (get_string(a, AI_MATKEY_GLTF_ALPHAMODE, &mode) && strcmp(mode.data, "BLEND") == 0) {
        struct aiColor4D c;
        double alpha = aiGetMaterialColor(a, AI_MATKEY_BASE_COLOR, &c) == AI_SUCCESS && isfinite(c.a) ? c.a : 1;
        m.transparency = clamp(1 - alpha, 0, 1 - m.refraction);
    }
    return m;
}

/* Adds the texture embedded as "*N". */
static glint_status add_embedded(glint_scene *scene, const struct aiScene *ai, const char *ref,
                                 const mesh_import_ctx *ctx, int *out, glint_error *err)
{
    char *end;
    unsigned long i = strtoul(ref + 1, &end, 10);
    if (end == ref + 1 || *end || i >= ai->mNumTextures)
        return error_set(err, GLINT_ERR_INVALID, "%s: texture '%s' is not in the file", ctx->file, ref);
    const struct aiTexture *t = ai->mTextures[i];
    if (t->mHeight != 0 || !t->pcData)
        return error_set(err, GLINT_ERR_INVALID, "%s: texture '%s' is not PNG or JPEG data", ctx->file, ref);
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    glint_error inner;
    *out = glint_scene_add_image_memory(scene, NULL, t->pcData, t->mWidth, uv, &inner);
    if (*out < 0)
        return error_set(err, inner.status, "%s: texture '%s': %s", ctx->file, ref, inner.message);
    return GLINT_OK;
}

/* Adds the texture file `ref` names, relative to the model's directory. */
static glint_status add_file(glint_scene *scene, const char *ref, const mesh_import_ctx *ctx, int *out,
                             glint_error *err)
{
    char *path = mesh_import_path(ctx->dir, ref);
    if (!path)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", ctx->file);
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    glint_error inner;
    *out = glint_scene_add_image_file(scene, NULL, path, uv, &inner);
    free(path);
    if (*out < 0)
        return error_set(err, inner.status, "%s: texture '%s': %s", ctx->file, ref, inner.message);
    return GLINT_OK;
}

/* Sets *out to the texture of image `ref`, adding it the first time: -1
 * when ref is NULL or names a file that may not be read. */
static glint_status material_texture(glint_scene *scene, const struct aiScene *ai, const char *ref,
                                     const mesh_import_ctx *ctx, texture_cache *cache, int *out, glint_error *err)
{
    *out = -1;
    bool embedded = ai && ref && ref[0] == '*';
    if (!ref || (!embedded && !ctx->dir))
        return GLINT_OK;
    for (size_t i = 0; i < cache->count; i++)
        if (strcmp(cache->refs[i], ref) == 0) {
            *out = cache->index[i];
            return GLINT_OK;
        }
    glint_status s = embedded ? add_embedded(scene, ai, ref, ctx, out, err) : add_file(scene, ref, ctx, out, err);
    if (s)
        return s;
    cache->refs[cache->count] = ref;
    cache->index[cache->count++] = *out;
    return GLINT_OK;
}

/* Adds m as "<stem>/<what>", or "<stem>/<what>#N" when that name is taken
 * (the same model imported twice), or unnamed after that. */
static glint_status add_material(glint_scene *scene, const char *what, const glint_material *m,
                                 const mesh_import_ctx *ctx, int *out, glint_error *err)
{
    size_t len = strlen(ctx->stem) + strlen(what) + 16;
    char *name = malloc(len);
    if (!name)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", ctx->file);
    snprintf(name, len, "%s/%s", ctx->stem, what);
    for (int n = 2; scene_find_material(scene, name) >= 0 && n <= MAX_NAME_TRIES + 1; n++)
        snprintf(name, len, "%s/%s#%d", ctx->stem, what, n);
    glint_error inner;
    *out = glint_scene_add_material(scene, scene_find_material(scene, name) >= 0 ? NULL : name, m, &inner);
    free(name);
    if (*out < 0)
        return error_set(err, inner.status, "%s: %s", ctx->file, inner.message);
    return GLINT_OK;
}

glint_status mesh_import_add_materials(glint_scene *scene, const import_material *mats, size_t count,
                                       const struct aiScene *ai, const mesh_import_ctx *ctx, int *index,
                                       glint_error *err)
{
    size_t n = count ? count : 1;
    texture_cache cache = {calloc(n, sizeof *cache.refs), calloc(n, sizeof *cache.index), 0};
    int *tex = calloc(n, sizeof *tex);
    glint_status s = GLINT_OK;
    if (!cache.refs || !cache.index || !tex)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", ctx->file);
    /* Textures go first: they are what a good file most often fails on, and
     * a failure then leaves behind only unnamed textures, never named
     * materials. */
    for (size_t i = 0; !s && i < count; i++)
        s = material_texture(scene, ai, mats[i].name ? mats[i].texture : NULL, ctx, &cache, &tex[i], err);
    int fallback = ctx->default_material;
    for (size_t i = 0; !s && i < count; i++) {
        if (mats[i].name) {
            glint_material m = mats[i].m;
            m.texture = tex[i];
            s = add_material(scene, mats[i].name, &m, ctx, &index[i], err);
            continue;
        }
        if (fallback < 0) {
            glint_material m = grey();
            s = add_material(scene, "default", &m, ctx, &fallback, err);
        }
        index[i] = fallback;
    }
    free(cache.refs);
    free(cache.index);
    free(tex);
    return s;
}

/* The diffuse or base-colour image Assimp material a names, into *ref;
 * false when it names none. */
static bool colour_image(const struct aiMaterial *a, struct aiString *ref)
{
    return get_string(a, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0), ref) ||
           get_string(a, AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0), ref);
}

glint_status mesh_import_materials(glint_scene *scene, const struct aiScene *ai, const bool *used, int *index,
                                   const mesh_import_ctx *ctx, glint_error *err)
{
    unsigned n = ai->mNumMaterials ? ai->mNumMaterials : 1;
    import_material *mats = calloc(n, sizeof *mats);
    struct aiString *names = calloc(n, sizeof *names), *refs = calloc(n, sizeof *refs);
    int *added = calloc(n, sizeof *added);
    if (!mats || !names || !refs || !added) {
        free(mats);
        free(names);
        free(refs);
        free(added);
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", ctx->file);
    }
    size_t count = 0;
    for (unsigned i = 0; i < ai->mNumMaterials; i++) {
        if (!used[i])
            continue;
        import_material *m = &mats[count++];
        if (is_made_up(ai, i, ctx->format))
            continue;
        const struct aiMaterial *a = ai->mMaterials[i];
        if (!get_string(a, AI_MATKEY_NAME, &names[i]))
            names[i].length = (ai_uint32)snprintf(names[i].data, sizeof names[i].data, "material%u", i);
        m->name = names[i].data;
        m->m = from_gltf(a);
        m->texture = colour_image(a, &refs[i]) ? refs[i].data : NULL;
    }
    glint_status s = mesh_import_add_materials(scene, mats, count, ai, ctx, added, err);
    for (unsigned i = 0, k = 0; !s && i < ai->mNumMaterials; i++)
        if (used[i])
            index[i] = added[k++];
    free(mats);
    free(names);
    free(refs);
    free(added);
    return s;
}
