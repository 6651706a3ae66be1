/* fuzz_mesh.c - libFuzzer target for the model importer: the first byte
 * picks the name, and so the format (model.obj, .ply, .stl, .glb, .gltf),
 * the rest goes to glint_scene_import_mesh_memory, and whatever scene comes
 * back is freed, so the sanitizers catch any crash, leak, overflow or hang
 * in our readers, checks and merging or in Assimp's readers behind them. A
 * refused model without an error message naming it also counts as a crash.
 * From memory no other file is read, so runs do not depend on the
 * directory; glTF text after an 'F' is written to a file of its own folder
 * instead and imported from there, beside a buffer file, so that buffer
 * URIs are followed (or refused) as from a user's disk; MTL text, which only files name, goes to glint's MTL reader
 * directly when the first byte is 'M', and every material it reads is
 * mapped to glint's. OBJ text is also read by glint's OBJ reader with
 * three threads parsing ahead in pieces of a few bytes, which must give
 * the model and the message of reading it in one pass. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include <stddef.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "model/mtl_read.h"
#include "model/obj_read.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Reads MTL text and maps each material it defines. */
static void fuzz_mtl(const uint8_t *data, size_t size)
{
    mtl_library lib = {0};
    glint_error err;
    err.message[0] = '\0';
    if (mtl_read(&lib, (const char *)data, size, "model.mtl", &err) && strncmp(err.message, "model.mtl", 9) != 0)
        abort();
    for (size_t i = 0; i < lib.count; i++) {
        glint_material m = mtl_to_glint(&lib.items[i]);
        if (mtl_find(&lib, lib.text + lib.items[i].name) != &lib.items[i] || !(m.ior > 0))
            abort();
    }
    mtl_free(&lib);
}

/* Whether two readings of the same array hold the same count of items of
 * `size` bytes. */
static bool same_array(const void *a, size_t a_count, const void *b, size_t b_count, size_t size)
{
    return a_count == b_count && (a_count == 0 || memcmp(a, b, a_count * size) == 0);
}

/* Reads OBJ text in one pass and parsed ahead by threads, and aborts
 * unless both give the same model or the same message. */
static void fuzz_obj_split(const uint8_t *data, size_t size)
{
    obj_model a, b;
    glint_error ea, eb;
    ea.message[0] = eb.message[0] = '\0';
    glint_status sa = obj_read_memory_split(&a, data, size, "model.obj", 1, (size_t)1 << 40, &ea);
    glint_status sb = obj_read_memory_split(&b, data, size, "model.obj", 3, 1 + size % 17, &eb);
    bool same = sa == sb && strcmp(ea.message, eb.message) == 0;
    if (same && !sa)
        same = same_array(a.positions, a.position_count, b.positions, b.position_count, 3 * sizeof(float)) &&
               same_array(a.uvs, a.uv_count, b.uvs, b.uv_count, 2 * sizeof(float)) &&
               same_array(a.normals, a.normal_count, b.normals, b.normal_count, 3 * sizeof(float)) &&
               same_array(a.corners, a.corner_count, b.corners, b.corner_count, sizeof(obj_corner)) &&
               same_array(a.triangles, a.triangle_count, b.triangles, b.triangle_count, 3 * sizeof(uint32_t)) &&
               same_array(a.runs, a.run_count, b.runs, b.run_count, sizeof(obj_run)) &&
               same_array(a.text, a.text_len, b.text, b.text_len, 1) &&
               same_array(a.materials, a.material_count, b.materials, b.material_count, sizeof(size_t)) &&
               same_array(a.libraries, a.library_count, b.libraries, b.library_count, sizeof(size_t)) &&
               a.generate == b.generate && a.textured == b.textured;
    obj_model_free(&a);
    obj_model_free(&b);
    if (!same)
        abort();
}

/* Writes glTF text to model.gltf in a folder of its own (made once, with
 * buffer.bin beside it: three triangles' floats) and imports it from
 * there, so that buffer URIs reach files: inside the folder, outside it,
 * devices, FIFOs' kin. */
static char disk_dir[64], disk_model[96], disk_buffer[96];

static void remove_disk_folder(void)
{
    remove(disk_model);
    remove(disk_buffer);
    remove(disk_dir);
}

static void fuzz_gltf_on_disk(const uint8_t *data, size_t size)
{
    char *dir = disk_dir, *path = disk_model;
    if (!dir[0]) {
        strcpy(dir, "/tmp/glint-fuzz-mesh-XXXXXX");
        if (!mkdtemp(dir))
            abort();
        char *buffer = disk_buffer;
        snprintf(buffer, sizeof disk_buffer, "%s/buffer.bin", dir);
        atexit(remove_disk_folder);
        float floats[27];
        for (int i = 0; i < 27; i++)
            floats[i] = (float)(i % 5);
        FILE *f = fopen(buffer, "wb");
        if (!f || fwrite(floats, sizeof floats, 1, f) != 1 || fclose(f) != 0)
            abort();
        snprintf(path, sizeof disk_model, "%s/model.gltf", dir);
    }
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, size, 1, f) != 1) || fclose(f) != 0)
        abort();
    glint_scene *scene = glint_scene_new();
    glint_error err;
    err.message[0] = '\0';
    if (scene && glint_scene_import_mesh(scene, path, NULL, &err) < 0 && strncmp(err.message, path, strlen(path)) != 0)
        abort();
    glint_scene_free(scene);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"model.obj", "model.ply", "model.stl", "model.glb", "model.gltf"};
    if (size < 1)
        return 0;
    if (data[0] == 'M') {
        fuzz_mtl(data + 1, size - 1);
        return 0;
    }
    if (data[0] == 'F') {
        fuzz_gltf_on_disk(data + 1, size - 1);
        return 0;
    }
    const char *name = names[data[0] % (sizeof names / sizeof names[0])];
    if (name == names[0])
        fuzz_obj_split(data + 1, size - 1);
    glint_scene *scene = glint_scene_new();
    if (!scene)
        return 0;
    glint_error err;
    err.message[0] = '\0';
    int mesh = glint_scene_import_mesh_memory(scene, data + 1, size - 1, name, NULL, &err);
    if (mesh < 0 && strncmp(err.message, name, strlen(name)) != 0)
        abort();
    glint_scene_free(scene);
    return 0;
}
