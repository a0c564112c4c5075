/* jpeg_stream.c: the JPEG reader's faults, warnings and markers found in
 * its bytes, the bottom step that jpeg.c, jpeg_markers.c and
 * jpeg_entropy.c call down to (see jpeg_decode.h). */
#include <stdarg.h>
#include <stdio.h>

#include "image/jpeg.h"
#include "jpeg_decode.h"

int jpeg_is(const unsigned char *data, size_t len)
{
    return len >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF;
}

/* Records a fault "at byte OFFSET: MESSAGE"; returns -1. */
int jpeg_fail(Jpeg *J, const char *fmt, const char *what)
{
    char msg[200];

    snprintf(msg, sizeof msg, fmt, what ? what : "");
    error_set(J->err, J->name, "at byte %zu: %s", J->pos, msg);
    return -1;
}

/* Records that the file uses something this reader does not; returns -1. */
int jpeg_unsupported(Jpeg *J, const char *what)
{
    error_set(J->err, J->name, "unsupported JPEG: %s", what);
    return -1;
}

void jpeg_warn(Jpeg *J, const char *fmt, ...)
{
    if (J->warnings++ == 0) {
        char msg[120];
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, sizeof msg, fmt, ap);
        va_end(ap);
        snprintf(J->warning, sizeof J->warning, "at byte %zu: %s", J->pos, msg);
    }
}

int jpeg_find_marker(Jpeg *J, size_t junk)
{
    size_t start = J->pos;

    for (;;) {
        size_t at;
        while (J->pos < J->len && J->data[J->pos] != 0xFF) {
            J->pos++;
            junk++;
        }
        at = J->pos;
        while (J->pos < J->len && J->data[J->pos] == 0xFF)
            J->pos++;
        if (J->pos >= J->len) {
            J->pos = start;
            return -1;
        }
        if (J->data[J->pos] != 0) {
            int marker = J->data[J->pos];
            J->pos = J->pos - 1; /* its last 0xFF */
            if (junk > 0) {
                size_t here = J->pos;
                J->pos = at;
                jpeg_warn(J, "%zu extraneous bytes before marker 0x%02X", junk, marker);
                J->pos = here;
            }
            return marker;
        }
        /* 0xFF 0x00: a stuffed byte of data, not a marker. */
        J->pos++;
        junk += 2;
    }
}
