/* load_everywhere.c - rank 0's load recorded, sent and replayed on the
 * other ranks (load_everywhere.h). */
#include <limits.h>
#include "core/error.h"
#include "core/file_log.h"
#include "mpi/agree.h"
#include "mpi/load_everywhere.h"
#include "mpi/ship_files.h"

/* Rank 0's load, recording the files it reads into a new *log. */
static glint_status load_recording(scene_loader load, void *user, bool with_stdin, file_log **log,
                                   glint_error *err)
{
    glint_status status = with_stdin ? keep_stdin(err) : GLINT_OK;
    if (!status && !(*log = file_log_new()))
        status = error_set(err, GLINT_ERR_NOMEM, "out of memory");
    if (status)
        return status;
    file_log_record(*log);
    status = load(user, true, err);
    file_log_stop();
    return status;
}

glint_status load_everywhere(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, bool wait_for_all,
                             int *failed_rank, glint_error *err)
{
    *failed_rank = 0;
    int rank;
    MPI_Comm_rank(comm, &rank);
    file_log *log = NULL;
    glint_error told = {0};
    if (rank == 0 && load_recording(load, user, with_stdin, &log, &told))
        *err = told;
    /* Rank 0's outcome, waited for without spinning: its load may be long. */
    agree_on_rank0_bytes(comm, &told, (int)sizeof told);
    if (told.status) {
        *err = told;
        file_log_free(log);
        return told.status;
    }
    bool by_rank0 = rank == 0;
    glint_status status = rank == 0 ? send_files(comm, log, with_stdin, err)
                                    : receive_files(comm, &log, &by_rank0, err);
    if (!status && rank != 0) {
        file_log_replay(log);
        status = load(user, false, err);
        file_log_stop();
    }
    file_log_free(log);
    if (!wait_for_all) {
        *failed_rank = status && !by_rank0 ? rank : 0;
        return status;
    }
    /* The first rank that failed, and why, on every rank. */
    int first = status ? (by_rank0 ? 0 : rank) : INT_MAX;
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
