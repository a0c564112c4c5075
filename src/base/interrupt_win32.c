/* interrupt_win32.c: interrupts on Windows: Ctrl-C, Ctrl-Break and the
 * console's closing (see interrupt.h). Windows calls the handler in a
 * thread of its own, so it takes a lock that interrupt_hold() holds. */
#include "base/interrupt.h"

#include <stdlib.h>
#include <string.h>
#include <windows.h>

#include "wide.h"

/* The file to remove, for the handler. */
static const char *volatile interrupt_path;

/* Set while a progress bar is on the console, for the handler to erase. */
static volatile LONG interrupt_bar_shown;

/* What the handler says. */
static const char *interrupt_message = "interrupted\n";

/* Held by interrupt_hold() and by the handler. */
static CRITICAL_SECTION interrupt_lock;

/* Removes the file interrupt_path names, if any. The file is open for
 * writing, shared for deletion (outfile_win32.c): Windows removes it as
 * soon as the process's handle closes, which ending the process does. */
static void interrupt_remove(void)
{
    const char *path = interrupt_path;
    wchar_t *w;

    if (!path || !*path)
        return;
    w = wide_from_utf8(path);
    if (w)
        DeleteFileW(w);
    free(w);
}

/* Writes n bytes at s on standard error, as they are. */
static void interrupt_say(const char *s, size_t n)
{
    HANDLE err = GetStdHandle(STD_ERROR_HANDLE);
    DWORD done;

    if (err != NULL && err != INVALID_HANDLE_VALUE)
        WriteFile(err, s, (DWORD)n, &done, NULL);
}

/* On Ctrl-C (130, as SIGINT's 128 + 2), Ctrl-Break or the console's
 * closing, logoff or shutdown (143, as SIGTERM's): remove the file, say so
 * and end the process at once, its other threads with it. */
static BOOL WINAPI interrupt_on_event(DWORD event)
{
    static const char erase[] = "\r\033[K";

    EnterCriticalSection(&interrupt_lock);
    interrupt_remove();
    if (interrupt_bar_shown)
        interrupt_say(erase, sizeof erase - 1);
    interrupt_say(interrupt_message, strlen(interrupt_message));
    TerminateProcess(GetCurrentProcess(),
                     event == CTRL_C_EVENT || event == CTRL_BREAK_EVENT ? 130 : 143);
    return TRUE;
}

/* At any exit: remove the file. */
static void interrupt_at_exit(void)
{
    interrupt_remove();
}

void interrupt_catch(const char *message)
{
    static int caught;

    if (caught)
        return;
    caught = 1;
    interrupt_message = message;
    InitializeCriticalSection(&interrupt_lock);
    SetConsoleCtrlHandler(interrupt_on_event, TRUE);
    atexit(interrupt_at_exit);
}

void interrupt_hold(void)
{
    EnterCriticalSection(&interrupt_lock);
}

void interrupt_release(void)
{
    LeaveCriticalSection(&interrupt_lock);
}

void interrupt_watch(const char *path)
{
    interrupt_path = path;
}

void interrupt_bar(int shown)
{
    InterlockedExchange(&interrupt_bar_shown, shown);
}
