/* writer.c: choosing and writing the output format (see writer.h). */
#include "image/writer.h"

#include <ctype.h>
#include <string.h>

#include "image/bmp.h"
#include "image/jpeg.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"

static const char *const writer_names[] = {"ppm", "png", "pfm", "jpeg", "bmp"};

/* The other image formats' extensions and names, which raytrace does not
 * write. */
static const char *const writer_others[][2] = {
    {"tif", "TIFF"},  {"tiff", "TIFF"},     {"tga", "TGA"},      {"gif", "GIF"},
    {"webp", "WebP"}, {"exr", "OpenEXR"},   {"hdr", "Radiance HDR"}, {"jxl", "JPEG XL"},
    {"jp2", "JPEG 2000"}, {"j2k", "JPEG 2000"}, {"avif", "AVIF"}, {"heic", "HEIF"},
    {"heif", "HEIF"}, {"ico", "ICO"},       {"psd", "Photoshop"}, {"dds", "DDS"},
    {"qoi", "QOI"},   {"pgm", "PGM (grey)"}, {"pbm", "PBM (black and white)"},
    {"pam", "PAM"},   {"xpm", "XPM"},       {"svg", "SVG"},      {"pdf", "PDF"},
    {"eps", "EPS"},   {"pcx", "PCX"},       {"dng", "DNG"}};

int writer_format_named(const char *name)
{
    for (int k = 0; k < (int)(sizeof writer_names / sizeof writer_names[0]); k++)
        if (strcmp(name, writer_names[k]) == 0)
            return k;
    return strcmp(name, "jpg") == 0 ? FORMAT_JPEG : strcmp(name, "pnm") == 0 ? FORMAT_PPM : -1;
}

/* Puts path's extension, in lower case, into ext (5 bytes); returns 0, or
 * -1 when path has none of 2 to 4 characters. */
static int writer_extension(const char *path, char ext[5])
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    size_t n;

    if (!dot || (slash && dot < slash) || (n = strlen(dot + 1)) < 2 || n > 4)
        return -1;
    for (size_t i = 0; i < n; i++)
        ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    ext[n] = '\0';
    return 0;
}

ImageFormat writer_format_for(const char *path)
{
    char ext[5];

    if (writer_extension(path, ext) != 0 || writer_format_named(ext) < 0)
        return FORMAT_PPM;
    return (ImageFormat)writer_format_named(ext);
}

const char *writer_unwritable(const char *path)
{
    char ext[5];

    if (writer_extension(path, ext) != 0)
        return NULL;
    for (size_t k = 0; k < sizeof writer_others / sizeof writer_others[0]; k++)
        if (strcmp(ext, writer_others[k][0]) == 0)
            return writer_others[k][1];
    return NULL;
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
    case FORMAT_BMP:
        return n + 3 * (size_t)width + 4;
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
    case FORMAT_BMP:
        return bmp_write(f, img->width, img->height, img->rgb);
    default:
        return opts->ascii ? ppm_write_ascii(f, img->width, img->height, img->rgb, opts->note)
                           : ppm_write(f, img->width, img->height, img->rgb, opts->note);
    }
}
