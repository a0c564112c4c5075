/* threads.c: the process's thread count (see threads.h). */
#include "base/threads.h"

#ifdef _OPENMP
#include <omp.h>
#endif

int threads_processors(void)
{
#ifdef _OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}

void threads_use(int n)
{
#ifdef _OPENMP
    omp_set_num_threads(n);
#else
    (void)n;
#endif
}

int threads_count(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}
