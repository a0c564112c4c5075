/* aligned_win32.c: aligned memory on Windows (see aligned.h). */
#include "base/aligned.h"

#include <malloc.h>

void *aligned_new(size_t align, size_t size)
{
    return _aligned_malloc(size, align);
}

void aligned_free(void *p)
{
    _aligned_free(p);
}
