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

/* Returns the FNV-1a hash, 32 bits, of the string s (each system's
 * outfile_temp_name() hashes the machine's name with it). */
unsigned long outfile_hash(const char *s);

/* outfile_temp_name() for the machine whose name's outfile_hash() is
 * host. */
int outfile_temp_format(const char *dest, unsigned long host, unsigned long pid, unsigned try,
                        char *name, size_t size);

/* Says whether entry, a name in an output's directory, is a temporary
 * name outfile_temp_format() gives beside the output named base on the
 * machine host; then stores its process in *pid (never 0). */
int outfile_temp_of(const char *entry, const char *base, unsigned long host, unsigned long *pid);

/* Starts *out for path, as both systems' outfile_open() do: cleared, the
 * name kept, standard output for "-". Returns 1 for "-", 0 to go on, -1
 * (with err) when path is too long. */
int outfile_start(OutFile *out, const char *path, Error *err);

/* Copies into dir (OUTFILE_PATH_MAX bytes) the folder path lies in, as
 * messages name it: path's folder part without its last separator (a
 * root keeps its own), or "." when path has none; returns where path's
 * own name starts (path_dir_length()). path is shorter than dir. */
size_t outfile_folder(const char *path, char *dir);

/* Says in *err that writing out failed (errno value saved, 0: EIO) and
 * removes its temporary file; returns -1. */
int outfile_failed(OutFile *out, int saved, Error *err);

#endif
