/*
 * outfile.h: writing an output file all at once or not at all.
 *
 * On Linux a regular output file is written to a new file without a name
 * (O_TMPFILE) in its directory, which is given the output's name (linkat,
 * and rename over an existing file) only when everything was written and
 * synced, then the directory synced: a failed, interrupted or killed
 * render leaves an existing file untouched and nothing beside it. Where
 * unnamed files are not possible (other POSIX systems, some file
 * systems), a named temporary file beside the output takes their place;
 * on Windows too, where it is flushed to the disk and moved over the
 * output with MoveFileEx's replace. A temporary file is removed on
 * failure, and by the command on an interrupt and any exit it did not
 * choose (base/interrupt.h); a SIGKILL or a killed Windows process leaves
 * it, and on Linux a SIGKILL in the microseconds between an unnamed file's
 * link to a temporary name and its rename over an existing output leaves
 * the complete file under that name. Such names carry the machine and the
 * process (outfile_temp_name()), and opening the same output again
 * removes those whose process no longer runs. When even its removal
 * fails, the message names it. "-" means standard output, written in
 * binary mode, and an existing file that is
 * not a regular file (a device such as /dev/null or NUL, a FIFO) is
 * written in place, since it cannot be replaced. outfile_posix.c and
 * outfile_win32.c hold the two ways, outfile_shared.c what they share.
 */
#ifndef RAYTRACE_OUTFILE_H
#define RAYTRACE_OUTFILE_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"

enum { OUTFILE_PATH_MAX = 4096 }; /* longest path handled, bytes */

typedef struct {
    FILE *fp;                    /* where to write; NULL when not open */
    char path[OUTFILE_PATH_MAX]; /* the file to produce, as named by the user */
    char dest[OUTFILE_PATH_MAX]; /* what the rename replaces (links resolved) */
    char temp[OUTFILE_PATH_MAX]; /* temporary file, "" when writing in place
                                    or to an unnamed file */
    char dir[OUTFILE_PATH_MAX];  /* the destination's directory */
    int unnamed;                 /* 1: fp is an unnamed file (O_TMPFILE)
                                    that commit links to dest */
    int fd;                      /* fp's descriptor when it is a new file,
                                    else -1 (always -1 on Windows) */
    int is_stdout;               /* 1 when writing to standard output */
} OutFile;

/* Says whether path ("-": standard output) could be opened for writing
 * (it is no directory, and its directory exists and may be written to),
 * creating nothing: a check to make before a long render; returns 0, or -1
 * with *err saying why. */
int outfile_check(const char *path, Error *err);

/* Opens path ("-": standard output) for writing as described above; returns
 * 0, or -1 with *err saying why and nothing created. */
int outfile_open(OutFile *out, const char *path, Error *err);

/* Finishes the file: flushes and syncs it, closes it and renames the
 * temporary file onto the destination. Returns 0, or -1 with *err filled
 * and the temporary file removed (or, if that fails too, named in *err's
 * message). */
int outfile_commit(OutFile *out, Error *err);

/* Writes into name (size bytes) the temporary name that process pid
 * takes at attempt try beside the output dest: ".BASE.HOST-PID-TRY" in
 * dest's directory (BASE dest's name, HOST a hash of this machine's name
 * in 8 hex digits). outfile_open() removes those of processes of this
 * machine that no longer run. Returns 0, or -1 when it does not fit. */
int outfile_temp_name(const char *dest, unsigned long pid, unsigned try, char *name,
                      size_t size);

/* Abandons the file: closes it and removes the temporary file, leaving any
 * existing output as it was. Returns 0, or -1 when the temporary file
 * could not be removed: then its name and why are added to *err's message
 * (err may be NULL). */
int outfile_abort(OutFile *out, Error *err);

#endif
