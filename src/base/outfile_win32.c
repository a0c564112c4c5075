/* outfile_win32.c: all-or-nothing output files on Windows (see outfile.h):
 * a temporary file beside the output, shared for deletion so that an
 * interrupt can remove it while it is open, flushed to the disk, then
 * moved over the output by MoveFileEx's replace; the names a killed
 * process left beside an output are removed when it is opened again. */
#include "outfile_sys.h"

#include <errno.h>
#include <fcntl.h>
#include <io.h>
#include <stdlib.h>
#include <string.h>
#include <windows.h>

#include "base/path.h"
#include "wide.h"

/* What the file path is: OUTFILE_NONE, a folder, a file on a disk, or
 * something else (a device such as NUL or CON, a pipe), written in place. */
typedef enum { OUTFILE_NONE, OUTFILE_FOLDER, OUTFILE_DISK, OUTFILE_DEVICE } OutfileKind;

static OutfileKind outfile_kind(const wchar_t *path)
{
    DWORD attrs = GetFileAttributesW(path);
    HANDLE h;
    DWORD type;

    if (attrs != INVALID_FILE_ATTRIBUTES)
        return attrs & FILE_ATTRIBUTE_DIRECTORY ? OUTFILE_FOLDER : OUTFILE_DISK;
    /* Devices have no attributes to read: open it to ask. */
    h = CreateFileW(path, 0, FILE_SHARE_READ | FILE_SHARE_WRITE, NULL, OPEN_EXISTING, 0, NULL);
    if (h == INVALID_HANDLE_VALUE)
        return OUTFILE_NONE;
    type = GetFileType(h);
    CloseHandle(h);
    return type == FILE_TYPE_DISK ? OUTFILE_DISK : OUTFILE_DEVICE;
}

/* Returns the hash of this machine's name that temporary names carry, so
 * that a sweep judges only its own machine's. */
static unsigned long outfile_host(void)
{
    char host[MAX_COMPUTERNAME_LENGTH + 1] = "";
    DWORD size = sizeof host;

    if (!GetComputerNameA(host, &size))
        host[0] = '\0';
    return outfile_hash(host);
}

int outfile_temp_name(const char *dest, unsigned long pid, unsigned try, char *name,
                      size_t size)
{
    return outfile_temp_format(dest, outfile_host(), pid, try, name, size);
}

/* Says whether process pid no longer runs (the system knows no such
 * process, or it has ended). */
static int outfile_gone(unsigned long pid)
{
    HANDLE h = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, (DWORD)pid);
    DWORD code;
    int gone;

    if (!h)
        return GetLastError() == ERROR_INVALID_PARAMETER;
    gone = GetExitCodeProcess(h, &code) && code != STILL_ACTIVE;
    CloseHandle(h);
    return gone;
}

/* Removes, from folder dir, the temporary names beside output base that
 * processes of this machine left when they were killed (those that no
 * longer run). Best effort: what cannot be read or removed stays. */
static void outfile_sweep(const char *dir, const char *base)
{
    unsigned long host = outfile_host(), pid;
    const char *sep = path_dir_length(dir) == strlen(dir) ? "" : "\\";
    char pattern[OUTFILE_PATH_MAX];
    WIN32_FIND_DATAW found;
    wchar_t *w;
    HANDLE find;

    if (snprintf(pattern, sizeof pattern, "%s%s.*", dir, sep) >= (int)sizeof pattern ||
        !(w = wide_from_utf8(pattern)))
        return;
    find = FindFirstFileW(w, &found);
    free(w);
    if (find == INVALID_HANDLE_VALUE)
        return;
    do {
        char *entry = wide_to_utf8(found.cFileName), name[OUTFILE_PATH_MAX];
        if (entry && outfile_temp_of(entry, base, host, &pid) && outfile_gone(pid) &&
            snprintf(name, sizeof name, "%s%s%s", dir, sep, entry) < (int)sizeof name &&
            (w = wide_from_utf8(name)) != NULL) {
            DeleteFileW(w);
            free(w);
        }
        free(entry);
    } while (FindNextFileW(find, &found));
    FindClose(find);
}

/* Creates out->temp, a new file beside out->dest (outfile_temp_name());
 * returns its handle, or INVALID_HANDLE_VALUE with GetLastError() saying
 * why. */
static HANDLE outfile_create_temp(OutFile *out)
{
    for (unsigned try = 0; try < 100; try++) {
        wchar_t *w;
        HANDLE h;
        if (outfile_temp_name(out->dest, GetCurrentProcessId(), try, out->temp,
                              sizeof out->temp) != 0) {
            SetLastError(ERROR_FILENAME_EXCED_RANGE);
            break;
        }
        w = wide_from_utf8(out->temp);
        if (!w) {
            SetLastError(ERROR_INVALID_NAME);
            break;
        }
        /* Shared for deletion: an interrupt may remove it while open. */
        h = CreateFileW(w, GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_DELETE, NULL, CREATE_NEW,
                        FILE_ATTRIBUTE_NORMAL, NULL);
        free(w);
        if (h != INVALID_HANDLE_VALUE)
            return h;
        if (GetLastError() != ERROR_FILE_EXISTS && GetLastError() != ERROR_ALREADY_EXISTS)
            break;
    }
    out->temp[0] = '\0';
    return INVALID_HANDLE_VALUE;
}

/* Opens path in place (a device); returns 0, or -1 with *err set. */
static int outfile_in_place(OutFile *out, const char *path, Error *err)
{
    wchar_t *w = wide_from_utf8(path);

    out->fp = w ? _wfopen(w, L"wb") : NULL;
    free(w);
    if (!out->fp) {
        error_set(err, path, "cannot open for writing: %s", strerror(errno));
        return -1;
    }
    return 0;
}

int outfile_open(OutFile *out, const char *path, Error *err)
{
    char dir[OUTFILE_PATH_MAX];
    size_t base;
    wchar_t *w;
    OutfileKind kind;
    HANDLE h;
    int fd, rc = outfile_start(out, path, err);

    if (rc < 0)
        return -1;
    if (rc > 0) {
        _setmode(_fileno(stdout), _O_BINARY);
        return 0;
    }
    if (!(w = wide_from_utf8(path))) {
        error_set(err, path, "cannot open for writing: %s", strerror(errno));
        return -1;
    }
    kind = outfile_kind(w);
    free(w);
    if (kind == OUTFILE_FOLDER) {
        error_set(err, path, "cannot write the image: it is a directory");
        return -1;
    }
    if (kind == OUTFILE_DEVICE)
        return outfile_in_place(out, path, err);
    strcpy(out->dest, path);
    base = outfile_folder(path, dir);
    strcpy(out->dir, dir);
    outfile_sweep(dir, path + base);
    h = outfile_create_temp(out);
    if (h == INVALID_HANDLE_VALUE) {
        wide_errno(GetLastError());
        error_set(err, path, "cannot create a file in directory '%s': %s", dir, strerror(errno));
        return -1;
    }
    fd = _open_osfhandle((intptr_t)h, _O_WRONLY | _O_BINARY);
    if (fd < 0 || !(out->fp = _fdopen(fd, "wb"))) {
        error_set(err, path, "cannot write in directory '%s': %s", dir, strerror(errno));
        if (fd >= 0)
            _close(fd);
        else
            CloseHandle(h);
        outfile_remove_temp(out, err);
        return -1;
    }
    return 0;
}

int outfile_check(const char *path, Error *err)
{
    char dir[OUTFILE_PATH_MAX];
    wchar_t *w;
    DWORD attrs;

    if (strcmp(path, "-") == 0)
        return 0;
    if (strlen(path) >= OUTFILE_PATH_MAX - 32) {
        error_set(err, path, "output path is too long");
        return -1;
    }
    if (!(w = wide_from_utf8(path))) {
        error_set(err, path, "cannot open for writing: %s", strerror(errno));
        return -1;
    }
    switch (outfile_kind(w)) {
    case OUTFILE_FOLDER:
        free(w);
        error_set(err, path, "cannot write the image: it is a directory");
        return -1;
    case OUTFILE_DEVICE:
        free(w);
        return 0;
    default:
        free(w);
    }
    outfile_folder(path, dir);
    w = wide_from_utf8(dir);
    attrs = w ? GetFileAttributesW(w) : INVALID_FILE_ATTRIBUTES;
    free(w);
    if (attrs != INVALID_FILE_ATTRIBUTES && (attrs & FILE_ATTRIBUTE_DIRECTORY))
        return 0;
    if (attrs != INVALID_FILE_ATTRIBUTES)
        SetLastError(ERROR_DIRECTORY);
    wide_errno(GetLastError());
    error_set(err, path, "cannot create a file in directory '%s': %s", dir, strerror(errno));
    return -1;
}

/* Moves out's finished temporary file over its destination; returns 0, or
 * -1 with GetLastError() saying why. */
static int outfile_replace(const OutFile *out)
{
    wchar_t *from = wide_from_utf8(out->temp), *to = wide_from_utf8(out->dest);
    int ok = from && to &&
             MoveFileExW(from, to, MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH);

    if (!from || !to)
        SetLastError(ERROR_NOT_ENOUGH_MEMORY);
    free(from);
    free(to);
    return ok ? 0 : -1;
}

int outfile_commit(OutFile *out, Error *err)
{
    int failed = fflush(out->fp) != 0 || ferror(out->fp);
    int saved = errno;

    /* Make the data durable before the move makes it visible. */
    if (!failed && out->temp[0] &&
        !FlushFileBuffers((HANDLE)_get_osfhandle(_fileno(out->fp)))) {
        wide_errno(GetLastError());
        failed = 1;
        saved = errno;
    }
    if (!out->is_stdout && fclose(out->fp) != 0 && !failed) {
        failed = 1;
        saved = errno;
    }
    out->fp = NULL;
    if (!failed && out->temp[0] && outfile_replace(out) != 0) {
        wide_errno(GetLastError());
        failed = 1;
        saved = errno;
    }
    if (failed)
        return outfile_failed(out, saved, err);
    out->temp[0] = '\0';
    return 0;
}
