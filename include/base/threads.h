/*
 * threads.h: how many threads the process works with: OpenMP's default team
 * size, which -j sets; reading, building and rendering all follow it. In
 * builds without OpenMP there is one.
 */
#ifndef RAYTRACE_THREADS_H
#define RAYTRACE_THREADS_H

/* Returns the processors the system offers this process. */
int threads_processors(void);

/* Makes the process work with n threads (n >= 1) from now on. */
void threads_use(int n);

/* Returns the threads the process works with. */
int threads_count(void);

#endif
