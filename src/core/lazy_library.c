/* lazy_library.c - opening a shared library on first use (lazy_library.h). */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include "core/lazy_library.h"

/* One lock for every library: each is opened once, and rarely. */
static pthread_mutex_t loading = PTHREAD_MUTEX_INITIALIZER;

/* Whether the dynamic loader's message says memory ran out: glibc leaves
 * errno alone and words it as a mapping or an allocation that failed. */
static bool out_of_memory(const char *why)
{
    return strstr(why, "failed to map") || strstr(why, "cannot map") || strstr(why, "allocate") ||
           strstr(why, "memory");
}

/* Opens the library and finds its functions: state 1, or -1 with failure
 * set; a failure for want of memory leaves state 0, to try again. */
static glint_status open_library(lazy_library *l)
{
    void *handle = dlopen(l->soname, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char *why = dlerror();
        why = why ? why : "it cannot be opened";
        if (out_of_memory(why))
            return GLINT_ERR_NOMEM;
        snprintf(l->failure, sizeof l->failure, "%s", why);
        l->state = -1;
        return GLINT_ERR_IO;
    }
    for (int i = 0; l->names[i]; i++) {
        l->addresses[i] = dlsym(handle, l->names[i]);
        if (!l->addresses[i]) {
            snprintf(l->failure, sizeof l->failure, "it has no function %s", l->names[i]);
            l->state = -1;
            return GLINT_ERR_IO; /* the handle stays open: the library may hold others' state */
        }
    }
    l->state = 1;
    return GLINT_OK;
}

bool lazy_library_load(lazy_library *l, glint_error *err)
{
    pthread_mutex_lock(&loading);
    glint_status status = l->state == 0 ? open_library(l) : l->state == 1 ? GLINT_OK : GLINT_ERR_IO;
    pthread_mutex_unlock(&loading);
    if (status == GLINT_ERR_NOMEM)
        error_set(err, status, "out of memory loading %s", l->soname);
    else if (status)
        error_set(err, status, "%s needs %s: %s", l->needed_by, l->soname, l->failure);
    return status == GLINT_OK;
}
