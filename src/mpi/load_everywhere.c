/* load_everywhere.c - rank 0's load recorded and sent as it goes, and
 * replayed on the other ranks at the same time (load_everywhere.h).
 *
 * A worker loads on a thread of its own while its main thread, the one
 * that calls MPI, takes in rank 0's files: the two loads run side by side,
 * a worker's waiting only for files rank 0 has not opened yet, so that the
 * workers begin to render about when rank 0 does. */
#include <limits.h>
#include <pthread.h>
#include "core/error.h"
#include "core/file_log.h"
#include "mpi/agree.h"
#include "mpi/load_everywhere.h"
#include "mpi/ship_files.h"

/* Rank 0's load, its files sent to the others as it reads them, and kept
 * in *kept when it is not NULL. */
static glint_status load_sending(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, file_log **kept,
                                 glint_error *err)
{
    glint_error told = {0};
    if (with_stdin && send_stdin(comm, keep_stdin(&told), &told)) {
        *err = told;
        return told.status;
    }
    file_log *log = file_log_new();
    file_log *keep = kept ? file_log_new() : NULL;
    file_sender sender;
    glint_status began = send_files_begin(&sender, comm, log, keep);
    if (!log || (kept && !keep))
        error_set(&told, GLINT_ERR_NOMEM, "out of memory");
    else if (!began) {
        file_log_record(log);
        load(user, true, &told);
        file_log_stop();
    }
    glint_status status = send_files_end(&sender, &told, err);
    file_log_free(log);
    if (kept && !status)
        *kept = keep;
    else
        file_log_free(keep);
    return status;
}

/* A worker's load, on its own thread, replaying the log as it comes. */
typedef struct replay {
    file_log *log;
    scene_loader load;
    void *user;
    glint_status status;
    glint_error err;
} replay;

static void *load_replaying(void *arg)
{
    replay *r = arg;
    file_log_replay(r->log);
    r->status = r->load(r->user, false, &r->err);
    file_log_stop();
    return NULL;
}

/* A worker's load from rank 0's files, kept in *kept when it is not NULL;
 * *by_rank0 when rank 0 failed. */
static glint_status load_receiving(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, file_log **kept,
                                   bool *by_rank0, glint_error *err)
{
    glint_status status = with_stdin ? receive_stdin(comm, by_rank0, err) : GLINT_OK;
    if (*by_rank0)
        return status;
    replay r = {.log = file_log_new(), .load = load, .user = user};
    pthread_t thread;
    bool started = false;
    if (!status && !r.log)
        status = error_set(err, GLINT_ERR_NOMEM, "out of memory taking the scene's files from rank 0");
    if (!status && !(started = pthread_create(&thread, NULL, load_replaying, &r) == 0))
        status = error_set(err, GLINT_ERR_NOMEM, "out of memory for a thread to load the scene");
    /* A rank that failed already still takes part, keeping nothing. */
    glint_error received_err = {0};
    glint_status received = receive_files(comm, status ? NULL : r.log, by_rank0, &received_err);
    if (started)
        pthread_join(thread, NULL);
    /* Rank 0's failure first, then the rank's own, receiving or loading. */
    if (*by_rank0 || (!status && received)) {
        *err = received_err;
        status = received;
    } else if (!status && r.status) {
        *err = r.err;
        status = r.status;
    }
    if (kept && !status)
        *kept = r.log;
    else
        file_log_free(r.log);
    return status;
}

glint_status load_everywhere(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, bool wait_for_all,
                             file_log **kept, int *failed_rank, glint_error *err)
{
    *failed_rank = 0;
    if (kept)
        *kept = NULL;
    int rank;
    MPI_Comm_rank(comm, &rank);
    bool by_rank0 = rank == 0;
    glint_status status = rank == 0 ? load_sending(comm, load, user, with_stdin, kept, err)
                                    : load_receiving(comm, load, user, with_stdin, kept, &by_rank0, err);
    if (status && by_rank0)
        return status;
    if (!wait_for_all) {
        *failed_rank = status ? rank : 0;
        return status;
    }
    /* The first rank that failed, and why, on every rank. */
    int first = status ? rank : INT_MAX;
    agree_on_min(comm, &first);
    if (first == INT_MAX)
        return GLINT_OK;
    *failed_rank = first;
    int why = rank == first ? (int)status : 0;
    agree_on_max(comm, &why);
    if (rank != first)
        status = error_set(err, (glint_status)why, "rank %d could not load the scene rank 0 loaded", first);
    return status;
}

glint_status load_again(file_log *log, scene_loader load, void *user, bool rank0, glint_error *err)
{
    file_log_replay(log);
    glint_status status = load(user, rank0, err);
    file_log_stop();
    return status;
}
