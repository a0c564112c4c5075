/* file_posix.c: files on POSIX systems (see file.h). */
#define _POSIX_C_SOURCE 200809L /* fileno */

#include "base/file.h"

#include <errno.h>
#include <sys/stat.h>
#include <unistd.h>

FILE *file_open(const char *path, const char *mode)
{
    return fopen(path, mode);
}

int file_delete(const char *path)
{
    return unlink(path) == 0 || errno == ENOENT ? 0 : errno;
}

int file_same(const char *a, const char *b)
{
    struct stat sa, sb;

    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

void file_binary(FILE *f)
{
    (void)f; /* POSIX streams never translate */
}

int file_is_terminal(FILE *f)
{
    return isatty(fileno(f));
}
