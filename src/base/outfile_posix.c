/* outfile_posix.c: all-or-nothing output files on POSIX systems (see
 * outfile.h). */
/* POSIX.1-2008 with XSI (fchmod, realpath) and, on Linux, its
 * unnamed files (O_TMPFILE, named through /proc) and glibc's fopencookie;
 * RAYTRACE_STRICT_POSIX leaves Linux's out, as a macOS or BSD build has
 * to (CI builds so). */
#if defined(__linux__) && !defined(RAYTRACE_STRICT_POSIX)
#define _GNU_SOURCE
#define OUTFILE_LINUX 1
#else
#define _XOPEN_SOURCE 700
#define OUTFILE_LINUX 0
#endif

#include "outfile_sys.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Returns the hash of this machine's name that temporary names carry, so
 * that a sweep judges only its own machine's. */
static unsigned long outfile_host(void)
{
    char host[256] = "";

    if (gethostname(host, sizeof host - 1) != 0)
        host[0] = '\0';
    host[sizeof host - 1] = '\0';
    return outfile_hash(host);
}

int outfile_temp_name(const char *dest, unsigned long pid, unsigned try, char *name,
                      size_t size)
{
    return outfile_temp_format(dest, outfile_host(), pid, try, name, size);
}

/* Says whether entry, beside the output named base, is a temporary name
 * a process of this machine (whose outfile_host() is host) left when it
 * was killed: one that no longer runs. */
static int outfile_stale(const char *entry, const char *base, unsigned long host)
{
    unsigned long pid;

    if (!outfile_temp_of(entry, base, host, &pid) || pid > (unsigned long)INT_MAX)
        return 0;
    /* A process of the same number may be another program now: kept. */
    return kill((pid_t)pid, 0) != 0 && errno == ESRCH;
}

/* Removes, from directory dir, the temporary names beside output base that
 * processes of this machine left when they were killed (outfile_stale()).
 * Best effort: what cannot be read or removed stays. */
static void outfile_sweep(const char *dir, const char *base)
{
    unsigned long host = outfile_host();
    DIR *d = opendir(dir);
    struct dirent *e;

    if (!d)
        return;
    while ((e = readdir(d)) != NULL) {
        char name[OUTFILE_PATH_MAX];
        if (outfile_stale(e->d_name, base, host) &&
            snprintf(name, sizeof name, "%s/%s", dir, e->d_name) < (int)sizeof name)
            unlink(name);
    }
    closedir(d);
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

/* Writes all n bytes at buf to descriptor *cookie, on after short writes
 * and after writes a signal interrupted (EINTR); returns n, or -1 with
 * errno set (the stdio stream then reports the error). */
static ssize_t outfile_write_all(void *cookie, const char *buf, size_t n)
{
    int fd = *(int *)cookie;
    size_t done = 0;

    while (done < n) {
        ssize_t w = write(fd, buf + done, n - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            if (w == 0)
                errno = EIO;
            return -1;
        }
        done += (size_t)w;
    }
    return (ssize_t)n;
}

/* Closes the descriptor behind a stream of outfile_stream(). */
static int outfile_close_fd(void *cookie)
{
    int fd = *(int *)cookie;

    free(cookie);
    return close(fd);
}

/* Returns a stream writing to descriptor fd through outfile_write_all()
 * (glibc's fopencookie; elsewhere fdopen, whose writes stdio makes), or
 * NULL with fd left open. */
static FILE *outfile_stream(int fd)
{
#if OUTFILE_LINUX && defined(__GLIBC__)
    cookie_io_functions_t io = {NULL, outfile_write_all, NULL, outfile_close_fd};
    int *cookie = malloc(sizeof *cookie);
    FILE *f;

    if (!cookie)
        return NULL;
    *cookie = fd;
    f = fopencookie(cookie, "wb", io);
    if (!f)
        free(cookie);
    return f;
#else
    (void)outfile_write_all;
    (void)outfile_close_fd;
    return fdopen(fd, "wb");
#endif
}

/* Opens an unnamed file in directory dir with mode (Linux's O_TMPFILE):
 * nothing is in the directory until outfile_commit() links it there, so a
 * process killed before then leaves nothing. Returns its descriptor, or -1
 * (where the system or the file system cannot). */
static int outfile_unnamed(const char *dir, mode_t mode)
{
#if OUTFILE_LINUX && defined(O_TMPFILE)
    int fd;

    /* Naming it later goes through /proc/self/fd. */
    if (access("/proc/self/fd", F_OK) != 0)
        return -1;
    fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);

    /* O_TMPFILE ignores the umask's effect on the mode we ask for exactly. */
    if (fd >= 0 && fchmod(fd, mode) != 0) {
        close(fd);
        return -1;
    }
    return fd;
#else
    (void)dir;
    (void)mode;
    return -1;
#endif
}

/* Creates a new file under the first free name outfile_temp_name() gives
 * and writes that name in out->temp (left empty until then); returns its
 * descriptor, or -1 with errno set. */
static int outfile_create_temp(OutFile *out)
{
    char name[sizeof out->temp];

    for (unsigned try = 0; try < 100; try++) {
        int fd;
        if (outfile_temp_name(out->dest, (unsigned long)getpid(), try, name, sizeof name) != 0) {
            errno = ENAMETOOLONG;
            return -1;
        }
        fd = open(name, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd >= 0) {
            strcpy(out->temp, name);
            return fd;
        }
        if (errno != EEXIST)
            return -1;
    }
    errno = EEXIST;
    return -1;
}

int outfile_open(OutFile *out, const char *path, Error *err)
{
    char dir[OUTFILE_PATH_MAX];
    const char *base;
    struct stat st;
    int exists, fd, too_long, rc = outfile_start(out, path, err);

    if (rc != 0)
        return rc < 0 ? -1 : 0;
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
    base = out->dest + outfile_folder(out->dest, dir);
    /* The longest name a try could take must fit; none is made yet. */
    too_long = outfile_temp_name(out->dest, (unsigned long)INT_MAX, UINT_MAX, out->temp,
                                 sizeof out->temp) != 0;
    out->temp[0] = '\0';
    if (too_long) {
        error_set(err, path, "output path is too long");
        return -1;
    }
    strcpy(out->dir, dir);
    outfile_sweep(dir, base);
    fd = outfile_unnamed(dir, outfile_mode(&st, exists));
    if (fd >= 0 && (out->fp = outfile_stream(fd)) != NULL) {
        out->fd = fd;
        out->unnamed = 1;
        return 0;
    }
    if (fd >= 0)
        close(fd);
    /* No O_TMPFILE here: a named temporary file beside the output. */
    fd = outfile_create_temp(out);
    if (fd < 0) {
        error_set(err, path, "cannot create a file in directory '%s': %s", dir, strerror(errno));
        return -1;
    }
    if (fchmod(fd, outfile_mode(&st, exists)) != 0 || !(out->fp = outfile_stream(fd))) {
        error_set(err, path, "cannot write in directory '%s': %s", dir, strerror(errno));
        close(fd);
        outfile_remove_temp(out, err);
        return -1;
    }
    out->fd = fd;
    return 0;
}

int outfile_check(const char *path, Error *err)
{
    char dest[OUTFILE_PATH_MAX], dir[OUTFILE_PATH_MAX];
    struct stat st;
    int exists, saved;

    if (strcmp(path, "-") == 0)
        return 0;
    if (strlen(path) >= OUTFILE_PATH_MAX - 32) {
        error_set(err, path, "output path is too long");
        return -1;
    }
    exists = stat(path, &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) {
        error_set(err, path, "cannot write the image: it is a directory");
        return -1;
    }
    if (exists && !S_ISREG(st.st_mode))
        return 0; /* a device or a FIFO, written in place */
    if (!exists || !realpath(path, dest))
        strcpy(dest, path);
    outfile_folder(dest, dir);
    if (stat(dir, &st) != 0)
        saved = errno;
    else if (!S_ISDIR(st.st_mode))
        saved = ENOTDIR;
    else if (access(dir, W_OK | X_OK) != 0)
        saved = errno;
    else
        return 0;
    error_set(err, path, "cannot create a file in directory '%s': %s", dir, strerror(saved));
    return -1;
}

/* Syncs directory dir, so that a name just made in it survives a crash
 * (where the file system allows: errors are not the caller's concern). */
static void outfile_sync_dir(const char *dir)
{
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);

    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

/* Gives out's unnamed file its name: linked straight to the destination
 * when there is none yet, else linked to a temporary name beside it and
 * renamed over it (rename replaces at once; linkat does not). Returns 0, or
 * -1 with errno set and no name left behind. A SIGKILL between the link and
 * the rename leaves the complete file under its temporary name, which the
 * next render to the same output removes (outfile_sweep()). */
static int outfile_link(OutFile *out)
{
    char proc[64];

    snprintf(proc, sizeof proc, "/proc/self/fd/%d", out->fd);
    if (linkat(AT_FDCWD, proc, AT_FDCWD, out->dest, AT_SYMLINK_FOLLOW) == 0)
        return 0;
    if (errno != EEXIST)
        return -1;
    for (unsigned try = 0; try < 100; try++) {
        char name[sizeof out->temp];
        int saved;
        if (outfile_temp_name(out->dest, (unsigned long)getpid(), try, name, sizeof name) != 0) {
            errno = ENAMETOOLONG;
            return -1;
        }
        if (linkat(AT_FDCWD, proc, AT_FDCWD, name, AT_SYMLINK_FOLLOW) != 0) {
            if (errno == EEXIST)
                continue;
            return -1;
        }
        if (rename(name, out->dest) == 0)
            return 0;
        /* The commit's failure removes the name, or says it stays. */
        saved = errno;
        strcpy(out->temp, name);
        errno = saved;
        return -1;
    }
    errno = EEXIST;
    return -1;
}

int outfile_commit(OutFile *out, Error *err)
{
    int failed = fflush(out->fp) != 0 || ferror(out->fp);
    int saved = errno;

    /* Make the data durable before the rename makes it visible. */
    while (!failed && (out->temp[0] || out->unnamed) && fsync(out->fd) != 0) {
        if (errno == EINTR)
            continue;
        failed = 1;
        saved = errno;
    }
    if (!out->is_stdout && !out->unnamed) {
        if (fclose(out->fp) != 0 && !failed) {
            failed = 1;
            saved = errno;
        }
        out->fp = NULL;
    }
    if (!failed && out->unnamed && outfile_link(out) != 0) {
        failed = 1;
        saved = errno;
    }
    if (!out->is_stdout && out->fp)
        fclose(out->fp);
    out->fp = NULL;
    if (!failed && out->temp[0] && rename(out->temp, out->dest) != 0) {
        failed = 1;
        saved = errno;
    }
    /* Make the new name durable too. */
    if (!failed && (out->temp[0] || out->unnamed))
        outfile_sync_dir(out->dir);
    if (failed)
        return outfile_failed(out, saved, err);
    out->temp[0] = '\0';
    return 0;
}
