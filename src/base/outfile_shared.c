/* outfile_shared.c: what all-or-nothing output files do alike on every system
 * (see outfile.h; the systems' own calls are in outfile_posix.c and
 * outfile_win32.c). */
#include "outfile_sys.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "base/file.h"
#include "base/path.h"

/* The most bytes of the output's name a temporary name repeats. */
#define OUTFILE_BASE_KEPT 200

unsigned long outfile_hash(const char *s)
{
    unsigned long h = 2166136261u;

    for (const unsigned char *c = (const unsigned char *)s; *c; c++)
        h = ((h ^ *c) * 16777619u) & 0xffffffffu;
    return h;
}

int outfile_temp_format(const char *dest, unsigned long host, unsigned long pid, unsigned try,
                        char *name, size_t size)
{
    size_t dir = path_dir_length(dest);

    return snprintf(name, size, "%.*s.%.*s.%08lx-%lu-%u", (int)dir, dest, OUTFILE_BASE_KEPT,
                    dest + dir, host, pid, try) >= (int)size
               ? -1
               : 0;
}

int outfile_start(OutFile *out, const char *path, Error *err)
{
    memset(out, 0, sizeof *out);
    out->fd = -1;
    if (strlen(path) >= OUTFILE_PATH_MAX - 32) {
        error_set(err, path, "output path is too long");
        return -1;
    }
    strcpy(out->path, path);
    if (strcmp(path, "-") != 0)
        return 0;
    out->fp = stdout;
    out->is_stdout = 1;
    return 1;
}

size_t outfile_folder(const char *path, char *dir)
{
    size_t name = path_dir_length(path), n = name;

    if (n == 0) {
        strcpy(dir, ".");
        return 0;
    }
    if (n > path_root_length(path) && path_is_separator(path[n - 1]))
        n--;
    memcpy(dir, path, n);
    dir[n] = '\0';
    return name;
}

/* Reads the decimal number at *s (at least one digit) into *value and moves
 * *s past it; returns 0, or -1 when there is none or it overflows. */
static int outfile_parse_number(const char **s, unsigned long *value)
{
    if (**s < '0' || **s > '9')
        return -1;
    *value = 0;
    for (; **s >= '0' && **s <= '9'; (*s)++) {
        if (*value > (ULONG_MAX - 9) / 10)
            return -1;
        *value = *value * 10 + (unsigned long)(**s - '0');
    }
    return 0;
}

int outfile_temp_of(const char *entry, const char *base, unsigned long host, unsigned long *pid)
{
    size_t n = strlen(base) < OUTFILE_BASE_KEPT ? strlen(base) : OUTFILE_BASE_KEPT;
    unsigned long try;
    char hex[9];

    if (entry[0] != '.' || strncmp(entry + 1, base, n) != 0 || entry[n + 1] != '.')
        return 0;
    entry += n + 2;
    snprintf(hex, sizeof hex, "%08lx", host);
    if (strncmp(entry, hex, 8) != 0 || entry[8] != '-')
        return 0;
    entry += 9;
    return outfile_parse_number(&entry, pid) == 0 && *pid != 0 && *entry++ == '-' &&
           outfile_parse_number(&entry, &try) == 0 && *entry == '\0';
}

int outfile_remove_temp(OutFile *out, Error *err)
{
    int saved = out->temp[0] ? file_delete(out->temp) : 0;

    if (saved != 0 && err) {
        size_t n = strlen(err->message);
        snprintf(err->message + n, sizeof err->message - n,
                 "; and the temporary file '%s' could not be removed (%s): delete it", out->temp,
                 strerror(saved));
    }
    out->temp[0] = '\0';
    return saved != 0 ? -1 : 0;
}

int outfile_failed(OutFile *out, int saved, Error *err)
{
    error_set(err, out->is_stdout ? "<stdout>" : out->path, "cannot write the image: %s",
              strerror(saved ? saved : EIO));
    outfile_remove_temp(out, err);
    return -1;
}

int outfile_abort(OutFile *out, Error *err)
{
    /* An unnamed file (Linux's) vanishes with its descriptor. */
    if (out->fp && !out->is_stdout)
        fclose(out->fp);
    out->fp = NULL;
    return outfile_remove_temp(out, err);
}
