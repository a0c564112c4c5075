/* outfile.c: all-or-nothing output files (see outfile.h). */
#define _XOPEN_SOURCE 700 /* POSIX.1-2008 with XSI: mkstemp, fchmod, realpath */

#include "base/outfile.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Splits path into its directory (or "." if none) in dir and its last
 * component in base. */
static void outfile_split(const char *path, char *dir, const char **base)
{
    const char *slash = strrchr(path, '/');

    if (!slash) {
        strcpy(dir, ".");
        *base = path;
    } else if (slash == path) {
        strcpy(dir, "/");
        *base = slash + 1;
    } else {
        memcpy(dir, path, (size_t)(slash - path));
        dir[slash - path] = '\0';
        *base = slash + 1;
    }
}

/* Returns the permissions a new output file gets: those of the file it
 * replaces, or 0666 less the umask. */
static mode_t outfile_mode(const struct stat *existing, int exists)
{
    mode_t mask;

    if (exists)
        return existing->st_mode & 07777;
    mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

int outfile_open(OutFile *out, const char *path, Error *err)
{
    char dir[OUTFILE_PATH_MAX];
    const char *base;
    struct stat st;
    int exists, fd;

    memset(out, 0, sizeof *out);
    if (strlen(path) >= OUTFILE_PATH_MAX - 32) {
        error_set(err, path, "output path is too long");
        return -1;
    }
    strcpy(out->path, path);
    if (strcmp(path, "-") == 0) {
        out->fp = stdout;
        out->is_stdout = 1;
        return 0;
    }
    exists = stat(path, &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) {
        error_set(err, path, "cannot write the image: it is a directory");
        return -1;
    }
    if (exists && !S_ISREG(st.st_mode)) {
        out->fp = fopen(path, "wb");
        if (!out->fp) {
            error_set(err, path, "cannot open for writing: %s", strerror(errno));
            return -1;
        }
        return 0;
    }
    /* Write through a symbolic link rather than replace it. */
    if (!exists || !realpath(path, out->dest))
        strcpy(out->dest, path);
    outfile_split(out->dest, dir, &base);
    if (snprintf(out->temp, sizeof out->temp, "%s/.%.200s.XXXXXX", dir, base) >=
        (int)sizeof out->temp) {
        error_set(err, path, "output path is too long");
        out->temp[0] = '\0';
        return -1;
    }
    fd = mkstemp(out->temp);
    if (fd < 0) {
        error_set(err, path, "cannot create a file in directory '%s': %s", dir, strerror(errno));
        out->temp[0] = '\0';
        return -1;
    }
    if (fchmod(fd, outfile_mode(&st, exists)) != 0 || !(out->fp = fdopen(fd, "wb"))) {
        error_set(err, path, "cannot write in directory '%s': %s", dir, strerror(errno));
        close(fd);
        unlink(out->temp);
        out->temp[0] = '\0';
        return -1;
    }
    return 0;
}

int outfile_commit(OutFile *out, Error *err)
{
    int failed = fflush(out->fp) != 0 || ferror(out->fp);
    int saved = errno;

    /* Make the data durable before the rename makes it visible. */
    if (!failed && out->temp[0] && fsync(fileno(out->fp)) != 0) {
        failed = 1;
        saved = errno;
    }
    if (!out->is_stdout) {
        if (fclose(out->fp) != 0 && !failed) {
            failed = 1;
            saved = errno;
        }
    }
    out->fp = NULL;
    if (!failed && out->temp[0] && rename(out->temp, out->dest) != 0) {
        failed = 1;
        saved = errno;
    }
    if (failed) {
        error_set(err, out->is_stdout ? "<stdout>" : out->path, "cannot write the image: %s",
                  strerror(saved ? saved : EIO));
        if (out->temp[0])
            unlink(out->temp);
        out->temp[0] = '\0';
        return -1;
    }
    out->temp[0] = '\0';
    return 0;
}

void outfile_abort(OutFile *out)
{
    if (out->fp && !out->is_stdout)
        fclose(out->fp);
    out->fp = NULL;
    if (out->temp[0])
        unlink(out->temp);
    out->temp[0] = '\0';
}
