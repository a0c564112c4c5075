/* file.c: reading whole files (see file.h). */
#include "file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *file_display_name(const char *path)
{
    return strcmp(path, "-") == 0 ? "<stdin>" : path;
}

/* Reads f to its end into a growing buffer; returns 0 or -1 with errno. */
static int file_slurp(FILE *f, char **data, size_t *len)
{
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);

    if (!buf)
        return -1;
    for (;;) {
        size_t got;
        if (n + 1 == cap) {
            char *grown = cap > (size_t)-1 / 2 ? NULL : realloc(buf, 2 * cap);
            if (!grown) {
                free(buf);
                errno = ENOMEM;
                return -1;
            }
            buf = grown;
            cap *= 2;
        }
        got = fread(buf + n, 1, cap - 1 - n, f);
        n += got;
        if (got == 0) {
            if (ferror(f)) {
                int saved = errno;
                free(buf);
                errno = saved ? saved : EIO;
                return -1;
            }
            break;
        }
    }
    buf[n] = '\0';
    *data = buf;
    *len = n;
    return 0;
}

int file_read_all(const char *path, char **data, size_t *len, Error *err)
{
    const char *name = file_display_name(path);
    int is_stdin = strcmp(path, "-") == 0;
    FILE *f = is_stdin ? stdin : fopen(path, "rb");

    if (!f) {
        error_set(err, name, "cannot open: %s", strerror(errno));
        return -1;
    }
    errno = 0;
    if (file_slurp(f, data, len) != 0) {
        error_set(err, name, "cannot read: %s", strerror(errno));
        if (!is_stdin)
            fclose(f);
        return -1;
    }
    if (!is_stdin)
        fclose(f);
    return 0;
}
