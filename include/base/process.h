/*
 * process.h: what the system tells a command of itself: its arguments in
 * UTF-8, a clock, its peak memory. process_posix.c and process_win32.c say
 * how each system is asked.
 */
#ifndef RAYTRACE_PROCESS_H
#define RAYTRACE_PROCESS_H

/* Readies the process, first thing in main(): on Windows, replaces *argv
 * with the command line's arguments in UTF-8 (whatever the code page) and
 * lets the console show UTF-8 and the progress bar's escapes; elsewhere
 * changes nothing. */
void process_init(int *argc, char ***argv);

/* Returns the seconds since some fixed time, from a clock that never goes
 * back. */
double process_seconds(void);

/* Returns the most memory the process has held at once (its peak resident
 * set, Windows's peak working set), in bytes; 0 when the system cannot
 * say. */
double process_peak_memory(void);

#endif
