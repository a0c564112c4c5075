/* path_win32.c: paths on Windows (see path.h). */
#include "base/path.h"

#include <errno.h>
#include <stdlib.h>
#include <windows.h>

#include "wide.h"

int path_is_separator(char c)
{
    return c == '/' || c == '\\';
}

/* "C:\" (or "C:" alone), "\\server\share\", or one separator: the
 * current drive's root. */
size_t path_root_length(const char *path)
{
    size_t n;

    if (path[0] && path[1] == ':')
        return path_is_separator(path[2]) ? 3 : 2;
    if (!path_is_separator(path[0]))
        return 0;
    if (!path_is_separator(path[1]))
        return 1;
    /* A server and its share, each followed by its separator. */
    n = 2;
    for (int part = 0; part < 2 && path[n]; part++) {
        while (path[n] && !path_is_separator(path[n]))
            n++;
        if (path[n])
            n++;
    }
    return n;
}

/* A drive's letter and colon ("C:") start an absolute path, and so does a
 * drive's relative one ("C:name", the drive's current folder), which no
 * scene's folder may be put before. */
int path_is_absolute(const char *path, size_t len)
{
    if (len >= 1 && path_is_separator(path[0]))
        return 1;
    return len >= 2 && path[1] == ':' &&
           ((path[0] >= 'A' && path[0] <= 'Z') || (path[0] >= 'a' && path[0] <= 'z'));
}

size_t path_dir_length(const char *path)
{
    size_t n = 0;

    for (size_t i = 0; path[i]; i++)
        if (path_is_separator(path[i]) || (i == 1 && path[i] == ':'))
            n = i + 1;
    return n;
}

char *path_absolute(const char *path)
{
    wchar_t *w = wide_from_utf8(path), *full;
    DWORD n, attrs;
    char *s;

    if (!w)
        return NULL;
    attrs = GetFileAttributesW(w);
    n = attrs == INVALID_FILE_ATTRIBUTES ? 0 : GetFullPathNameW(w, 0, NULL, NULL);
    if (n == 0) {
        wide_errno(GetLastError());
        free(w);
        return NULL;
    }
    full = malloc(n * sizeof *full);
    if (!full || GetFullPathNameW(w, n, full, NULL) == 0) {
        errno = full ? EIO : ENOMEM;
        free(full);
        free(w);
        return NULL;
    }
    s = wide_to_utf8(full);
    free(full);
    free(w);
    return s;
}
