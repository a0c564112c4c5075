/* aligned_posix.c: aligned memory from C11's aligned_alloc (see aligned.h). */
#include "base/aligned.h"

#include <stdlib.h>

void *aligned_new(size_t align, size_t size)
{
    return aligned_alloc(align, size);
}

void aligned_free(void *p)
{
    free(p);
}
