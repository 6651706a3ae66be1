/* fuzz_nff.c - libFuzzer target for the NFF scene reader: feeds arbitrary
 * bytes to glint_scene_load_memory as "fuzz.nff" and frees whatever comes
 * back, so the sanitizers catch any crash, leak, overflow or hang; a
 * refused scene without an error message, or one whose message does not
 * name the file, also counts as a crash. The same bytes read as a stream
 * must load or be refused alike, with the same message. */
#define _GNU_SOURCE /* fmemopen */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    glint_error err;
    err.message[0] = '\0';
    glint_scene *scene = glint_scene_load_memory((const char *)data, size, "fuzz.nff", NULL, &err);
    if (!scene && strncmp(err.message, "fuzz.nff", 8) != 0)
        abort();
    FILE *in = fmemopen(size ? (void *)data : (void *)"", size ? size : 1, "r");
    if (in) {
        glint_error streamed;
        streamed.message[0] = '\0';
        glint_scene *again = glint_scene_load_stream(in, "fuzz.nff", NULL, &streamed);
        fclose(in);
        if (size && (!again) != (!scene))
            abort();
        if (size && !scene && strcmp(err.message, streamed.message) != 0)
            abort();
        glint_scene_free(again);
    }
    glint_scene_free(scene);
    return 0;
}
