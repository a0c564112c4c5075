/*
 * aligned.h: memory aligned beyond malloc()'s guarantee (C11's
 * aligned_alloc, which Windows's C library lacks: there
 * _aligned_malloc, whose blocks only _aligned_free may release).
 * aligned_posix.c and aligned_win32.c hold the two.
 */
#ifndef RAYTRACE_ALIGNED_H
#define RAYTRACE_ALIGNED_H

#include <stddef.h>

/* Returns size bytes aligned to align (a power of two; size a multiple of
 * it), or NULL; release them with aligned_free() alone. */
void *aligned_new(size_t align, size_t size);

/* Releases a block of aligned_new() (NULL: nothing). */
void aligned_free(void *p);

#endif
