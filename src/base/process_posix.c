/* process_posix.c: the process on POSIX systems (see process.h). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "base/process.h"

#include <sys/resource.h>
#include <time.h>

void process_init(int *argc, char ***argv)
{
    (void)argc; /* arguments are the bytes the user typed */
    (void)argv;
}

double process_seconds(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

double process_peak_memory(void)
{
    struct rusage ru;

    if (getrusage(RUSAGE_SELF, &ru) != 0)
        return 0;
#ifdef __APPLE__
    return (double)ru.ru_maxrss; /* bytes on macOS */
#else
    return (double)ru.ru_maxrss * 1024; /* kilobytes on Linux and the BSDs */
#endif
}
