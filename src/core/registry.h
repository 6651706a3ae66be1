/* registry.h - the look-ups every registry of kinds offers, written once.
 * A registry is a static const array of pointers to its kinds' records,
 * each record with an `id` field (the public enum's value); the kinds' own
 * header declares the functions and says what they are for. */
#ifndef GLINT_CORE_REGISTRY_H
#define GLINT_CORE_REGISTRY_H

#include <stddef.h>

/* Defines, over KINDS (an array of `const T *`):
 *   const T *P_of(ID id)   the kind with that id, or NULL
 *   int P_count(void)      how many kinds there are
 *   const T *P_at(int i)   kind i, in the array's order, or NULL */
#define REGISTRY_LOOKUPS(T, P, ID, KINDS)                                                                          \
    const T *P##_of(ID id)                                                                                         \
    {                                                                                                              \
        for (size_t i = 0; i < sizeof KINDS / sizeof KINDS[0]; i++)                                                \
            if (KINDS[i]->id == id)                                                                                \
                return KINDS[i];                                                                                   \
        return NULL;                                                                                               \
    }                                                                                                              \
    int P##_count(void) { return (int)(sizeof KINDS / sizeof KINDS[0]); }                                          \
    const T *P##_at(int i) { return i >= 0 && i < P##_count() ? KINDS[i] : NULL; }

#endif
