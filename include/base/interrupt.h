/*
 * interrupt.h: what an interrupt does while raytrace runs. An interrupt is
 * SIGINT or SIGTERM on POSIX systems; Ctrl-C, Ctrl-Break or the console's
 * closing on Windows. It removes the temporary output file being written,
 * if any, erases the progress bar if one is shown, writes the message
 * given to interrupt_catch() on standard error and ends the process with
 * status 128 + the signal's number (130 for Ctrl-C, 143 for SIGTERM or a
 * closing console). Any exit the program did not choose (the OpenMP
 * runtime's fatal errors call exit() from its threads) removes the
 * temporary file too. An interrupt the process's parent set to be ignored
 * (a POSIX shell's background job, nohup; on Windows, a process group
 * started with Ctrl-C disabled) stays ignored. interrupt_posix.c and
 * interrupt_win32.c say how.
 */
#ifndef RAYTRACE_INTERRUPT_H
#define RAYTRACE_INTERRUPT_H

/* Arranges, once, for interrupts and exits to do the above; message (a
 * static string) is what an interrupt says. */
void interrupt_catch(const char *message);

/* Holds interrupts back until interrupt_release(), so that none strikes
 * between a temporary file's creation and interrupt_watch(); calls do not
 * nest, and come after interrupt_catch(). */
void interrupt_hold(void);
void interrupt_release(void);

/* Makes the file named by the string at path (read when an interrupt
 * comes, so it may be filled in later; "" names none) the one to remove;
 * NULL: none. */
void interrupt_watch(const char *path);

/* Says whether a progress bar is on standard error (1) or not (0). */
void interrupt_bar(int shown);

#endif
