/* path.c: paths relative to a file's folder (see path.h). */
#include "base/path.h"

#include <stdlib.h>
#include <string.h>

char *path_beside(const char *file, const char *folder, const char *name, size_t len)
{
    int absolute = path_is_absolute(name, len);
    size_t dir = absolute ? 0 : path_dir_length(file);
    size_t k = absolute ? 0 : strlen(folder);
    char *path = malloc(dir + k + len + 1);

    if (!path)
        return NULL;
    memcpy(path, file, dir);
    memcpy(path + dir, folder, k);
    memcpy(path + dir + k, name, len);
    path[dir + k + len] = '\0';
    return path;
}

/* Returns the length of the component of path at i (up to a separator). */
static size_t path_component(const char *path, size_t i)
{
    size_t n = 0;

    while (path[i + n] && !path_is_separator(path[i + n]))
        n++;
    return n;
}

/* Moves i past the separators of path at i. */
static size_t path_skip(const char *path, size_t i)
{
    while (path[i] && path_is_separator(path[i]))
        i++;
    return i;
}

char *path_relative(const char *from, const char *to)
{
    size_t root = path_root_length(from), f, t, ups = 0, n, len;
    char *rel;

    if (root == 0 || root != path_root_length(to) || memcmp(from, to, root) != 0)
        return path_beside("", "", to, strlen(to));
    /* Past the components both share... */
    f = path_skip(from, root);
    t = path_skip(to, root);
    for (;;) {
        size_t fl = path_component(from, f), tl = path_component(to, t);
        if (fl == 0 || fl != tl || memcmp(from + f, to + t, fl) != 0 || !to[t + tl])
            break;
        f = path_skip(from, f + fl);
        t = path_skip(to, t + tl);
    }
    /* ...one "../" for each of from's that is left, then the rest of to. */
    for (size_t i = f; from[i]; i = path_skip(from, i + path_component(from, i)))
        ups++;
    len = strlen(to + t);
    rel = malloc(3 * ups + len + 1);
    if (!rel)
        return NULL;
    for (n = 0; n < 3 * ups; n += 3)
        memcpy(rel + n, "../", 3);
    /* '/' between folders, which every system reads. */
    for (size_t i = 0; i <= len; i++)
        rel[n + i] = path_is_separator(to[t + i]) ? '/' : to[t + i];
    return rel;
}
