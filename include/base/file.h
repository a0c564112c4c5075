/*
 * file.h: opening files by their UTF-8 names, reading a whole input file
 * into memory, and what the system says of a file (the same file as
 * another, a terminal). file_posix.c and file_win32.c hold the calls that
 * differ between systems.
 */
#ifndef RAYTRACE_FILE_H
#define RAYTRACE_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"

/* The largest input file read, in bytes (1 GiB): a larger one is refused
 * rather than read into memory. */
#define FILE_MAX (1 << 30)

/* Reads all of path ("-" reads standard input) into a new NUL-terminated
 * buffer stored in *data, its length (without the NUL) in *len; returns 0,
 * or -1 with *err saying why. The caller frees *data. */
int file_read_all(const char *path, char **data, size_t *len, Error *err);

/* Returns the name to use for path in messages: "<stdin>" for "-". */
const char *file_display_name(const char *path);

/* Opens path (UTF-8) as fopen() does with mode; NULL with errno set when
 * it cannot. */
FILE *file_open(const char *path, const char *mode);

/* Deletes file path; returns 0 when it is gone (or never was), else the
 * errno value that says why it stays. */
int file_delete(const char *path);

/* Says whether paths a and b name the same existing file (through links,
 * or under two names). */
int file_same(const char *a, const char *b);

/* Makes stream f (standard input or output) carry bytes unchanged: no
 * line ends translated where the system would (Windows). */
void file_binary(FILE *f);

/* Says whether stream f is a terminal (a console on Windows), where a
 * progress bar may be drawn and binary images must not go. */
int file_is_terminal(FILE *f);

#endif
