/*
 * outfile_sys.h: what outfile_shared.c, the platform-neutral part of
 * outfile.h, gives outfile_posix.c and outfile_win32.c (it calls only
 * down, to file.h).
 */
#ifndef RAYTRACE_OUTFILE_SYS_H
#define RAYTRACE_OUTFILE_SYS_H

#include "base/outfile.h"

/* Removes out's temporary file, if any; when that fails too, adds to err's
 * message (err may be NULL) the file's name and why, so that the user can
 * delete it. Returns 0, or -1 when the file stays. */
int outfile_remove_temp(OutFile *out, Error *err);

/* Says in *err that writing out failed (errno value saved, 0: EIO) and
 * removes its temporary file; returns -1. */
int outfile_failed(OutFile *out, int saved, Error *err);

#endif
