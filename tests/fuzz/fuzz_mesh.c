/* fuzz_mesh.c - libFuzzer target for the model importer: the first byte
 * picks the name, and so the format (model.obj, .ply, .stl, .glb, .gltf),
 * the rest goes to glint_scene_import_mesh_memory, and whatever scene comes
 * back is freed, so the sanitizers catch any crash, leak, overflow or hang
 * in our checks and merging or in Assimp's readers behind them. A refused
 * model without an error message naming it also counts as a crash. From
 * memory no other file is read, so runs do not depend on the directory. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"model.obj", "model.ply", "model.stl", "model.glb", "model.gltf"};
    if (size < 1)
        return 0;
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
