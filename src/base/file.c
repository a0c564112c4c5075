/* file.c: reading whole files (see file.h); the calls that differ between
 * systems are in file_posix.c and file_win32.c. */
#define _XOPEN_SOURCE 700 /* POSIX.1-2008: fileno, fstat */

#include "base/file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char *file_display_name(const char *path)
{
    return strcmp(path, "-") == 0 ? "<stdin>" : path;
}

/* Reads f to its end into a growing buffer, with read() on its descriptor
 * (f is not read through: a read interrupted by a signal, EINTR, is
 * retried); returns 0, 1 when it holds more than FILE_MAX bytes, or -1 with
 * errno. */
static int file_slurp(FILE *f, char **data, size_t *len)
{
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);

    if (!buf)
        return -1;
    for (;;) {
        ssize_t got;
        if (n > FILE_MAX) {
            free(buf);
            return 1;
        }
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
        got = read(fileno(f), buf + n, cap - 1 - n);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            int saved = errno;
            free(buf);
            errno = saved ? saved : EIO;
            return -1;
        }
        if (got == 0)
            break;
        n += (size_t)got;
    }
    buf[n] = '\0';
    *data = buf;
    *len = n;
    return 0;
}

#define FILE_TOO_LARGE "larger than 1 GiB, the most any input may be"
#define FILE_IS_DIR "it is a directory, not a file"

/* Says why the open file f cannot be read as a whole (a directory, a
 * device), or NULL when it can: a regular file, a pipe or a terminal
 * standing for standard input. */
static const char *file_unreadable(FILE *f, int is_stdin)
{
    struct stat st;

    if (fstat(fileno(f), &st) != 0)
        return NULL; /* reading will say what is wrong */
    if (S_ISDIR(st.st_mode))
        return FILE_IS_DIR;
    if (S_ISREG(st.st_mode) && st.st_size > FILE_MAX)
        return FILE_TOO_LARGE;
    if (S_ISREG(st.st_mode) || S_ISFIFO(st.st_mode) || is_stdin)
        return NULL;
    return "not a regular file (a device or a socket): give a file or a pipe";
}

int file_read_all(const char *path, char **data, size_t *len, Error *err)
{
    const char *name = file_display_name(path);
    int is_stdin = strcmp(path, "-") == 0, rc;
    FILE *f = is_stdin ? stdin : file_open(path, "rb");
    const char *why;

    if (is_stdin)
        file_binary(stdin);

    if (!f) {
        if (errno == EISDIR) /* where a folder cannot be opened (Windows) */
            error_set(err, name, "cannot read: %s", FILE_IS_DIR);
        else
            error_set(err, name, "cannot open: %s", strerror(errno));
        return -1;
    }
    why = file_unreadable(f, is_stdin);
    if (why) {
        error_set(err, name, "cannot read: %s", why);
        if (!is_stdin)
            fclose(f);
        return -1;
    }
    errno = 0;
    rc = file_slurp(f, data, len);
    if (rc > 0)
        error_set(err, name, "cannot read: %s", FILE_TOO_LARGE);
    else if (rc < 0)
        error_set(err, name, "cannot read: %s", strerror(errno));
    if (!is_stdin)
        fclose(f);
    return rc == 0 ? 0 : -1;
}
