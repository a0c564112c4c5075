/*
 * wide.h: UTF-8 names to and from the UTF-16 ones Windows's calls take
 * (the Windows implementations of base/ only).
 */
#ifndef RAYTRACE_WIDE_H
#define RAYTRACE_WIDE_H

#include <wchar.h>

/* Returns s (UTF-8) as a new UTF-16 string; NULL with errno set (EILSEQ
 * when s is not UTF-8, ENOMEM) when it cannot. The caller frees it. */
wchar_t *wide_from_utf8(const char *s);

/* Returns w (UTF-16) as a new UTF-8 string; NULL with errno set when it
 * cannot. The caller frees it. */
char *wide_to_utf8(const wchar_t *w);

/* Sets errno to the C library's nearest code for Windows error code e
 * (a GetLastError() value). */
void wide_errno(unsigned long e);

#endif
