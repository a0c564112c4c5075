/*
 * path.h: what a file name means on this system. POSIX systems separate
 * folders with '/' and start an absolute path with it; Windows takes '/'
 * and '\' alike, and an absolute path starts with a drive ("C:\"), two
 * separators (a server's share) or one (the current drive's root). Every
 * name is UTF-8 on both. The readers resolve the files a scene names
 * (textures, meshes) through path_beside(), so that one rule holds for all
 * of them; path_posix.c and path_win32.c say the rules.
 */
#ifndef RAYTRACE_PATH_H
#define RAYTRACE_PATH_H

#include <stddef.h>

/* Says whether c separates folders in a path. */
int path_is_separator(char c);

/* Returns the length of path's root, which names the same folder whatever
 * the current one: "/" on POSIX systems; "C:\" or "\\server\share\" on
 * Windows; 0 when path is relative. */
size_t path_root_length(const char *path);

/* Says whether path (len bytes) names a file whatever the current folder. */
int path_is_absolute(const char *path, size_t len);

/* Returns the length of path's folder part: up to and including its last
 * separator (or, on Windows, a drive's colon), 0 when it has none. */
size_t path_dir_length(const char *path);

/* Returns, newly allocated, the path of name (len bytes) in the folder
 * `folder` ("" for none) of file's folder, or name as it is when it is
 * absolute; NULL when memory runs out. */
char *path_beside(const char *file, const char *folder, const char *name, size_t len);

/* Returns, newly allocated, the path that names file `to` from folder
 * `from`, both absolute as path_absolute() gives them ("../models/a.obj",
 * with '/' between folders); `to` as it is when no relative path leads
 * there (another drive); NULL when memory runs out. */
char *path_relative(const char *from, const char *to);

/* Returns, newly allocated, the absolute path of the existing file path,
 * links resolved where the system has them; NULL with errno set when it
 * cannot. */
char *path_absolute(const char *path);

#endif
