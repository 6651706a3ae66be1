/* fuzz_scene.c - libFuzzer target for the YAML scene loader: feeds arbitrary
 * bytes to glint_scene_load_memory and frees whatever comes back, so the
 * sanitizers catch any crash, leak, overflow or hang in libyaml's use, the
 * tree builder, the alias/merge-key walker, includes and every section's
 * reader; a refused scene without an error message also counts as a crash.
 * The quick YAML reader and libyaml must read the bytes alike (the same
 * tree, or the same first message). The same bytes read as a stream
 * (glint_scene_load_stream, `glint -`) must load or be refused alike, with
 * the same first message; and read from whole trees rather than with the
 * objects read while parsed (the default, scenefile/scene_file.h), they
 * must be refused with the same first message or load to the same scene,
 * written back byte for byte.
 * Problems are only counted (NULL report): the library must stay silent.
 * Relative includes and texture files resolve against the working
 * directory, since the input is named "fuzz.yaml" (tests/fuzz/README.md). */
#define _GNU_SOURCE /* fmemopen */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "scenefile/scene_file.h"
#include "scenefile/yaml_tree.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The quick YAML reader must read whatever it takes exactly as libyaml
 * does: the same status and first message, or the same tree. */
static void same_with_both_readers(const uint8_t *data, size_t size)
{
    ydoc quick, full;
    glint_error quick_err, full_err;
    quick_err.message[0] = full_err.message[0] = '\0';
    long quick_aliases = 0, full_aliases = 0;
    glint_status a = ydoc_parse(&quick, (const char *)data, size, "fuzz.yaml", &quick_aliases, NULL, &quick_err);
    ydoc_use_quick_reader(false);
    glint_status b = ydoc_parse(&full, (const char *)data, size, "fuzz.yaml", &full_aliases, NULL, &full_err);
    ydoc_use_quick_reader(true);
    if (a != b || strcmp(quick_err.message, full_err.message) != 0 || (!a && !ynode_same(quick.root, full.root)))
        abort();
    if (!a) {
        ydoc_free(&quick);
        ydoc_free(&full);
    }
}

/* What two ways of loading must agree on: the scene written as a file
 * (or why it could not be), or the first message of its refusal. */
static char *outcome(const glint_scene *scene, const glint_error *err)
{
    char *text = NULL;
    size_t length = 0;
    FILE *f = open_memstream(&text, &length);
    if (!f)
        abort();
    glint_error write_err;
    if (!scene)
        fprintf(f, "refused: %s", err->message);
    else if (glint_scene_write_yaml(scene, f, &write_err))
        fprintf(f, "\nnot written: %s", write_err.message);
    fclose(f);
    return text;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    same_with_both_readers(data, size);
    glint_load_options options = {.report = NULL, .report_user = NULL, .max_errors = 0};
    glint_error err, stream_err;
    err.message[0] = stream_err.message[0] = '\0';
    glint_scene *scene = glint_scene_load_memory((const char *)data, size, "fuzz.yaml", &options, &err);
    /* The API's promise: a refused scene always comes with its first problem. */
    if (!scene && err.message[0] == '\0')
        abort();
    /* fmemopen takes no empty buffer on every libc: an empty input is a
     * one-byte buffer of which nothing is read. */
    FILE *in = fmemopen(size ? (void *)data : (void *)"", size ? size : 1, "r");
    if (in && size == 0)
        fseek(in, 1, SEEK_SET);
    if (in) {
        glint_scene *streamed = glint_scene_load_stream(in, "fuzz.yaml", &options, &stream_err);
        if (!streamed != !scene || (!scene && strcmp(err.message, stream_err.message) != 0))
            abort();
        glint_scene_free(streamed);
        fclose(in);
    }
    glint_error whole_err;
    whole_err.message[0] = '\0';
    scene_file_set_mode(SCENE_FILE_WHOLE);
    glint_scene *whole = glint_scene_load_memory((const char *)data, size, "fuzz.yaml", &options, &whole_err);
    scene_file_set_mode(SCENE_FILE_STREAMED);
    char *a = outcome(scene, &err), *b = outcome(whole, &whole_err);
    if (strcmp(a, b) != 0)
        abort();
    free(a);
    free(b);
    glint_scene_free(whole);
    glint_scene_free(scene);
    return 0;
}
