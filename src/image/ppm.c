/* ppm.c: PPM writing and reading (see ppm.h). */
#include "image/ppm.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image/image.h"

int ppm_write(FILE *f, int width, int height, const unsigned char *rgb, const char *note)
{
    size_t n = image_size(width, height);

    if (fprintf(f, "P6\n%s%s%s%d %d\n255\n", note ? "# " : "", note ? note : "",
                note ? "\n" : "", width, height) < 0)
        return -1;
    if (fwrite(rgb, 1, n, f) != n)
        return -1;
    return 0;
}

int ppm_write_ascii(FILE *f, int width, int height, const unsigned char *rgb, const char *note)
{
    size_t n = (size_t)width * (size_t)height;
    int col = 0;

    if (fprintf(f, "P3\n%s%s%s%d %d\n255\n", note ? "# " : "", note ? note : "",
                note ? "\n" : "", width, height) < 0)
        return -1;
    for (size_t k = 0; k < n; k++) {
        const unsigned char *p = rgb + 3 * k;
        int w;

        /* A pixel takes at most 12 characters: " 255 255 255". */
        if (col > 0 && (col + 12 > 70 || k % (size_t)width == 0)) {
            if (putc('\n', f) == EOF)
                return -1;
            col = 0;
        }
        w = fprintf(f, col ? " %d %d %d" : "%d %d %d", p[0], p[1], p[2]);
        if (w < 0)
            return -1;
        col += w;
    }
    return putc('\n', f) == EOF ? -1 : 0;
}

/* Cursor over a PPM file: position kept as line and column for messages. */
typedef struct {
    const char *name;      /* file name for messages */
    const unsigned char *p; /* next byte */
    const unsigned char *end;
    const unsigned char *line_start; /* first byte of the current line */
    int line;              /* 1-based */
    Error *err;
} PpmCursor;

static int ppm_column(const PpmCursor *c)
{
    return (int)(c->p - c->line_start) + 1;
}

/* Records an error at the cursor, quoting the current line. */
static void ppm_fail(PpmCursor *c, const char *what)
{
    const unsigned char *eol = c->line_start;
    while (eol < c->end && *eol != '\n' && eol - c->line_start < 4096)
        eol++;
    error_set_at(c->err, c->name, c->line, ppm_column(c), (const char *)c->line_start,
                 (size_t)(eol - c->line_start), "%s", what);
}

static int ppm_is_space(unsigned char ch)
{
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\v' || ch == '\f';
}

/* Skips whitespace and '#' comments, keeping the line count. */
static void ppm_skip_space(PpmCursor *c)
{
    while (c->p < c->end) {
        if (*c->p == '#') {
            while (c->p < c->end && *c->p != '\n')
                c->p++;
        } else if (ppm_is_space(*c->p)) {
            if (*c->p == '\n') {
                c->line++;
                c->line_start = c->p + 1;
            }
            c->p++;
        } else {
            break;
        }
    }
}

/* ppm-number -> digits, with value in 0..max; what names it in messages. */
static int ppm_expect_uint(PpmCursor *c, long max, const char *what, long *out)
{
    char msg[200];
    long v = 0;

    ppm_skip_space(c);
    if (c->p >= c->end || *c->p < '0' || *c->p > '9') {
        snprintf(msg, sizeof msg, "expected %s (a whole number), found %s", what,
                 c->p >= c->end ? "the end of the file" : "something else");
        ppm_fail(c, msg);
        return -1;
    }
    while (c->p < c->end && *c->p >= '0' && *c->p <= '9') {
        v = v * 10 + (*c->p - '0');
        if (v > max) {
            snprintf(msg, sizeof msg, "%s is out of range (at most %ld)", what, max);
            ppm_fail(c, msg);
            return -1;
        }
        c->p++;
    }
    *out = v;
    return 0;
}

void ppm_free(PpmImage *img)
{
    free(img->samples);
    img->samples = NULL;
    img->width = img->height = img->maxval = 0;
}

/* Reads the raster of a P6 file, which holds count samples of one or two
 * bytes, big-endian. */
static int ppm_read_binary(PpmCursor *c, PpmImage *img, size_t count)
{
    size_t bytes = img->maxval > 255 ? 2 : 1;

    for (size_t k = 0; k < count; k++) {
        unsigned v = bytes == 2 ? (unsigned)(c->p[0] << 8 | c->p[1]) : c->p[0];
        if (v > (unsigned)img->maxval) {
            ppm_fail(c, "sample value exceeds the maxval");
            return -1;
        }
        img->samples[k] = (unsigned short)v;
        c->p += bytes;
    }
    return 0;
}

/* Reads the raster of a P3 file: decimal samples separated by whitespace. */
static int ppm_read_ascii(PpmCursor *c, PpmImage *img, size_t count)
{
    for (size_t k = 0; k < count; k++) {
        long v;
        if (ppm_expect_uint(c, img->maxval, "a sample", &v) != 0)
            return -1;
        img->samples[k] = (unsigned short)v;
    }
    return 0;
}

int ppm_parse(const char *name, const char *data, size_t len, PpmImage *img, Error *err)
{
    size_t count;
    long w, h, maxval;
    int binary, rc = -1;
    PpmCursor c;

    img->samples = NULL;
    img->width = img->height = img->maxval = 0;
    c.name = name;
    c.p = c.line_start = (const unsigned char *)data;
    c.end = c.p + len;
    c.line = 1;
    c.err = err;
    if (len < 2 || c.p[0] != 'P' || (c.p[1] != '6' && c.p[1] != '3')) {
        ppm_fail(&c, "not a PPM file: expected 'P6' or 'P3' at the start");
        goto done;
    }
    binary = c.p[1] == '6';
    c.p += 2;
    if (ppm_expect_uint(&c, INT_MAX, "the width", &w) != 0 ||
        ppm_expect_uint(&c, INT_MAX, "the height", &h) != 0 ||
        ppm_expect_uint(&c, 65535, "the maxval", &maxval) != 0)
        goto done;
    if (w < 1 || h < 1 || maxval < 1) {
        ppm_fail(&c, "width, height and maxval must be at least 1");
        goto done;
    }
    if (binary) {
        if (c.p >= c.end || !ppm_is_space(*c.p)) {
            ppm_fail(&c, "expected one whitespace byte before the pixel data");
            goto done;
        }
        c.p++;
    }
    if ((size_t)w > ((size_t)-1 / sizeof *img->samples / 3) / (size_t)h) {
        ppm_fail(&c, "image too large");
        goto done;
    }
    count = 3 * (size_t)w * (size_t)h;
    /* A header may promise more pixels than the file holds: say so before
     * allocating for them. */
    if (binary && (size_t)(c.end - c.p) / (maxval > 255 ? 2 : 1) < count) {
        char msg[200];
        snprintf(msg, sizeof msg, "truncated pixel data: expected %zu bytes, found %zu",
                 count * (maxval > 255 ? 2 : 1), (size_t)(c.end - c.p));
        ppm_fail(&c, msg);
        goto done;
    }
    if (!binary && (size_t)(c.end - c.p) < count) {
        char msg[200];
        snprintf(msg, sizeof msg,
                 "truncated pixel data: %zu samples need more than the %zu bytes left", count,
                 (size_t)(c.end - c.p));
        ppm_fail(&c, msg);
        goto done;
    }
    img->width = (int)w;
    img->height = (int)h;
    img->maxval = (int)maxval;
    img->samples = malloc(count * sizeof *img->samples);
    if (!img->samples) {
        error_set(err, c.name, "out of memory for a %ld x %ld image", w, h);
        goto done;
    }
    rc = binary ? ppm_read_binary(&c, img, count) : ppm_read_ascii(&c, img, count);
done:
    if (rc != 0)
        ppm_free(img);
    return rc;
}
