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
 * written back byte for byte. A load recorded (core/file_log.h), its
 * answers packed and its files' bytes read as it opens them, then taken
 * into another log and replayed, as glint-mpi's ranks load rank 0's scene,
 * must come out as the recorded load did; what was sent, with one byte
 * changed, must be taken or refused, cleanly.
 * Problems are only counted (NULL report): the library must stay silent.
 * Relative includes and texture files resolve against the working
 * directory, since the input is named "fuzz.yaml" (tests/fuzz/README.md). */
#define _GNU_SOURCE /* fmemopen */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "glint.h"
#include "core/file_log.h"
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

/* Two loads' outcomes must be the same; frees both scenes. */
static void expect_same_and_free(glint_scene *a, const glint_error *a_err, glint_scene *b, const glint_error *b_err)
{
    char *a_text = outcome(a, a_err), *b_text = outcome(b, b_err);
    if (strcmp(a_text, b_text) != 0)
        abort();
    free(a_text);
    free(b_text);
    glint_scene_free(a);
    glint_scene_free(b);
}

/* What rank 0 of glint-mpi sends as its load opens files: the answers
 * noted so far, then the file's bytes, as one stream. */
typedef struct sent {
    file_log *log;
    FILE *stream;
    char *bytes;
    size_t size;
    size_t first_answers;     /* where the first answers begin, after their length */
} sent;

static void put_piece(sent *s, const void *data, uint64_t n)
{
    if (fwrite(&n, sizeof n, 1, s->stream) != 1 || (n && fwrite(data, 1, (size_t)n, s->stream) != n))
        abort();
}

/* The log's open hook: the answers packed, then the file read again with
 * pread, as ship_files.c sends them. */
static int note_sent(void *user, const char *path, int fd, uint64_t size)
{
    sent *s = user;
    unsigned char *packed;
    size_t packed_size;
    glint_error err;
    if (file_log_pack(s->log, &packed, &packed_size, &err))
        abort();
    fflush(s->stream);
    if (!s->first_answers)
        s->first_answers = s->size + sizeof(uint64_t);
    put_piece(s, packed, packed_size);
    free(packed);
    unsigned char *bytes = malloc(size ? (size_t)size : 1);
    if (!bytes || (size > 0 && pread(fd, bytes, (size_t)size, 0) != (ssize_t)size))
        abort(); /* the corpus's files do not change */
    put_piece(s, bytes, size);
    free(bytes);
    (void)path;
    return fd;
}

/* Takes the stream's pieces into a new log, answers and bytes turn about:
 * NULL when the log refuses them (a garbled stream), else the log,
 * complete. */
static file_log *taken(const char *bytes, size_t size)
{
    file_log *log = file_log_new();
    if (!log)
        abort();
    glint_error err;
    bool answers = true, refused = false;
    for (size_t at = 0; at + sizeof(uint64_t) <= size && !refused; answers = !answers) {
        uint64_t n;
        memcpy(&n, bytes + at, sizeof n);
        at += sizeof n;
        if (n > size - at)
            break;
        refused = answers ? file_log_take_answers(log, (const unsigned char *)bytes + at, (size_t)n, &err) != GLINT_OK
                          : file_log_take_bytes(log, bytes + at, (size_t)n, &err) != GLINT_OK;
        at += (size_t)n;
    }
    file_log_complete(log);
    if (refused) {
        file_log_free(log);
        return NULL;
    }
    return log;
}

/* The load recorded, then replayed from what was sent, must come out the
 * same; the sent answers with one byte changed are taken or refused. */
static void same_when_replayed(const uint8_t *data, size_t size, const glint_load_options *options)
{
    sent s = {.log = file_log_new()};
    if (!s.log || !(s.stream = open_memstream(&s.bytes, &s.size)))
        abort();
    glint_error err, replay_err, pack_err;
    err.message[0] = replay_err.message[0] = '\0';
    file_log_on_open(s.log, note_sent, &s);
    file_log_record(s.log);
    glint_scene *scene = glint_scene_load_memory((const char *)data, size, "fuzz.yaml", options, &err);
    file_log_stop();
    unsigned char *packed;
    size_t packed_size;
    if (file_log_pack(s.log, &packed, &packed_size, &pack_err))
        abort();
    put_piece(&s, packed, packed_size);
    free(packed);
    if (fclose(s.stream) != 0)
        abort();
    file_log *replaying = taken(s.bytes, s.size);
    if (!replaying)
        abort();
    file_log_replay(replaying);
    glint_scene *replayed = glint_scene_load_memory((const char *)data, size, "fuzz.yaml", options, &replay_err);
    file_log_stop();
    expect_same_and_free(scene, &err, replayed, &replay_err);
    file_log_free(replaying);
    size_t first = s.first_answers ? s.first_answers : sizeof(uint64_t);
    if (s.size > first) {
        s.bytes[first + (size * 131 + (size ? data[0] : 0)) % (s.size - first)] ^=
            (unsigned char)(size ? data[size - 1] | 1 : 1);
        file_log_free(taken(s.bytes, s.size));
    }
    free(s.bytes);
    file_log_free(s.log);
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
    expect_same_and_free(scene, &err, whole, &whole_err);
    same_when_replayed(data, size, &options);
    return 0;
}
