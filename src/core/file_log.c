/* file_log.c - recording a load's look at the file system, packing it,
 * and answering a replayed load from it (file_log.h).
 *
 * A log is a list of answers, one per (question, path), found through an
 * id_table. The files' bytes live in one anonymous memory file (memfd) in
 * the order the log lists them: one descriptor however many thousands of
 * files a scene names. Each open replayed gets a fresh memory file holding
 * a copy of its file's bytes, so that it has its own offset and can be
 * read and closed as a file on disk is.
 *
 * A replayed log may still be taking answers and bytes from another thread
 * (glint-mpi's worker loads while rank 0's files arrive): its lock guards
 * the answers, the index and the bytes taken, and a question waits on
 * `arrived` until the log can answer it or is complete. The answers' strings
 * never move once added, so a copy of an answer stays good after the lock. */
#define _GNU_SOURCE /* memfd_create */
#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include "core/array.h"
#include "core/error.h"
#include "core/file_log.h"
#include "core/id_table.h"
#include "core/open_file.h"

enum question { ASK_OPEN, ASK_REALPATH, ASK_STAT };

/* The status of a file, as much as loaders use of it. */
typedef struct file_status {
    uint64_t dev, ino, size;
    int64_t mtime_sec, mtime_nsec;
    uint32_t mode;
} file_status;

typedef struct answer {
    uint8_t question;
    uint8_t found;            /* the call succeeded */
    int32_t errnum;           /* why it did not */
    char *path;
    char *resolved;           /* realpath's result */
    file_status status;       /* stat's, or the opened file's */
    uint64_t offset;          /* an open's bytes in the store */
} answer;

struct file_log {
    answer *answers;
    size_t count, cap;
    id_table index;
    bool failed;              /* memory ran out while recording */
    uint32_t *files;          /* the answers of the opens whose bytes go with the log, in order */
    size_t file_count, file_cap;
    uint64_t file_bytes;      /* their length in all */
    int store;                /* their bytes (replay); -1 */
    uint64_t taken;           /* how many of them came */
    size_t packed;            /* the answers file_log_pack has packed (recording) */
    file_log_open_hook on_open;
    void *on_open_user;
    pthread_mutex_t lock;     /* (replay) answers, index and taken, as they come */
    pthread_cond_t arrived;   /* signalled when answers or bytes come, or all has */
    bool complete;            /* (replay) nothing more comes: what is missing is not there */
};

static _Thread_local file_log *current_log;
static _Thread_local bool current_replays;

file_log *file_log_new(void)
{
    file_log *log = calloc(1, sizeof *log);
    if (!log)
        return NULL;
    log->store = -1;
    if (pthread_mutex_init(&log->lock, NULL) != 0) {
        free(log);
        return NULL;
    }
    if (pthread_cond_init(&log->arrived, NULL) != 0) {
        pthread_mutex_destroy(&log->lock);
        free(log);
        return NULL;
    }
    return log;
}

void file_log_free(file_log *log)
{
    if (!log)
        return;
    for (size_t i = 0; i < log->count; i++) {
        free(log->answers[i].path);
        free(log->answers[i].resolved);
    }
    free(log->answers);
    free(log->files);
    id_table_free(&log->index);
    if (log->store >= 0)
        close(log->store);
    pthread_cond_destroy(&log->arrived);
    pthread_mutex_destroy(&log->lock);
    free(log);
}

void file_log_on_open(file_log *log, file_log_open_hook hook, void *user)
{
    log->on_open = hook;
    log->on_open_user = user;
}

void file_log_record(file_log *log)
{
    current_log = log;
    current_replays = false;
}

void file_log_replay(file_log *log)
{
    current_log = log;
    current_replays = true;
}

void file_log_stop(void)
{
    current_log = NULL;
}

/* The key of an answer: the question and the path. */
typedef struct question_key {
    uint8_t question;
    const char *path;
} question_key;

static uint32_t key_hash(uint8_t question, const char *path)
{
    return id_hash_text(path) ^ question;
}

static bool stored_equal(const void *answers, uint32_t id, const void *key)
{
    const answer *a = &((const answer *)answers)[id];
    const question_key *k = key;
    return a->question == k->question && strcmp(a->path, k->path) == 0;
}

static const answer *find(const file_log *log, uint8_t question, const char *path)
{
    question_key k = {question, path};
    uint32_t id;
    return id_table_find(&log->index, key_hash(question, path), &k, stored_equal, log->answers, &id)
               ? &log->answers[id]
               : NULL;
}

/* Adds answer a, its strings malloc'd and now the log's, for a (question,
 * path) not in the log yet; NULL (a's strings freed) when out of memory. */
static answer *add(file_log *log, const answer *a)
{
    if (log->count < UINT32_MAX - 1 &&
        array_reserve((void **)&log->answers, &log->cap, log->count + 1, sizeof *log->answers)) {
        log->answers[log->count] = *a;
        if (id_table_add(&log->index, key_hash(a->question, a->path), (uint32_t)log->count))
            return &log->answers[log->count++];
    }
    free(a->path);
    free(a->resolved);
    return NULL;
}

/* Enters a (question, path) not in the log yet; its answer is the
 * caller's to fill. NULL when out of memory. */
static answer *enter(file_log *log, uint8_t question, const char *path)
{
    answer a = {.question = question, .path = strdup(path)};
    return a.path ? add(log, &a) : NULL;
}

/* Lists answer a, an open that found its file, among those whose bytes go
 * with the log, its bytes after theirs; false when out of memory or past
 * what a file system holds. */
static bool add_file(file_log *log, answer *a)
{
    if (a->status.size > INT64_MAX - log->file_bytes ||
        !array_reserve((void **)&log->files, &log->file_cap, log->file_count + 1, sizeof *log->files))
        return false;
    log->files[log->file_count++] = (uint32_t)(a - log->answers);
    a->offset = log->file_bytes;
    log->file_bytes += a->status.size;
    return true;
}

/* The answer to note for (question, path) while recording, or NULL when
 * the thread does not record or already has one. */
static answer *to_note(uint8_t question, const char *path)
{
    file_log *log = current_log;
    if (!log || current_replays || log->failed || find(log, question, path))
        return NULL;
    answer *a = enter(log, question, path);
    log->failed = !a;
    return a;
}

static file_status status_of(const struct stat *st)
{
    return (file_status){.dev = (uint64_t)st->st_dev,
                         .ino = (uint64_t)st->st_ino,
                         .size = st->st_size > 0 ? (uint64_t)st->st_size : 0,
                         .mtime_sec = (int64_t)st->st_mtim.tv_sec,
                         .mtime_nsec = (int64_t)st->st_mtim.tv_nsec,
                         .mode = (uint32_t)st->st_mode};
}

static void stat_of(const file_status *s, struct stat *st)
{
    memset(st, 0, sizeof *st);
    st->st_dev = (dev_t)s->dev;
    st->st_ino = (ino_t)s->ino;
    st->st_size = (off_t)s->size;
    st->st_mtim.tv_sec = (time_t)s->mtime_sec;
    st->st_mtim.tv_nsec = (long)s->mtime_nsec;
    st->st_mode = (mode_t)s->mode;
    st->st_nlink = 1;
}

/* Copies the thread's replayed answer to (question, path) into *out once
 * the log has it, and for an open that found its file, once all its bytes
 * came: waits while more may come. False with errno ENOENT when the log
 * has no answer, else errno set as the call failed (EIO for an open whose
 * bytes never all came). */
static bool replayed(uint8_t question, const char *path, answer *out)
{
    file_log *log = current_log;
    pthread_mutex_lock(&log->lock);
    const answer *a;
    while (!(a = find(log, question, path)) && !log->complete)
        pthread_cond_wait(&log->arrived, &log->lock);
    if (a)
        *out = *a;
    /* An open's bytes end where the next file's begin in the store. */
    bool awaits_bytes = a && out->found && question == ASK_OPEN;
    uint64_t end = awaits_bytes ? out->offset + out->status.size : 0;
    while (awaits_bytes && log->taken < end && !log->complete)
        pthread_cond_wait(&log->arrived, &log->lock);
    bool whole = log->taken >= end;
    pthread_mutex_unlock(&log->lock);
    if (!a) {
        errno = ENOENT;
        return false;
    }
    if (!out->found || !whole) {
        errno = out->found ? EIO : out->errnum;
        return false;
    }
    return true;
}

char *file_realpath(const char *path, char *resolved)
{
    if (current_log && current_replays) {
        answer a;
        return replayed(ASK_REALPATH, path, &a) ? strcpy(resolved, a.resolved) : NULL;
    }
    char *r = realpath(path, resolved);
    int e = errno;
    answer *a = to_note(ASK_REALPATH, path);
    if (a) {
        a->found = r != NULL;
        a->errnum = r ? 0 : e;
        if (r && !(a->resolved = strdup(r)))
            current_log->failed = true;
    }
    errno = e;
    return r;
}

int file_stat(const char *path, struct stat *st)
{
    if (current_log && current_replays) {
        answer a;
        if (!replayed(ASK_STAT, path, &a))
            return -1;
        stat_of(&a.status, st);
        return 0;
    }
    int r = stat(path, st);
    int e = errno;
    answer *a = to_note(ASK_STAT, path);
    if (a) {
        a->found = r == 0;
        a->errnum = r == 0 ? 0 : e;
        if (r == 0)
            a->status = status_of(st);
    }
    errno = e;
    return r;
}

int file_log_note_open(const char *path, int fd, const struct stat *st, int errnum)
{
    answer *a = to_note(ASK_OPEN, path);
    if (!a)
        return fd;
    a->found = fd >= 0;
    a->errnum = fd >= 0 ? 0 : errnum;
    if (fd >= 0) {
        a->status = status_of(st);
        current_log->failed = !add_file(current_log, a);
    }
    return current_log->on_open ? current_log->on_open(current_log->on_open_user, path, fd, fd >= 0 ? a->status.size : 0)
                                : fd;
}

bool file_log_replay_open(const char *path, int *fd, struct stat *st, int *errnum)
{
    if (!current_log || !current_replays)
        return false;
    *fd = -1;
    answer a;
    if (!replayed(ASK_OPEN, path, &a)) {
        *errnum = errno;
        return true;
    }
    *fd = open_file_copy(current_log->store, a.offset, a.status.size);
    if (*fd < 0)
        *errnum = errno;
    else
        stat_of(&a.status, st);
    return true;
}

/* Packing: fixed-width numbers in the machine's own order (every rank runs
 * the same build), each answer's numbers then its two strings. */

#define LOG_MAGIC 0x676c6667u /* "glfg" */

typedef struct packer {
    unsigned char *bytes;
    size_t size, cap;
    bool failed;
} packer;

static void put(packer *p, const void *data, size_t n)
{
    if (n == 0)
        return;
    if (p->failed || !array_reserve((void **)&p->bytes, &p->cap, p->size + n, 1)) {
        p->failed = true;
        return;
    }
    memcpy(p->bytes + p->size, data, n);
    p->size += n;
}

static void put_u64(packer *p, uint64_t v)
{
    put(p, &v, sizeof v);
}

static void put_text(packer *p, const char *s)
{
    uint64_t n = s ? strlen(s) : 0;
    put_u64(p, n);
    put(p, s, n);
}

glint_status file_log_pack(file_log *log, unsigned char **bytes, size_t *size, glint_error *err)
{
    *bytes = NULL;
    *size = 0;
    packer p = {0};
    put_u64(&p, LOG_MAGIC);
    put_u64(&p, log->count - log->packed);
    for (size_t i = log->packed; i < log->count; i++) {
        const answer *a = &log->answers[i];
        const file_status *s = &a->status;
        uint64_t numbers[] = {a->question, a->found,   (uint64_t)(int64_t)a->errnum, s->dev, s->ino, s->size,
                              (uint64_t)s->mtime_sec, (uint64_t)s->mtime_nsec, s->mode};
        put(&p, numbers, sizeof numbers);
        put_text(&p, a->path);
        put_text(&p, a->resolved);
    }
    if (log->failed || p.failed) {
        free(p.bytes);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory noting the scene's files");
    }
    *bytes = p.bytes;
    *size = p.size;
    log->packed = log->count;
    return GLINT_OK;
}

typedef struct unpacker {
    const unsigned char *at, *end;
    bool failed;
} unpacker;

static void get(unpacker *u, void *data, size_t n)
{
    if (u->failed || (size_t)(u->end - u->at) < n) {
        u->failed = true;
        memset(data, 0, n);
        return;
    }
    memcpy(data, u->at, n);
    u->at += n;
}

/* A string of the packed log, malloc'd; NULL for an empty one (or a
 * failure, then noted). */
static char *get_text(unpacker *u, bool *no_memory)
{
    uint64_t n;
    get(u, &n, sizeof n);
    if (u->failed || n == 0)
        return NULL;
    if (n >= PATH_MAX || (uint64_t)(u->end - u->at) < n || memchr(u->at, '\0', (size_t)n)) {
        u->failed = true;
        return NULL;
    }
    char *s = strndup((const char *)u->at, (size_t)n);
    *no_memory = *no_memory || !s;
    u->at += n;
    return s;
}

/* Reads one answer into a (its strings the log's to free); false when the
 * bytes are no answer. */
static bool get_answer(unpacker *u, answer *a, bool *no_memory)
{
    uint64_t numbers[9];
    get(u, numbers, sizeof numbers);
    *a = (answer){.question = (uint8_t)numbers[0],
                  .found = (uint8_t)numbers[1],
                  .errnum = (int32_t)(int64_t)numbers[2],
                  .status = {.dev = numbers[3],
                             .ino = numbers[4],
                             .size = numbers[5],
                             .mtime_sec = (int64_t)numbers[6],
                             .mtime_nsec = (int64_t)numbers[7],
                             .mode = (uint32_t)numbers[8]}};
    a->path = get_text(u, no_memory);
    a->resolved = get_text(u, no_memory);
    bool sound = !u->failed && a->path && numbers[0] <= ASK_STAT && numbers[1] <= 1 &&
                 numbers[2] == (uint64_t)(int64_t)a->errnum && numbers[5] <= INT64_MAX &&
                 (a->resolved != NULL) == (a->question == ASK_REALPATH && a->found);
    return sound;
}

/* Adds the packed answers to the log, which is locked; false with err
 * set when they are garbled or memory ran out. */
static bool take_answers(file_log *log, const unsigned char *bytes, size_t size, glint_error *err)
{
    unpacker u = {bytes, bytes + size, false};
    uint64_t magic, count;
    get(&u, &magic, sizeof magic);
    get(&u, &count, sizeof count);
    /* Each answer takes at least its numbers and two lengths. */
    bool no_memory = false;
    u.failed = u.failed || magic != LOG_MAGIC || count > size / (11 * sizeof(uint64_t));
    for (uint64_t i = 0; i < count && !u.failed && !no_memory; i++) {
        answer a;
        /* Recording kept one answer a question: a second is garbled. */
        if (!get_answer(&u, &a, &no_memory) || no_memory || find(log, a.question, a.path)) {
            u.failed = !no_memory;
            free(a.path);
            free(a.resolved);
            break;
        }
        answer *entered = add(log, &a);
        no_memory = !entered;
        if (entered && a.question == ASK_OPEN && a.found && !add_file(log, entered)) {
            u.failed = a.status.size > INT64_MAX - log->file_bytes;
            no_memory = !u.failed;
        }
    }
    if (!no_memory && !u.failed && u.at == u.end && log->store < 0) {
        log->store = memfd_create("glint-files", MFD_CLOEXEC);
        no_memory = log->store < 0;
    }
    if (no_memory)
        error_set(err, GLINT_ERR_NOMEM, "out of memory taking the scene's files from rank 0");
    else if (u.failed || u.at != u.end)
        error_set(err, GLINT_ERR_INVALID, "the scene's files came garbled from rank 0");
    return !no_memory && !u.failed && u.at == u.end;
}

glint_status file_log_take_answers(file_log *log, const unsigned char *bytes, size_t size, glint_error *err)
{
    pthread_mutex_lock(&log->lock);
    bool taken = take_answers(log, bytes, size, err);
    pthread_cond_broadcast(&log->arrived);
    pthread_mutex_unlock(&log->lock);
    return taken ? GLINT_OK : err->status;
}

void file_log_complete(file_log *log)
{
    pthread_mutex_lock(&log->lock);
    log->complete = true;
    pthread_cond_broadcast(&log->arrived);
    pthread_mutex_unlock(&log->lock);
}

glint_status file_log_take_bytes(file_log *log, const void *data, size_t n, glint_error *err)
{
    pthread_mutex_lock(&log->lock);
    glint_status status = GLINT_OK;
    if (n > log->file_bytes - log->taken)
        status = error_set(err, GLINT_ERR_INVALID, "more of the scene's files came from rank 0 than it announced");
    for (const unsigned char *at = data; n > 0 && !status;) {
        ssize_t w = write(log->store, at, n);
        if (w <= 0)
            status = error_set(err, errno == ENOSPC || errno == ENOMEM ? GLINT_ERR_NOMEM : GLINT_ERR_IO,
                               "cannot keep the scene's files from rank 0: %s", strerror(w < 0 ? errno : EIO));
        else {
            at += w;
            n -= (size_t)w;
            log->taken += (uint64_t)w;
        }
    }
    pthread_cond_broadcast(&log->arrived);
    pthread_mutex_unlock(&log->lock);
    return status;
}
