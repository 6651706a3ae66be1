/* same_build.c - every rank's build compared with rank 0's (same_build.h). */
#define _GNU_SOURCE /* dl_iterate_phdr */
#include <elf.h>
#include <link.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "mpi/same_build.h"

/* A build's name: "0.1.0 build 3f2a...", the version and the build ID in
 * hex ("no build ID" when the linker gave none). */
typedef struct build_name {
    char text[128];
} build_name;

/* dl_iterate_phdr's callback: the first object listed is the executable;
 * its build ID note, when found, goes into the build_name. */
static int find_build_id(struct dl_phdr_info *info, size_t size, void *user)
{
    (void)size;
    build_name *name = user;
    for (int i = 0; i < info->dlpi_phnum; i++) {
        const ElfW(Phdr) *ph = &info->dlpi_phdr[i];
        if (ph->p_type != PT_NOTE)
            continue;
        const unsigned char *at = (const unsigned char *)(info->dlpi_addr + ph->p_vaddr), *end = at + ph->p_memsz;
        while (at + sizeof(ElfW(Nhdr)) <= end) {
            const ElfW(Nhdr) *note = (const ElfW(Nhdr) *)at;
            const unsigned char *desc = at + sizeof *note + ((note->n_namesz + 3) & ~3u);
            if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 && memcmp(at + sizeof *note, "GNU", 4) == 0 &&
                desc + note->n_descsz <= end) {
                size_t used = strlen(name->text);
                snprintf(name->text + used, sizeof name->text - used, " build ");
                for (unsigned k = 0; k < note->n_descsz && k < 40; k++) {
                    used = strlen(name->text);
                    snprintf(name->text + used, sizeof name->text - used, "%02x", desc[k]);
                }
                return 1;
            }
            at = desc + ((note->n_descsz + 3) & ~3u);
        }
    }
    return 1; /* only the executable */
}

static build_name this_build(void)
{
    build_name name;
    snprintf(name.text, sizeof name.text, "%s", GLINT_VERSION);
    size_t before = strlen(name.text);
    dl_iterate_phdr(find_build_id, &name);
    if (strlen(name.text) == before)
        snprintf(name.text + before, sizeof name.text - before, ", no build ID");
    return name;
}

glint_status check_same_build(MPI_Comm comm, glint_error *err)
{
    int rank, ranks;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &ranks);
    build_name mine = this_build();
    build_name *all = rank == 0 ? calloc((size_t)ranks, sizeof *all) : NULL;
    if (rank == 0 && !all) {
        /* Not even the others can be told: MPI ends the job. */
        fputs("glint: out of memory for the ranks' builds\n", stderr);
        MPI_Abort(comm, 5);
    }
    int differs = 0;
    MPI_Gather(&mine, sizeof mine, MPI_BYTE, all, sizeof mine, MPI_BYTE, 0, comm);
    for (int r = 1; rank == 0 && r < ranks && !differs; r++) {
        all[r].text[sizeof all[r].text - 1] = '\0';
        if (strcmp(all[r].text, mine.text) != 0) {
            differs = r;
            error_set(err, GLINT_ERR_INVALID,
                      "rank %d runs another build of glint (%s) than rank 0 (%s): every rank must run the same "
                      "build, or the image would depend on which rank rendered what",
                      r, all[r].text, mine.text);
        }
    }
    free(all);
    MPI_Bcast(&differs, 1, MPI_INT, 0, comm);
    if (differs && rank != 0)
        error_set(err, GLINT_ERR_INVALID, "rank %d runs another build of glint than rank 0", differs);
    return differs ? GLINT_ERR_INVALID : GLINT_OK;
}
