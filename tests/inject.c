/*
 * inject.c: a fault injector for tests/faults.sh, loaded with LD_PRELOAD
 * into raytrace (test-only: built by `make test` as build/inject.so).
 *
 * RAYTRACE_FAULT=CALL:N:FAULT makes the N-th call (counting from 1) of CALL
 * fail: CALL is write, read, fsync, rename, linkat, open, unlink or malloc
 * (malloc, calloc and realloc counted together); FAULT is an errno name
 * (ENOSPC, EIO, EINTR, ENOMEM, EACCES) or, for write and read, "short": the
 * call moves half its bytes (at least one), or "exit": the call ends the
 * process with exit(1), as the OpenMP runtime's fatal errors do ("libgomp:
 * Out of memory allocating ..."), or "kill": the call is not made and the
 * process sends itself SIGKILL, as a kill landing just before it would.
 * RAYTRACE_FAULT_COUNT=FILE
 * instead appends to FILE, at exit, how many times each CALL was made.
 * RAYTRACE_FAULT2 names a second fault, the same way.
 * RAYTRACE_NO_TMPFILE=1 makes every open() of an unnamed file (O_TMPFILE)
 * fail with EOPNOTSUPP, as on a file system without them.
 * Only the calls the program makes through the dynamic linker are seen:
 * raytrace's own reads and writes (base/file.c, base/outfile.c) are.
 */
#define _GNU_SOURCE

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

enum { CALL_WRITE, CALL_READ, CALL_FSYNC, CALL_RENAME, CALL_LINKAT, CALL_OPEN, CALL_UNLINK,
       CALL_MALLOC, CALLS };
static const char *const inject_names[CALLS] = {"write",  "read", "fsync",  "rename",
                                                "linkat", "open", "unlink", "malloc"};
static unsigned long inject_counts[CALLS];
/* The faults to inject: the call to fail (-1: none), its number, the
 * errno it fails with (0: a short move, -1: exit(1), -2: SIGKILL). */
static struct {
    int call;
    unsigned long at;
    int err;
} inject_faults[2] = {{-1, 0, 0}, {-1, 0, 0}};
static int inject_errno; /* the errno of the fault that hit */
static int inject_ready;

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);

/* Reads fault k from the environment variable var, "CALL:N:FAULT". */
static void inject_parse(int k, const char *var)
{
    const char *spec = getenv(var);
    char name[16], fault[16];
    static const struct {
        const char *name;
        int value;
    } errnos[] = {{"ENOSPC", ENOSPC}, {"EIO", EIO},       {"EINTR", EINTR},
                  {"ENOMEM", ENOMEM}, {"EACCES", EACCES}, {"short", 0},
                  {"exit", -1},       {"kill", -2}};

    if (!spec || sscanf(spec, "%15[a-z]:%lu:%15[A-Za-z]", name, &inject_faults[k].at, fault) != 3)
        return;
    for (int c = 0; c < CALLS; c++)
        if (strcmp(name, inject_names[c]) == 0)
            inject_faults[k].call = c;
    for (size_t e = 0; e < sizeof errnos / sizeof errnos[0]; e++)
        if (strcmp(fault, errnos[e].name) == 0)
            inject_faults[k].err = errnos[e].value;
}

static void inject_setup(void)
{
    inject_ready = 1;
    inject_parse(0, "RAYTRACE_FAULT");
    inject_parse(1, "RAYTRACE_FAULT2");
}

/* Counts a call of kind k; returns 1 when it is the one to fail (or ends
 * the process, for an "exit" fault). */
static int inject_hit(int k)
{
    unsigned long n;

    if (!inject_ready)
        inject_setup();
    n = __atomic_add_fetch(&inject_counts[k], 1, __ATOMIC_RELAXED);
    for (int f = 0; f < 2; f++) {
        if (k != inject_faults[f].call || n != inject_faults[f].at)
            continue;
        if (inject_faults[f].err == -1) {
            static const char msg[] = "libgomp: Out of memory allocating (injected)\n";
            if (write(2, msg, sizeof msg - 1) < 0) {
                /* nothing more to say */
            }
            exit(1);
        }
        if (inject_faults[f].err == -2)
            raise(SIGKILL);
        inject_errno = inject_faults[f].err;
        return 1;
    }
    return 0;
}

__attribute__((destructor)) static void inject_report(void)
{
    const char *path = getenv("RAYTRACE_FAULT_COUNT");
    FILE *f;

    if (!path || !(f = fopen(path, "a")))
        return;
    for (int k = 0; k < CALLS; k++)
        fprintf(f, "%s %lu\n", inject_names[k], inject_counts[k]);
    fclose(f);
}

/* Returns the next definition of name (libc's). */
static void *inject_next(const char *name)
{
    return dlsym(RTLD_NEXT, name);
}

ssize_t write(int fd, const void *buf, size_t n)
{
    static ssize_t (*next)(int, const void *, size_t);

    if (!next)
        next = (ssize_t(*)(int, const void *, size_t))inject_next("write");
    if (fd > 2 && inject_hit(CALL_WRITE)) {
        if (inject_errno == 0 && n > 1)
            return next(fd, buf, n / 2);
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
    return next(fd, buf, n);
}

ssize_t read(int fd, void *buf, size_t n)
{
    static ssize_t (*next)(int, void *, size_t);

    if (!next)
        next = (ssize_t(*)(int, void *, size_t))inject_next("read");
    if (inject_hit(CALL_READ)) {
        if (inject_errno == 0 && n > 1)
            return next(fd, buf, n / 2);
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
    return next(fd, buf, n);
}

int fsync(int fd)
{
    static int (*next)(int);

    if (!next)
        next = (int (*)(int))inject_next("fsync");
    if (inject_hit(CALL_FSYNC)) {
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
    return next(fd);
}

int rename(const char *from, const char *to)
{
    static int (*next)(const char *, const char *);

    if (!next)
        next = (int (*)(const char *, const char *))inject_next("rename");
    if (inject_hit(CALL_RENAME)) {
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
    return next(from, to);
}

int linkat(int fd1, const char *from, int fd2, const char *to, int flags)
{
    static int (*next)(int, const char *, int, const char *, int);

    if (!next)
        next = (int (*)(int, const char *, int, const char *, int))inject_next("linkat");
    if (inject_hit(CALL_LINKAT)) {
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
    return next(fd1, from, fd2, to, flags);
}

int open(const char *path, int flags, ...)
{
    static int (*next)(const char *, int, ...);
    mode_t mode = 0;
    va_list ap;

    if (!next)
        next = (int (*)(const char *, int, ...))inject_next("open");
    va_start(ap, flags);
    if (flags & (O_CREAT | O_TMPFILE))
        mode = (mode_t)va_arg(ap, int);
    va_end(ap);
    if (inject_hit(CALL_OPEN)) {
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
#ifdef O_TMPFILE
    if ((flags & O_TMPFILE) == O_TMPFILE && getenv("RAYTRACE_NO_TMPFILE")) {
        errno = EOPNOTSUPP;
        return -1;
    }
#endif
    return next(path, flags, mode);
}

int unlink(const char *path)
{
    static int (*next)(const char *);

    if (!next)
        next = (int (*)(const char *))inject_next("unlink");
    if (inject_hit(CALL_UNLINK)) {
        errno = inject_errno ? inject_errno : EIO;
        return -1;
    }
    return next(path);
}

void *malloc(size_t n)
{
    if (inject_hit(CALL_MALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_malloc(n);
}

void *calloc(size_t n, size_t size)
{
    if (inject_hit(CALL_MALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_calloc(n, size);
}

void *realloc(void *p, size_t n)
{
    if (inject_hit(CALL_MALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_realloc(p, n);
}
