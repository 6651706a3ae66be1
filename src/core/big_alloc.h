/* big_alloc.h - memory for large buffers that are written whole soon after
 * they are allocated: decoded images, the film, encoded files. */
#ifndef GLINT_CORE_BIG_ALLOC_H
#define GLINT_CORE_BIG_ALLOC_H

#include <stddef.h>

/* Buffers of this many bytes or more lie on huge pages. */
#define BIG_ALLOC_MIN ((size_t)1 << 20)

/* Room for `bytes` bytes (none: room for one), not cleared, freed with
 * free(); NULL when memory runs out. From BIG_ALLOC_MIN up it starts on a
 * 2 MiB boundary and spans whole 2 MiB pages, which the kernel is asked to
 * back as huge pages (it may refuse: transparent huge pages off, or none
 * free; nothing else changes). A page fault clears a page: 4 KiB ones cost
 * about 10 us each on the virtual machines glint is measured on, so a
 * 1.5 MB texture took 385 faults and 4 ms, where one huge page takes 0.13
 * ms. A buffer from 1 to 2 MiB spends up to 1 MiB more for that. */
void *big_alloc(size_t bytes);

#endif
