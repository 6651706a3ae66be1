/* ship_files.c - rank 0's files broadcast to the other ranks (ship_files.h).
 *
 * What is sent, all by MPI_Bcast from rank 0:
 *   head     3 uint64: the packed log's length, the files' bytes in all,
 *            standard input's bytes (0 without); or SHIP_FAILED and the
 *            glint_status of rank 0's failure, and nothing follows
 *   log      the packed log
 *   chunks   the files' bytes one after the other, then standard input's,
 *            CHUNK_BYTES a chunk, each chunk after a uint64 that is 0, or
 *            the glint_status of rank 0's failure to read it, when the
 *            chunk does not follow and nothing more comes
 * A worker that cannot keep what comes still takes part in every
 * broadcast, so that no rank is left waiting in one. */
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
#include "mpi/ship_files.h"
#include "scenefile/scene_file.h"

#define SHIP_FAILED UINT64_MAX
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

/* The sender's place in the bytes it sends: the file being read, and how
 * much of it and of standard input is left. */
typedef struct reader {
    const file_log *log;
    size_t next_file;
    int fd;                   /* the file being read, or -1 */
    uint64_t left_in_file, stdin_left, stdin_at;
    glint_error err;
} reader;

/* Fills n bytes with what comes next; false with r->err set when a file
 * cannot be read as the load read it. */
static bool read_next(reader *r, unsigned char *to, size_t n)
{
    while (n > 0) {
        if (r->fd < 0 && r->next_file < file_log_file_count(r->log)) {
            r->fd = file_log_open_file(r->log, r->next_file, &r->left_in_file, &r->err);
            if (r->fd < 0)
                return false;
            r->next_file++;
        }
        bool in_file = r->fd >= 0;
        uint64_t left = in_file ? r->left_in_file : r->stdin_left;
        size_t want = left < n ? (size_t)left : n;
        ssize_t got = !want ? 0 : in_file ? read(r->fd, to, want) : pread(STDIN_FILENO, to, want, (off_t)r->stdin_at);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0 || (got == 0 && (want > 0 || !in_file))) {
            const char *reason = got < 0 ? strerror(errno) : "it is shorter than when the scene was loaded";
            if (in_file)
                error_set(&r->err, GLINT_ERR_IO, "cannot send '%s': %s",
                          file_log_file_path(r->log, r->next_file - 1), reason);
            else
                error_set(&r->err, GLINT_ERR_IO, "cannot send the scene on standard input: %s", reason);
            return false;
        }
        if (in_file && (r->left_in_file -= (uint64_t)got) == 0) {
            close(r->fd);
            r->fd = -1;
        } else if (!in_file) {
            r->stdin_left -= (uint64_t)got;
            r->stdin_at += (uint64_t)got;
        }
        to += got;
        n -= (size_t)got;
    }
    return true;
}

/* Broadcasts n bytes from rank 0 in chunks: into `bytes`, or, on a rank
 * with nowhere to keep them (NULL), through `scratch` (CHUNK_BYTES). */
static void broadcast_chunks(MPI_Comm comm, unsigned char *bytes, size_t n, unsigned char *scratch)
{
    for (size_t at = 0; at < n; at += CHUNK_BYTES)
        broadcast(comm, bytes ? bytes + at : scratch, n - at < CHUNK_BYTES ? n - at : CHUNK_BYTES);
}

glint_status send_files(MPI_Comm comm, const file_log *log, bool with_stdin, glint_error *err)
{
    unsigned char *packed = NULL, *chunk = malloc(CHUNK_BYTES);
    size_t packed_size = 0;
    struct stat st;
    reader r = {.log = log, .fd = -1};
    glint_status status = GLINT_OK;
    if (!chunk)
        status = error_set(err, GLINT_ERR_NOMEM, "out of memory sending the scene's files");
    else if (with_stdin && fstat(STDIN_FILENO, &st) != 0)
        status = error_set(err, GLINT_ERR_IO, "cannot send the scene on standard input: %s", strerror(errno));
    else
        status = file_log_pack(log, &packed, &packed_size, err);
    r.stdin_left = with_stdin && !status ? (uint64_t)st.st_size : 0;
    uint64_t head[3] = {status ? SHIP_FAILED : packed_size, status ? (uint64_t)status : file_log_file_bytes(log),
                        r.stdin_left};
    broadcast(comm, head, sizeof head);
    if (status) {
        free(chunk);
        return status;
    }
    broadcast_chunks(comm, packed, packed_size, NULL);
    free(packed);
    for (uint64_t left = head[1] + head[2]; left > 0 && !status;) {
        size_t n = left < CHUNK_BYTES ? (size_t)left : CHUNK_BYTES;
        if (!read_next(&r, chunk, n))
            status = error_set(err, r.err.status, "%s", r.err.message);
        uint64_t word = status ? (uint64_t)status : 0;
        broadcast(comm, &word, sizeof word);
        if (!status)
            broadcast(comm, chunk, n);
        left -= n;
    }
    if (r.fd >= 0)
        close(r.fd);
    free(chunk);
    return status;
}

/* Rank 0's failure, as a rank that did not see it tells it. */
static glint_status rank0_failed(glint_status status, glint_error *err)
{
    return error_set(err, status, "rank 0 could not send the scene's files");
}

glint_status receive_files(MPI_Comm comm, file_log **out, bool *by_rank0, glint_error *err)
{
    *out = NULL;
    *by_rank0 = false;
    uint64_t head[3];
    broadcast(comm, head, sizeof head);
    if (head[0] == SHIP_FAILED) {
        *by_rank0 = true;
        return rank0_failed((glint_status)head[1], err);
    }
    unsigned char *chunk = malloc(CHUNK_BYTES);
    if (!chunk) {
        fputs("glint: out of memory taking the scene's files from rank 0\n", stderr);
        MPI_Abort(comm, 5); /* it cannot even take part */
    }
    glint_status status = GLINT_OK;
    unsigned char *packed = head[0] <= SIZE_MAX ? malloc(head[0] ? (size_t)head[0] : 1) : NULL;
    if (!packed)
        status = error_set(err, GLINT_ERR_NOMEM, "out of memory taking the scene's files from rank 0");
    broadcast_chunks(comm, packed, (size_t)head[0], chunk);
    file_log *log = packed ? file_log_unpack(packed, (size_t)head[0], err) : NULL;
    free(packed);
    if (!log && !status)
        status = err->status;
    if (log && file_log_file_bytes(log) != head[1])
        status = error_set(err, GLINT_ERR_INVALID, "the scene's files came garbled from rank 0");
    int kept_stdin = head[2] > 0 ? memfd_create("glint-stdin", MFD_CLOEXEC) : -1;
    if (head[2] > 0 && kept_stdin < 0 && !status)
        status = error_set(err, GLINT_ERR_NOMEM, "cannot keep the scene on standard input: %s", strerror(errno));
    glint_status failed_there = GLINT_OK;
    for (uint64_t done = 0, total = head[1] + head[2]; done < total;) {
        size_t n = total - done < CHUNK_BYTES ? (size_t)(total - done) : CHUNK_BYTES;
        uint64_t word;
        broadcast(comm, &word, sizeof word);
        if (word != 0) {
            failed_there = (glint_status)word;
            break;
        }
        broadcast(comm, chunk, n);
        /* The chunk's bytes of files, then of standard input. */
        size_t to_files = done < head[1] ? (size_t)(head[1] - done < n ? head[1] - done : n) : 0;
        if (!status && to_files > 0)
            status = file_log_take_bytes(log, chunk, to_files, err);
        if (!status && n > to_files && !write_all(kept_stdin, chunk + to_files, n - to_files))
            status = error_set(err, GLINT_ERR_NOMEM, "cannot keep the scene on standard input: %s", strerror(errno));
        done += n;
    }
    free(chunk);
    if (!status && !failed_there && kept_stdin >= 0 &&
        (lseek(kept_stdin, 0, SEEK_SET) != 0 || dup2(kept_stdin, STDIN_FILENO) != STDIN_FILENO))
        status = error_set(err, GLINT_ERR_IO, "cannot keep the scene on standard input: %s", strerror(errno));
    if (kept_stdin >= 0)
        close(kept_stdin);
    if (failed_there) {
        *by_rank0 = true;
        status = rank0_failed(failed_there, err);
    }
    if (status) {
        file_log_free(log);
        return status;
    }
    *out = log;
    return GLINT_OK;
}
