/*
 * file.h: reading a whole input file into memory.
 */
#ifndef RAYTRACE_FILE_H
#define RAYTRACE_FILE_H

#include <stddef.h>

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

#endif
