/*
 * diff_main.c: the raytrace-diff command: compares a render with a
 * reference and says how far apart they are. The only code of the command
 * that prints or exits; the work is in compare.c.
 *
 * Exit status: 0 within tolerance, 1 different, 2 trouble (an unreadable
 * image, different sizes, a bad command line).
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/outfile.h"
#include "base/process.h"
#include "image/compare.h"
#include "image/writer.h"

#define DIFF_VERSION "0.2.0"

static const char diff_help[] =
    "Usage: raytrace-diff [OPTIONS] REFERENCE IMAGE\n"
    "Compare IMAGE with REFERENCE, channel by channel, on the 0..255 scale of an\n"
    "8-bit image. Both may be PPM (P3 or P6, any maxval), PFM, PNG, JPEG or BMP.\n"
    "\n"
    "Options:\n"
    "  -t, --tolerance N   a channel may differ by up to N levels (default 0)\n"
    "  -m, --max-pixels N  up to N pixels may exceed the tolerance (default 0)\n"
    "  -d, --diff FILE     write FILE: REFERENCE darkened, with the pixels over\n"
    "                      the tolerance in red (PPM, or PNG by extension)\n"
    "  -b, --box WxH       compare W x H boxes, each the mean of the pixels it\n"
    "                      covers in both images (a box filter, 1 <= W <= the\n"
    "                      width, 1 <= H <= the height): noise and edges averaged\n"
    "                      out, the pictures' look compared\n"
    "  -c, --clamp         clamp both to 0..255 first, as an 8-bit image shows\n"
    "                      them (a PFM's colours against an 8-bit render)\n"
    "  -o, --only MASK     compare only the pixels that are not black in MASK,\n"
    "                      an image of the same size (raytrace --spp-map's:\n"
    "                      the pixels that took more than the least samples)\n"
    "  -q, --quiet         print nothing; the exit status says it all\n"
    "  -h, --help          print this help and exit\n"
    "  -V, --version       print the version and exit\n"
    "\n"
    "Prints both sizes and formats, the largest difference with its pixel and\n"
    "both values, the mean and RMS differences, the PSNR, and the number of\n"
    "pixels over the tolerance.\n"
    "\n"
    "Exit status: 0 at most --max-pixels pixels exceed the tolerance; 1 more\n"
    "do; 2 an image cannot be read, the sizes differ, or the command line is\n"
    "wrong.\n";

static int diff_usage(const char *fmt, const char *arg)
{
    fprintf(stderr, "raytrace-diff: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry 'raytrace-diff --help'.\n");
    return 2;
}

static void diff_report(const Error *err)
{
    char message[4 * ERROR_MESSAGE_MAX];

    error_escape(message, sizeof message, err->message, strlen(err->message), 0, NULL);
    if (err->line > 0)
        fprintf(stderr, "raytrace-diff: %s:%d:%d: error: %s\n", err->file, err->line,
                err->column, message);
    else
        fprintf(stderr, "raytrace-diff: %s%serror: %s\n", err->file, err->file[0] ? ": " : "",
                message);
}

/* Reads a number >= 0 from text into *out; returns 0 or -1. */
static int diff_number(const char *text, double *out)
{
    char *end;
    double v = strtod(text, &end);

    if (!*text || *end || !(v >= 0) || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

/* Writes the diff image of a and b to path. */
static int diff_write_image(const char *path, const Picture *a, const Picture *b,
                            double tolerance)
{
    WriterOptions wopts = {writer_format_for(path), 0, DEFLATE_FIXED, 95, 1, NULL};
    Image img;
    OutFile out;
    Error err;

    if (wopts.format == FORMAT_PFM)
        wopts.format = FORMAT_PPM;
    if (image_init(&img, a->width, a->height) != 0) {
        fprintf(stderr, "raytrace-diff: %s: error: out of memory\n", path);
        return -1;
    }
    compare_diff_image(a, b, tolerance, &img);
    if (outfile_open(&out, path, &err) != 0) {
        diff_report(&err);
        image_free(&img);
        return -1;
    }
    if (writer_write(out.fp, &img, &wopts) != 0) {
        error_set(&err, path, "cannot write the image");
        outfile_abort(&out, &err);
        diff_report(&err);
        image_free(&img);
        return -1;
    }
    image_free(&img);
    if (outfile_commit(&out, &err) != 0) {
        diff_report(&err);
        return -1;
    }
    return 0;
}

/* Keeps of a and b (of one size) the pixels not black in the image at
 * mask_path; returns 0, or -1 after saying why not. */
static int diff_select(const char *mask_path, Picture *a, Picture *b)
{
    Picture mask;
    Error err;
    int rc = -1;

    if (picture_load(mask_path, &mask, &err) != 0) {
        diff_report(&err);
        return -1;
    }
    if (mask.width != a->width || mask.height != a->height)
        fprintf(stderr, "raytrace-diff: error: --only %s is %d x %d, the images %d x %d\n",
                mask_path, mask.width, mask.height, a->width, a->height);
    else if (picture_select(a, &mask, &err) != 0 || picture_select(b, &mask, &err) != 0)
        fprintf(stderr, "raytrace-diff: error: --only %s: %s\n", mask_path, err.message);
    else
        rc = 0;
    picture_free(&mask);
    return rc;
}

int main(int argc, char **argv)
{
    static const char *const channel[3] = {"red", "green", "blue"};
    const char *paths[2], *diff_path = NULL, *box = NULL, *only = NULL;
    int box_w = 0, box_h = 0;
    double tolerance = 0, max_pixels = 0;
    int npaths = 0, quiet = 0, clamp = 0, status, width, height;
    Picture a, b;
    Comparison c;
    Error err;

    process_init(&argc, &argv);
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
            fputs(diff_help, stdout);
            return 0;
        } else if (strcmp(arg, "-V") == 0 || strcmp(arg, "--version") == 0) {
            puts("raytrace-diff " DIFF_VERSION);
            return 0;
        } else if (strcmp(arg, "-q") == 0 || strcmp(arg, "--quiet") == 0) {
            quiet = 1;
        } else if (strcmp(arg, "-c") == 0 || strcmp(arg, "--clamp") == 0) {
            clamp = 1;
        } else if (strcmp(arg, "-o") == 0 || strcmp(arg, "--only") == 0) {
            if (i + 1 >= argc)
                return diff_usage("option '%s' needs a value", arg);
            only = argv[++i];
        } else if (strcmp(arg, "-t") == 0 || strcmp(arg, "--tolerance") == 0 ||
                   strcmp(arg, "-m") == 0 || strcmp(arg, "--max-pixels") == 0 ||
                   strcmp(arg, "-d") == 0 || strcmp(arg, "--diff") == 0) {
            int is_t = arg[1] == 't' || arg[2] == 't', is_d = arg[1] == 'd' || arg[2] == 'd';
            double *target = is_t ? &tolerance : &max_pixels;
            if (i + 1 >= argc)
                return diff_usage("option '%s' needs a value", arg);
            if (is_d) {
                diff_path = argv[++i];
            } else if (diff_number(argv[++i], target) != 0 ||
                       (!is_t && *target != floor(*target))) {
                return diff_usage(is_t ? "--tolerance takes a number of levels >= 0, found "
                                         "'%.40s'"
                                       : "--max-pixels takes a whole number >= 0, found "
                                         "'%.40s'",
                                  argv[i]);
            }
        } else if (strcmp(arg, "-b") == 0 || strcmp(arg, "--box") == 0) {
            char tail;
            if (i + 1 >= argc)
                return diff_usage("option '%s' needs a value", arg);
            box = argv[++i];
            if (sscanf(box, "%dx%d%c", &box_w, &box_h, &tail) != 2 || box_w < 1 || box_h < 1)
                return diff_usage("--box takes WxH, the boxes across and down (as 100x100), "
                                  "found '%.40s'",
                                  box);
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return diff_usage("unknown option '%.40s'", arg);
        } else if (npaths == 2) {
            return diff_usage("too many arguments: '%.40s' after REFERENCE and IMAGE", arg);
        } else {
            paths[npaths++] = arg;
        }
    }
    if (npaths < 2)
        return diff_usage("%s", npaths == 0 ? "missing REFERENCE and IMAGE" : "missing IMAGE");
    if (picture_load(paths[0], &a, &err) != 0) {
        diff_report(&err);
        return 2;
    }
    if (picture_load(paths[1], &b, &err) != 0) {
        diff_report(&err);
        picture_free(&a);
        return 2;
    }
    for (int i = 0; i < 2 && !quiet; i++)
        if ((i ? b.warning : a.warning)[0])
            fprintf(stderr, "raytrace-diff: %s: warning: %s\n", paths[i], i ? b.warning : a.warning);
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "raytrace-diff: error: the sizes differ: %s is %d x %d, %s is %d x %d\n",
                paths[0], a.width, a.height, paths[1], b.width, b.height);
        picture_free(&a);
        picture_free(&b);
        return 2;
    }
    if (clamp) {
        picture_clamp(&a);
        picture_clamp(&b);
    }
    width = a.width;
    height = a.height;
    if (only && box)
        fprintf(stderr, "raytrace-diff: error: --only and --box cannot be combined\n");
    if ((only && box) || (only && diff_select(only, &a, &b) != 0)) {
        picture_free(&a);
        picture_free(&b);
        return 2;
    }
    if (box && (box_w > a.width || box_h > a.height)) {
        fprintf(stderr, "raytrace-diff: error: --box %s: the images are %d x %d, fewer pixels "
                        "than boxes\n",
                box, a.width, a.height);
        picture_free(&a);
        picture_free(&b);
        return 2;
    }
    if (box && (picture_box(&a, box_w, box_h, &err) != 0 || picture_box(&b, box_w, box_h, &err) != 0)) {
        diff_report(&err);
        picture_free(&a);
        picture_free(&b);
        return 2;
    }
    c = compare_pictures(&a, &b, tolerance);
    status = (double)c.over <= max_pixels ? 0 : 1;
    if (!quiet) {
        const double *p = a.rgb + 3 * ((size_t)c.max_y * (size_t)a.width + (size_t)c.max_x);
        const double *q = b.rgb + 3 * ((size_t)c.max_y * (size_t)a.width + (size_t)c.max_x);
        printf("reference: %s: %d x %d, %s\n", paths[0], width, height, a.format);
        printf("image:     %s: %d x %d, %s\n", paths[1], width, height, b.format);
        if (only)
            printf("compared:  the %d pixels not black in %s (numbered in reading order)\n",
                   a.width, only);
        if (box)
            printf("compared:  %d x %d boxes, each the mean of the pixels it covers\n", box_w,
                   box_h);
        if (c.max_error > 0)
            printf("max error: %g at pixel (%d, %d), %s: reference (%g, %g, %g), image (%g, "
                   "%g, %g)\n",
                   c.max_error, c.max_x, c.max_y, channel[c.max_channel], p[0], p[1], p[2],
                   q[0], q[1], q[2]);
        else
            printf("max error: 0 (identical pixels)\n");
        printf("mean error: %.6g, RMS error: %.6g, PSNR: ", c.mean_error, c.rms_error);
        if (isinf(c.psnr))
            printf("infinite\n");
        else
            printf("%.2f dB\n", c.psnr);
        printf("over tolerance %g: %zu of %zu pixels (%.4f%%), at most %.0f allowed: %s\n",
               tolerance, c.over, c.pixels, c.pixels ? 100.0 * (double)c.over / (double)c.pixels : 0,
               max_pixels, status == 0 ? "same" : "DIFFERENT");
        printf("channels over tolerance %g: %zu of %zu (%.4f%%)\n", tolerance, c.channels_over,
               3 * c.pixels,
               c.pixels ? 100.0 * (double)c.channels_over / (3.0 * (double)c.pixels) : 0);
    }
    if (diff_path && diff_write_image(diff_path, &a, &b, tolerance) != 0)
        status = 2;
    picture_free(&a);
    picture_free(&b);
    return status;
}
