/* writer.c: choosing and writing the output format (see writer.h). */
#include "image/writer.h"

#include <ctype.h>
#include <string.h>

#include "image/jpeg.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"

static const char *const writer_names[] = {"ppm", "png", "pfm", "jpeg"};

int writer_format_named(const char *name)
{
    for (int k = 0; k < 4; k++)
        if (strcmp(name, writer_names[k]) == 0)
            return k;
    return strcmp(name, "jpg") == 0 ? FORMAT_JPEG : -1;
}

ImageFormat writer_format_for(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    char ext[5];
    size_t n;

    if (!dot || (slash && dot < slash) || (n = strlen(dot + 1)) < 3 || n > 4)
        return FORMAT_PPM;
    for (size_t i = 0; i < n; i++)
        ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    ext[n] = '\0';
    return writer_format_named(ext) >= 0 ? (ImageFormat)writer_format_named(ext) : FORMAT_PPM;
}

size_t writer_memory(const WriterOptions *opts, int width, int height)
{
    size_t n = image_size(width, height), rows = n + (size_t)height;

    switch (opts->format) {
    case FORMAT_PNG:
        return n + 2 * rows + ((size_t)1 << 20);
    case FORMAT_PFM:
        return n + n * sizeof(float);
    case FORMAT_JPEG:
        return n + jpeg_write_memory(width, height, !opts->jpeg_444);
    default:
        return n;
    }
}

int writer_write(FILE *f, const Image *img, const WriterOptions *opts)
{
    switch (opts->format) {
    case FORMAT_PNG:
        return png_write(f, img->width, img->height, img->rgb, opts->png_deflate, opts->note);
    case FORMAT_PFM:
        return pfm_write(f, img->width, img->height, img->linear, opts->note);
    case FORMAT_JPEG:
        return jpeg_write(f, img->width, img->height, img->rgb, opts->jpeg_quality,
                          !opts->jpeg_444);
    default:
        return opts->ascii ? ppm_write_ascii(f, img->width, img->height, img->rgb, opts->note)
                           : ppm_write(f, img->width, img->height, img->rgb, opts->note);
    }
}
