/* process_win32.c: the process on Windows (see process.h). */
#include "base/process.h"

#include <stdlib.h>
#include <windows.h>
#include <psapi.h>
#include <shellapi.h>

#include "wide.h"

#ifndef ENABLE_VIRTUAL_TERMINAL_PROCESSING
#define ENABLE_VIRTUAL_TERMINAL_PROCESSING 0x0004
#endif

/* Lets the console on standard error draw the progress bar ("\r\033[K"
 * erases it), where the console can (Windows 10 and later). */
static void process_console(void)
{
    HANDLE h = GetStdHandle(STD_ERROR_HANDLE);
    DWORD mode;

    SetConsoleOutputCP(CP_UTF8);
    if (h != INVALID_HANDLE_VALUE && GetConsoleMode(h, &mode))
        SetConsoleMode(h, mode | ENABLE_VIRTUAL_TERMINAL_PROCESSING);
}

/* The arguments, made once and kept to the end (as argv is). */
void process_init(int *argc, char ***argv)
{
    int n;
    wchar_t **w = CommandLineToArgvW(GetCommandLineW(), &n);
    char **args;

    process_console();
    if (!w)
        return; /* the C runtime's own argv stays */
    args = calloc((size_t)n + 1, sizeof *args);
    for (int i = 0; args && i < n; i++)
        if (!(args[i] = wide_to_utf8(w[i]))) {
            for (int j = 0; j < i; j++)
                free(args[j]);
            free(args);
            args = NULL;
        }
    LocalFree(w);
    if (!args)
        return;
    *argc = n;
    *argv = args;
}

double process_seconds(void)
{
    static LARGE_INTEGER freq;
    LARGE_INTEGER now;

    if (freq.QuadPart == 0)
        QueryPerformanceFrequency(&freq);
    QueryPerformanceCounter(&now);
    return (double)now.QuadPart / (double)freq.QuadPart;
}

double process_peak_memory(void)
{
    PROCESS_MEMORY_COUNTERS pmc;

    if (!GetProcessMemoryInfo(GetCurrentProcess(), &pmc, sizeof pmc))
        return 0;
    return (double)pmc.PeakWorkingSetSize;
}
