/* interrupt_posix.c: interrupts on POSIX systems, SIGINT and SIGTERM (see
 * interrupt.h). */
#define _POSIX_C_SOURCE 200809L

#include "base/interrupt.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The file to remove, for the handler. */
static const char *volatile interrupt_path;

/* Set while a progress bar is on the terminal, for the handler to erase. */
static volatile sig_atomic_t interrupt_bar_shown;

/* What the handler says. */
static const char *interrupt_message = "interrupted\n";

/* The signals held back while interrupt_hold() holds, and the mask before. */
static sigset_t interrupt_old;

/* On SIGINT or SIGTERM: remove the file, say so, exit 128 + sig; only
 * async-signal-safe calls. */
static void interrupt_on_signal(int sig)
{
    static const char erase[] = "\r\033[K";
    const char *path = interrupt_path;

    if (path && *path)
        unlink(path);
    if ((interrupt_bar_shown && write(STDERR_FILENO, erase, sizeof erase - 1) < 0) ||
        write(STDERR_FILENO, interrupt_message, strlen(interrupt_message)) < 0) {
        /* Nothing more can be done. */
    }
    _exit(128 + sig);
}

/* At any exit: remove the file. */
static void interrupt_at_exit(void)
{
    const char *path = interrupt_path;

    if (path && *path)
        unlink(path);
}

/* Gives sig to sa's handler, unless the process started with sig ignored
 * (a job its shell started in the background, nohup): that choice of the
 * parent's stands, as POSIX shells expect of their commands. */
static void interrupt_take(int sig, const struct sigaction *sa)
{
    struct sigaction now;

    if (sigaction(sig, NULL, &now) == 0 && now.sa_handler == SIG_IGN)
        return;
    sigaction(sig, sa, NULL);
}

void interrupt_catch(const char *message)
{
    static int caught;
    struct sigaction sa;

    if (caught)
        return;
    caught = 1;
    interrupt_message = message;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = interrupt_on_signal;
    sigemptyset(&sa.sa_mask);
    interrupt_take(SIGINT, &sa);
    interrupt_take(SIGTERM, &sa);
    atexit(interrupt_at_exit);
}

/* Only the calling thread's mask changes: it is called before the render's
 * threads exist, or after they are gone. */
void interrupt_hold(void)
{
    sigset_t set;

    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigprocmask(SIG_BLOCK, &set, &interrupt_old);
}

void interrupt_release(void)
{
    sigprocmask(SIG_SETMASK, &interrupt_old, NULL);
}

void interrupt_watch(const char *path)
{
    interrupt_path = path;
}

void interrupt_bar(int shown)
{
    interrupt_bar_shown = shown;
}
