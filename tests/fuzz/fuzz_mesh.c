/* fuzz_mesh.c - libFuzzer target for the model importer: the first byte
 * picks the name, and so the format (model.obj, .ply, .stl, .glb, .gltf),
 * the rest goes to glint_scene_import_mesh_memory, and whatever scene comes
 * back is freed, so the sanitizers catch any crash, leak, overflow or hang
 * in our readers, checks and merging or in Assimp's readers behind them. A
 * refused model without an error message naming it also counts as a crash.
 * From memory no other file is read, so runs do not depend on the
 * directory; MTL text, which only files name, goes to glint's MTL reader
 * directly when the first byte is 'M', and every material it reads is
 * mapped to glint's. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "io/mesh_import.h"
#include "io/mtl_read.h"

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
        glint_material m = mesh_import_from_mtl(&lib.items[i]);
        if (mtl_find(&lib, lib.text + lib.items[i].name) != &lib.items[i] || !(m.ior > 0))
            abort();
    }
    mtl_free(&lib);
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
    const char *name = names[data[0] % (sizeof names / sizeof names[0])];
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
