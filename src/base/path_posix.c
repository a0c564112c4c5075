/* path_posix.c: paths on POSIX systems (see path.h). */
#define _XOPEN_SOURCE 700 /* realpath */

#include "base/path.h"

#include <stdlib.h>
#include <string.h>

int path_is_separator(char c)
{
    return c == '/';
}

size_t path_root_length(const char *path)
{
    return path[0] == '/' ? 1 : 0;
}

int path_is_absolute(const char *path, size_t len)
{
    return len > 0 && path[0] == '/';
}

size_t path_dir_length(const char *path)
{
    const char *slash = strrchr(path, '/');

    return slash ? (size_t)(slash - path) + 1 : 0;
}

char *path_absolute(const char *path)
{
    return realpath(path, NULL);
}
