/* ship_files.c - rank 0's files broadcast to the other ranks as its load
 * reads them (ship_files.h).
 *
 * What is sent, all broadcast from rank 0: for a scene on standard input,
 * first its length (or STDIN_FAILED and the glint_status of rank 0's
 * failure to keep it) and its bytes, CHUNK_BYTES at a time, each chunk
 * after a uint64 that is 0, or the glint_status of rank 0's failure to
 * read it, when the chunk does not follow and nothing more comes. Then messages,
 * one or more an open of rank 0's load, each
 *   head     3 uint64: the length of the answers that follow, of the
 *            files' bytes that follow (at most CHUNK_BYTES), and whether
 *            this is the last message
 *   answers  what rank 0's log noted since the message before (file_log_pack)
 *   bytes    the next bytes of the files
 *   outcome  in the last message alone: a glint_error, rank 0's failure
 *            (to load, or to send a file) or status GLINT_OK
 * A head is waited for without spinning (rank 0's load runs between two),
 * the rest as a plain broadcast. A worker that cannot keep what comes
 * still takes part in every broadcast, so that no rank is left waiting in
 * one. */
#define _GNU_SOURCE /* memfd_create */
#include <errno.h>
#include <mpi.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/error.h"
#include "core/open_file.h"
#include "mpi/agree.h"
#include "mpi/ship_files.h"
#include "scenefile/scene_file.h"

#define STDIN_FAILED UINT64_MAX
#define CHUNK_BYTES ((size_t)16 << 20)

/* Broadcasts n bytes from rank 0 of comm, in pieces MPI's int counts can
 * hold. */
static void broadcast(MPI_Comm comm, void *bytes, size_t n)
{
    for (size_t at = 0; at < n;) {
        int piece = n - at < (size_t)1 << 30 ? (int)(n - at) : 1 << 30;
        MPI_Bcast((unsigned char *)bytes + at, piece, MPI_BYTE, 0, comm);
        at += (size_t)piece;
    }
}

/* Writes all n bytes to fd; false with errno set. */
static bool write_all(int fd, const unsigned char *bytes, size_t n)
{
    while (n > 0) {
        ssize_t w = write(fd, bytes, n);
        if (w <= 0) {
            errno = w < 0 ? errno : EIO;
            return false;
        }
        bytes += w;
        n -= (size_t)w;
    }
    return true;
}

glint_status keep_stdin(glint_error *err)
{
    int kept = memfd_create("glint-stdin", MFD_CLOEXEC);
    unsigned char *buffer = malloc(1 << 16);
    if (kept < 0 || !buffer) {
        free(buffer);
        if (kept >= 0)
            close(kept);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory keeping the scene from standard input");
    }
    size_t total = 0;
    ssize_t got = 0;
    while (total <= (size_t)SCENE_FILE_MAX_BYTES) {
        size_t want = (size_t)SCENE_FILE_MAX_BYTES + 1 - total;
        got = read(STDIN_FILENO, buffer, want < (1 << 16) ? want : (1 << 16));
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0 || !write_all(kept, buffer, (size_t)got))
            break;
        total += (size_t)got;
    }
    int e = errno;
    free(buffer);
    bool placed = got == 0 || total > (size_t)SCENE_FILE_MAX_BYTES;
    if (placed && (lseek(kept, 0, SEEK_SET) != 0 || dup2(kept, STDIN_FILENO) != STDIN_FILENO)) {
        placed = false;
        e = errno;
    }
    close(kept);
    if (!placed)
        return error_set(err, got < 0 ? GLINT_ERR_IO : GLINT_ERR_NOMEM, "cannot %s the scene on standard input: %s",
                         got < 0 ? "read" : "keep", strerror(e));
    return GLINT_OK;
}

/* Broadcasts n bytes from rank 0 in chunks: into `bytes`, or, on a rank
 * with nowhere to keep them (NULL), through `scratch` (CHUNK_BYTES). */
static void broadcast_chunks(MPI_Comm comm, unsigned char *bytes, size_t n, unsigned char *scratch)
{
    for (size_t at = 0; at < n; at += CHUNK_BYTES)
        broadcast(comm, bytes ? bytes + at : scratch, n - at < CHUNK_BYTES ? n - at : CHUNK_BYTES);
}

/* Reads n bytes at `offset` of fd; false with errno set (EIO: the file
 * ended first). */
static bool read_all_at(int fd, unsigned char *to, size_t n, uint64_t offset)
{
    while (n > 0) {
        ssize_t got = pread(fd, to, n, (off_t)offset);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0) {
            errno = got < 0 ? errno : EIO;
            return false;
        }
        to += got;
        n -= (size_t)got;
        offset += (uint64_t)got;
    }
    return true;
}

glint_status send_stdin(MPI_Comm comm, glint_status kept, glint_error *err)
{
    struct stat st;
    unsigned char *chunk = NULL;
    glint_status status = kept;
    if (!status && fstat(STDIN_FILENO, &st) != 0)
        status = error_set(err, GLINT_ERR_IO, "cannot send the scene on standard input: %s", strerror(errno));
    if (!status && !(chunk = malloc(CHUNK_BYTES)))
        status = error_set(err, GLINT_ERR_NOMEM, "out of memory sending the scene on standard input");
    uint64_t head[2] = {status ? STDIN_FAILED : (uint64_t)st.st_size, (uint64_t)status};
    agree_on_rank0_bytes(comm, head, (int)sizeof head);
    for (uint64_t at = 0; !status && at < head[0]; at += CHUNK_BYTES) {
        size_t n = head[0] - at < CHUNK_BYTES ? (size_t)(head[0] - at) : CHUNK_BYTES;
        if (!read_all_at(STDIN_FILENO, chunk, n, at))
            status = error_set(err, GLINT_ERR_IO, "cannot send the scene on standard input: %s", strerror(errno));
        uint64_t word = (uint64_t)status;
        broadcast(comm, &word, sizeof word);
        if (!status)
            broadcast(comm, chunk, n);
    }
    free(chunk);
    return status;
}

/* Rank 0's failure, as a rank that did not see it tells it. */
static glint_status rank0_failed(glint_status status, bool *by_rank0, glint_error *err)
{
    *by_rank0 = true;
    return error_set(err, status, "rank 0 could not send the scene on standard input");
}

glint_status receive_stdin(MPI_Comm comm, bool *by_rank0, glint_error *err)
{
    *by_rank0 = false;
    uint64_t head[2];
    /* Waited for without spinning: rank 0 reads all of its standard input first. */
    agree_on_rank0_bytes(comm, head, (int)sizeof head);
    if (head[0] == STDIN_FAILED)
        return rank0_failed((glint_status)head[1], by_rank0, err);
    unsigned char *chunk = malloc(CHUNK_BYTES);
    if (!chunk) {
        fputs("glint: out of memory taking the scene from rank 0\n", stderr);
        MPI_Abort(comm, 5); /* it cannot even take part */
    }
    glint_status status = GLINT_OK, failed_there = GLINT_OK;
    int kept = memfd_create("glint-stdin", MFD_CLOEXEC);
    if (kept < 0)
        status = error_set(err, GLINT_ERR_NOMEM, "cannot keep the scene on standard input: %s", strerror(errno));
    for (uint64_t at = 0; at < head[0] && !failed_there; at += CHUNK_BYTES) {
        size_t n = head[0] - at < CHUNK_BYTES ? (size_t)(head[0] - at) : CHUNK_BYTES;
        uint64_t word;
        broadcast(comm, &word, sizeof word);
        if ((failed_there = (glint_status)word))
            break;
        broadcast(comm, chunk, n);
        if (!status && !write_all(kept, chunk, n))
            status = error_set(err, GLINT_ERR_NOMEM, "cannot keep the scene on standard input: %s", strerror(errno));
    }
    free(chunk);
    if (!status && !failed_there && (lseek(kept, 0, SEEK_SET) != 0 || dup2(kept, STDIN_FILENO) != STDIN_FILENO))
        status = error_set(err, GLINT_ERR_IO, "cannot keep the scene on standard input: %s", strerror(errno));
    if (kept >= 0)
        close(kept);
    return failed_there ? rank0_failed(failed_there, by_rank0, err) : status;
}

/* One message: its head, the answers and the bytes; `outcome` for the
 * last. */
static void send_message(MPI_Comm comm, unsigned char *answers, size_t answer_bytes, unsigned char *bytes,
                         size_t byte_count, glint_error *outcome)
{
    uint64_t head[3] = {answer_bytes, byte_count, outcome != NULL};
    agree_on_rank0_bytes(comm, head, (int)sizeof head);
    broadcast(comm, answers, answer_bytes);
    broadcast(comm, bytes, byte_count);
    if (outcome)
        broadcast(comm, outcome, sizeof *outcome);
}

/* Adds what was just sent to the log rank 0 keeps, when it keeps one, as
 * the other ranks add it to theirs; a failure to keep it is the load's. */
static void keep_sent(file_sender *s, const unsigned char *answers, size_t answer_bytes, const unsigned char *bytes,
                      size_t byte_count)
{
    if (!s->keep || s->status)
        return;
    if (answer_bytes > 0)
        s->status = file_log_take_answers(s->keep, answers, answer_bytes, &s->err);
    if (!s->status && byte_count > 0)
        s->status = file_log_take_bytes(s->keep, bytes, byte_count, &s->err);
}

/* The open hook of rank 0's log: the answers noted so far and a copy of
 * the opened file's bytes, sent at once; the load reads the copy, so that
 * it reads what was sent. After a failure nothing more is sent: the last
 * message tells it. */
static int send_open(void *user, const char *path, int fd, uint64_t size)
{
    file_sender *s = user;
    unsigned char *answers = NULL;
    size_t answer_bytes = 0;
    if (s->status || (s->status = file_log_pack(s->log, &answers, &answer_bytes, &s->err)))
        return fd;
    int copy = fd >= 0 ? open_file_copy(fd, 0, size) : -1;
    if (fd >= 0 && copy < 0) {
        s->status = error_set(&s->err, errno == EIO ? GLINT_ERR_INVALID : GLINT_ERR_NOMEM, "cannot send '%s': %s", path,
                              errno == EIO ? "it changed while the scene was loaded" : strerror(errno));
        free(answers);
        return fd;
    }
    for (uint64_t at = 0; at == 0 || at < size; at += CHUNK_BYTES) {
        size_t n = size - at < CHUNK_BYTES ? (size_t)(size - at) : CHUNK_BYTES;
        if (n > 0 && !read_all_at(copy, s->chunk, n, at)) {
            s->status = error_set(&s->err, GLINT_ERR_IO, "cannot send '%s': %s", path, strerror(errno));
            break;
        }
        send_message(s->comm, answers, answer_bytes, s->chunk, n, NULL);
        keep_sent(s, answers, answer_bytes, s->chunk, n);
        free(answers);
        answers = NULL;
        answer_bytes = 0;
    }
    free(answers);
    if (copy < 0)
        return fd;
    close(fd);
    return copy;
}

glint_status send_files_begin(file_sender *s, MPI_Comm comm, file_log *log, file_log *keep)
{
    *s = (file_sender){.comm = comm, .log = log, .keep = keep, .chunk = malloc(CHUNK_BYTES)};
    if (!s->chunk)
        s->status = error_set(&s->err, GLINT_ERR_NOMEM, "out of memory sending the scene's files");
    if (log)
        file_log_on_open(log, send_open, s);
    return s->status;
}

glint_status send_files_end(file_sender *s, const glint_error *told, glint_error *err)
{
    unsigned char *answers = NULL;
    size_t answer_bytes = 0;
    if (!s->status && s->log)
        s->status = file_log_pack(s->log, &answers, &answer_bytes, &s->err);
    keep_sent(s, answers, answer_bytes, NULL, 0);
    if (s->keep)
        file_log_complete(s->keep);
    glint_error outcome = told->status ? *told : s->status ? s->err : (glint_error){0};
    send_message(s->comm, answers, answer_bytes, NULL, 0, &outcome);
    free(answers);
    free(s->chunk);
    if (s->log)
        file_log_on_open(s->log, NULL, NULL);
    if (outcome.status)
        *err = outcome;
    return outcome.status;
}

glint_status receive_files(MPI_Comm comm, file_log *log, bool *by_rank0, glint_error *err)
{
    *by_rank0 = false;
    unsigned char *chunk = malloc(CHUNK_BYTES);
    if (!chunk) {
        fputs("glint: out of memory taking the scene's files from rank 0\n", stderr);
        MPI_Abort(comm, 5); /* it cannot even take part */
    }
    /* Without a log the rank takes part, keeping nothing. */
    glint_status status = log ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "out of memory taking the scene's files");
    for (;;) {
        uint64_t head[3];
        agree_on_rank0_bytes(comm, head, (int)sizeof head);
        unsigned char *answers = !status && head[0] <= SIZE_MAX ? malloc(head[0] ? (size_t)head[0] : 1) : NULL;
        if (!answers && !status)
            status = error_set(err, GLINT_ERR_NOMEM, "out of memory taking the scene's files from rank 0");
        broadcast_chunks(comm, answers, (size_t)head[0], chunk);
        if (!status && head[0] > 0)
            status = file_log_take_answers(log, answers, (size_t)head[0], err);
        free(answers);
        broadcast_chunks(comm, NULL, (size_t)head[1], chunk);
        if (!status && head[1] > 0)
            status = head[1] <= CHUNK_BYTES ? file_log_take_bytes(log, chunk, (size_t)head[1], err)
                                            : error_set(err, GLINT_ERR_INVALID, "the scene's files came garbled from rank 0");
        /* The load waiting for what will not come fails now. */
        if (status && log)
            file_log_complete(log);
        if (head[2]) {
            glint_error outcome;
            broadcast(comm, &outcome, sizeof outcome);
            if (outcome.status) {
                *by_rank0 = true;
                *err = outcome;
                status = outcome.status;
            }
            break;
        }
    }
    free(chunk);
    if (log)
        file_log_complete(log);
    return status;
}
