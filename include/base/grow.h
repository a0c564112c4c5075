/*
 * grow.h: growable arrays: one rule for making room, shared by every
 * module that reads an unknown number of items.
 */
#ifndef RAYTRACE_GROW_H
#define RAYTRACE_GROW_H

#include <stdint.h>
#include <stdlib.h>

/* Returns the capacity grow_reserve() grows a full array of capacity to. */
static inline size_t grow_next_capacity(size_t capacity)
{
    return capacity ? 2 * capacity : 16;
}

/* Makes room for one more item of size bytes in the array *items, which
 * holds count items in room for *capacity, doubling it (from 16); returns
 * 0, or -1 leaving the array as it was when memory runs out. */
static inline int grow_reserve(void **items, size_t *capacity, size_t count, size_t size)
{
    size_t cap;
    void *grown;

    if (count < *capacity)
        return 0;
    cap = grow_next_capacity(*capacity);
    if (cap > SIZE_MAX / size)
        return -1;
    grown = realloc(*items, cap * size);
    if (!grown)
        return -1;
    *items = grown;
    *capacity = cap;
    return 0;
}

#endif
