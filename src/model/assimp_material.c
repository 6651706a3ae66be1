/* assimp_material.c - the materials of a model Assimp read (glTF's
 * metallic-roughness table of docs/meshes.md; PLY and STL have none) as
 * glint's, with their base-colour images, embedded ones included. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include "core/error.h"
#include "model/assimp_calls.h"
#include "model/assimp_material.h"
#include "model/model_build.h"

/* One float of a material property, or fallback when absent or not finite. */
static double get_float(const struct aiMaterial *m, const char *key, unsigned type, unsigned index, double fallback)
{
    ai_real v = 0;
    unsigned n = 1;
    if (assimp->GetMaterialFloatArray(m, key, type, index, &v, &n) != AI_SUCCESS || n < 1 || !isfinite(v))
        return fallback;
    return v;
}

static bool get_color(const struct aiMaterial *m, const char *key, unsigned type, unsigned index, glint_color *out)
{
    struct aiColor4D c;
    if (assimp->GetMaterialColor(m, key, type, index, &c) != AI_SUCCESS)
        return false;
    out->r = isfinite(c.r) ? fmax(c.r, 0) : 0;
    out->g = isfinite(c.g) ? fmax(c.g, 0) : 0;
    out->b = isfinite(c.b) ? fmax(c.b, 0) : 0;
    return true;
}

static bool get_string(const struct aiMaterial *m, const char *key, unsigned type, unsigned index,
                       struct aiString *out)
{
    return assimp->GetMaterialString(m, key, type, index, out) == AI_SUCCESS && out->length > 0;
}

/* True for a material Assimp made up because the file gave none: the
 * unnamed last one of a format that names its materials (glTF), and every
 * one of a format that has none (PLY, STL). */
static bool is_made_up(const struct aiScene *ai, unsigned i, const model_format *f)
{
    struct aiString name;
    if (f->names_materials)
        return !get_string(ai->mMaterials[i], AI_MATKEY_NAME, &name) && i + 1 == ai->mNumMaterials;
    return true;
}

/* glTF metallic-roughness: base colour is linear already; metals mirror
 * in their own colour,
 * roughness widens and dims the highlight, transmission refracts, the
 * emissive factor glows (times the emissive strength, which Assimp does
 * not read: the caller sets it). */
static glint_material from_gltf(const struct aiMaterial *a)
{
    glint_material m = glint_material_default();
    glint_color base = {1, 1, 1};
    if (!get_color(a, AI_MATKEY_BASE_COLOR, &base))
        get_color(a, AI_MATKEY_COLOR_DIFFUSE, &base);
    m.color = base;
    double metallic = model_clamp(get_float(a, AI_MATKEY_METALLIC_FACTOR, 0), 0, 1);
    double rough = model_clamp(get_float(a, AI_MATKEY_ROUGHNESS_FACTOR, 1), 0, 1);
    m.reflectivity = m.metallic = metallic;
    m.diffuse = 1 - metallic;
    m.ambient = 0.2 * (1 - metallic);
    m.specular = 1 - rough;
    /* The Phong exponent whose lobe matches a Beckmann roughness alpha = r^2. */
    double r4 = rough * rough * rough * rough;
    m.shininess = r4 > 0 ? model_clamp(2 / r4 - 2, 0, MODEL_MAX_SHININESS) : MODEL_MAX_SHININESS;
    m.refraction = model_clamp(get_float(a, AI_MATKEY_TRANSMISSION_FACTOR, 0), 0, 1);
    m.fresnel = m.refraction > 0;
    get_color(a, AI_MATKEY_COLOR_EMISSIVE, &m.emission); /* emissiveFactor, linear */
    double ior = get_float(a, AI_MATKEY_REFRACTI, 1.5);
    m.ior = ior > 0 ? ior : 1.5;
    struct aiString mode;
    if (get_string(a, AI_MATKEY_GLTF_ALPHAMODE, &mode) && strcmp(mode.data, "BLEND") == 0) {
        struct aiColor4D c;
        double alpha = assimp->GetMaterialColor(a, AI_MATKEY_BASE_COLOR, &c) == AI_SUCCESS && isfinite(c.a) ? c.a : 1;
        m.transparency = model_clamp(1 - alpha, 0, 1 - m.refraction);
    }
    return m;
}

/* The model_texture_fn of Assimp's models (user is the aiScene): images
 * embedded in the file, which Assimp names "*N", and image files. */
static glint_status add_texture(glint_scene *scene, const char *ref, const model_import *job, void *user, int *out,
                                glint_error *err)
{
    const struct aiScene *ai = user;
    if (ref[0] != '*')
        return model_add_texture_file(scene, ref, job, NULL, out, err);
    char *end;
    unsigned long i = strtoul(ref + 1, &end, 10);
    if (end == ref + 1 || *end || i >= ai->mNumTextures)
        return error_set(err, GLINT_ERR_INVALID, "%s: texture '%s' is not in the file", job->file, ref);
    const struct aiTexture *t = ai->mTextures[i];
    if (t->mHeight != 0 || !t->pcData)
        return error_set(err, GLINT_ERR_INVALID, "%s: texture '%s' is not PNG or JPEG data", job->file, ref);
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    glint_error inner;
    *out = glint_scene_add_image_memory(scene, NULL, t->pcData, t->mWidth, uv, &inner);
    if (*out < 0)
        return error_set(err, inner.status, "%s: texture '%s': %s", job->file, ref, inner.message);
    return GLINT_OK;
}

/* The diffuse or base-colour image Assimp material a names, into *ref;
 * false when it names none. */
static bool colour_image(const struct aiMaterial *a, struct aiString *ref)
{
    return get_string(a, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0), ref) ||
           get_string(a, AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0), ref);
}

glint_status assimp_add_materials(glint_scene *scene, const struct aiScene *ai, const bool *used, int *index,
                                  const double *strengths, size_t strength_count, const model_import *job,
                                  glint_error *err)
{
    unsigned n = ai->mNumMaterials ? ai->mNumMaterials : 1;
    model_material *mats = calloc(n, sizeof *mats);
    struct aiString *names = calloc(n, sizeof *names), *refs = calloc(n, sizeof *refs);
    struct aiString *normal_refs = calloc(n, sizeof *normal_refs);
    int *added = calloc(n, sizeof *added);
    if (!mats || !names || !refs || !normal_refs || !added) {
        free(mats);
        free(names);
        free(refs);
        free(normal_refs);
        free(added);
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", job->file);
    }
    size_t count = 0;
    for (unsigned i = 0; i < ai->mNumMaterials; i++) {
        if (!used[i])
            continue;
        model_material *m = &mats[count++];
        if (is_made_up(ai, i, job->format))
            continue;
        const struct aiMaterial *a = ai->mMaterials[i];
        if (!get_string(a, AI_MATKEY_NAME, &names[i]))
            names[i].length = (ai_uint32)snprintf(names[i].data, sizeof names[i].data, "material%u", i);
        m->name = names[i].data;
        m->m = from_gltf(a);
        if (i < strength_count)
            m->m.emission_strength = strengths[i];
        m->texture = colour_image(a, &refs[i]) ? refs[i].data : NULL;
        m->normals = get_string(a, AI_MATKEY_TEXTURE(aiTextureType_NORMALS, 0), &normal_refs[i]) ?
                         normal_refs[i].data : NULL;
    }
    glint_status s = model_add_materials(scene, mats, count, add_texture, (void *)ai, job, added, err);
    for (unsigned i = 0, k = 0; !s && i < ai->mNumMaterials; i++)
        if (used[i])
            index[i] = added[k++];
    free(mats);
    free(names);
    free(refs);
    free(normal_refs);
    free(added);
    return s;
}
