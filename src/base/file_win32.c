/* file_win32.c: files on Windows (see file.h). */
#include "base/file.h"

#include <errno.h>
#include <fcntl.h>
#include <io.h>
#include <stdlib.h>
#include <windows.h>

#include "wide.h"

/* Windows refuses to open a folder as "access denied": said as POSIX
 * systems say it, EISDIR. */
FILE *file_open(const char *path, const char *mode)
{
    wchar_t *w = wide_from_utf8(path), *m = wide_from_utf8(mode);
    FILE *f = w && m ? _wfopen(w, m) : NULL;
    int saved = errno;
    DWORD attrs;

    if (!f && w && saved == EACCES && (attrs = GetFileAttributesW(w)) != INVALID_FILE_ATTRIBUTES &&
        (attrs & FILE_ATTRIBUTE_DIRECTORY))
        saved = EISDIR;

    free(w);
    free(m);
    errno = saved;
    return f;
}

/* Fills *info for the existing file or folder path; returns 0, or -1. */
static int file_info(const char *path, BY_HANDLE_FILE_INFORMATION *info)
{
    wchar_t *w = wide_from_utf8(path);
    HANDLE h;
    int ok;

    if (!w)
        return -1;
    /* No access asked: only the file's identity is read. */
    h = CreateFileW(w, 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, NULL,
                    OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, NULL);
    free(w);
    if (h == INVALID_HANDLE_VALUE)
        return -1;
    ok = GetFileInformationByHandle(h, info);
    CloseHandle(h);
    return ok ? 0 : -1;
}

/* A volume's serial number and the file's index on it name one file. */
int file_delete(const char *path)
{
    wchar_t *w = wide_from_utf8(path);
    int rc;

    if (!w)
        return errno;
    rc = DeleteFileW(w) || GetLastError() == ERROR_FILE_NOT_FOUND ? 0 : (wide_errno(GetLastError()), errno);
    free(w);
    return rc;
}

int file_same(const char *a, const char *b)
{
    BY_HANDLE_FILE_INFORMATION ia, ib;

    return file_info(a, &ia) == 0 && file_info(b, &ib) == 0 &&
           ia.dwVolumeSerialNumber == ib.dwVolumeSerialNumber &&
           ia.nFileIndexHigh == ib.nFileIndexHigh && ia.nFileIndexLow == ib.nFileIndexLow;
}

void file_binary(FILE *f)
{
    _setmode(_fileno(f), _O_BINARY);
}

/* _isatty() says yes to every character device, NUL among them: only a
 * console has a console mode. */
int file_is_terminal(FILE *f)
{
    HANDLE h = (HANDLE)_get_osfhandle(_fileno(f));
    DWORD mode;

    return h != INVALID_HANDLE_VALUE && GetConsoleMode(h, &mode) != 0;
}
