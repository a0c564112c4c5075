/*
 * inject.c: a fault injector for tests/faults.sh, loaded with LD_PRELOAD
 * into raytrace (test-only: built by `make test` as build/inject.so).
 *
 * RAYTRACE_FAULT=CALL:N:FAULT makes the N-th call (counting from 1) of CALL
 * fail: CALL is write, read, fsync, rename, linkat, open or malloc
 * (malloc, calloc and realloc counted together); FAULT is an errno name
 * (ENOSPC, EIO, EINTR, ENOMEM, EACCES) or, for write and read, "short": the
 * call moves half its bytes (at least one). RAYTRACE_FAULT_COUNT=FILE
 * instead appends to FILE, at exit, how many times each CALL was made.
 * Only the calls the program makes through the dynamic linker are seen:
 * raytrace's own reads and writes (base/file.c, base/outfile.c) are.
 */
#define _GNU_SOURCE

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

enum { CALL_WRITE, CALL_READ, CALL_FSYNC, CALL_RENAME, CALL_LINKAT, CALL_OPEN, CALL_MALLOC,
       CALLS };
static const char *const inject_names[CALLS] = {"write",  "read", "fsync", "rename",
                                                "linkat", "open", "malloc"};
static unsigned long inject_counts[CALLS];
static int inject_call = -1;   /* the call to fail, or -1 */
static unsigned long inject_at; /* its number */
static int inject_errno;        /* the errno it fails with, 0: a short move */
static int inject_ready;

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);

static void inject_setup(void)
{
    const char *spec = getenv("RAYTRACE_FAULT");
    char name[16], fault[16];
    static const struct {
        const char *name;
        int value;
    } errnos[] = {{"ENOSPC", ENOSPC}, {"EIO", EIO},       {"EINTR", EINTR},
                  {"ENOMEM", ENOMEM}, {"EACCES", EACCES}, {"short", 0}};

    inject_ready = 1;
    if (!spec || sscanf(spec, "%15[a-z]:%lu:%15[A-Za-z]", name, &inject_at, fault) != 3)
        return;
    for (int k = 0; k < CALLS; k++)
        if (strcmp(name, inject_names[k]) == 0)
            inject_call = k;
    for (size_t k = 0; k < sizeof errnos / sizeof errnos[0]; k++)
        if (strcmp(fault, errnos[k].name) == 0)
            inject_errno = errnos[k].value;
}

/* Counts a call of kind k; returns 1 when it is the one to fail. */
static int inject_hit(int k)
{
    unsigned long n;

    if (!inject_ready)
        inject_setup();
    n = __atomic_add_fetch(&inject_counts[k], 1, __ATOMIC_RELAXED);
    return k == inject_call && n == inject_at;
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
    return next(path, flags, mode);
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
