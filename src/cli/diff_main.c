/*
 * diff_main.c: the raytrace-diff command: compares a render with a
 * reference and says how far apart they are. The only code of the command
 * that prints or exits; the work is in compare.c.
 *
 * Exit status: 0 within tolerance, 1 different, 2 trouble (an unreadable
 * image, different sizes, a bad command line).
 */
#define _POSIX_C_SOURCE 200809L

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/outfile.h"
#include "base/process.h"
#include "cli/args.h"
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
    "both values, the mean and RMS differences, the PSNR, the error that the\n"
    "worst 1% of pixels pass (a pixel's: the RMS of its channels), and the\n"
    "number of pixels over the tolerance.\n"
    "\n"
    "Exit status: 0 at most --max-pixels pixels exceed the tolerance; 1 more\n"
    "do; 2 an image cannot be read, the sizes differ, or the command line is\n"
    "wrong.\n";

/* The command line. */
typedef struct {
    double tolerance;           /* -t: levels a channel may differ by */
    size_t max_pixels;          /* -m: pixels that may exceed it */
    const char *diff_path;      /* -d FILE, or NULL */
    const char *box;            /* -b WxH as given, or NULL */
    int box_w, box_h;           /* its W and H */
    const char *only;           /* -o MASK, or NULL */
    int clamp, quiet;           /* -c, -q */
    const char *paths[2];       /* REFERENCE and IMAGE */
} DiffOptions;

enum { DIFF_HELP = 1, DIFF_SHOW_VERSION };

#define DIFF_OPT(name, kind, field) name, kind, offsetof(DiffOptions, field)
static const ArgSpec diff_specs[] = {
    {"--tolerance", DIFF_OPT("-t", ARG_REAL, tolerance), 0, INFINITY, NULL, 0},
    {"--max-pixels", DIFF_OPT("-m", ARG_COUNT, max_pixels), 0, 0, NULL, 0},
    {"--diff", DIFF_OPT("-d", ARG_TEXT, diff_path), 0, 0, NULL, 0},
    {"--box", DIFF_OPT("-b", ARG_TEXT, box), 0, 0, NULL, 0},
    {"--only", DIFF_OPT("-o", ARG_TEXT, only), 0, 0, NULL, 0},
    {"--clamp", DIFF_OPT("-c", ARG_FLAG, clamp), 0, 0, NULL, 0},
    {"--quiet", DIFF_OPT("-q", ARG_FLAG, quiet), 0, 0, NULL, 0},
    {"--help", "-h", ARG_ACT, 0, 0, 0, NULL, DIFF_HELP},
    {"--version", "-V", ARG_ACT, 0, 0, 0, NULL, DIFF_SHOW_VERSION},
};
#undef DIFF_OPT

/* Prints a usage error; returns the exit status 2. */
static int diff_usage(const char *msg)
{
    fprintf(stderr, "raytrace-diff: %s\nTry 'raytrace-diff --help'.\n", msg);
    return 2;
}

/* Reads the command line into *o; returns -1 to go on, else the exit
 * status after printing the help, the version or a usage error. */
static int diff_options(int argc, char **argv, DiffOptions *o)
{
    static const ArgTable table = {diff_specs, sizeof diff_specs / sizeof diff_specs[0], 2,
                                   "REFERENCE and IMAGE"};
    char msg[512];
    int n, rc;

    memset(o, 0, sizeof *o);
    rc = args_parse(&table, o, argc, argv, o->paths, &n, msg, sizeof msg);
    if (rc == DIFF_HELP) {
        fputs(diff_help, stdout);
        return 0;
    }
    if (rc == DIFF_SHOW_VERSION) {
        puts("raytrace-diff " DIFF_VERSION);
        return 0;
    }
    if (rc < 0)
        return diff_usage(msg);
    if (n < 2)
        return diff_usage(n == 0 ? "missing REFERENCE and IMAGE" : "missing IMAGE");
    if (o->box && args_pair(o->box, 'x', 1, INT_MAX, &o->box_w, &o->box_h) != 0) {
        snprintf(msg, sizeof msg,
                 "--box takes WxH, the boxes across and down (as 100x100), found '%.40s'",
                 o->box);
        return diff_usage(msg);
    }
    if (o->only && o->box)
        return diff_usage("--only and --box cannot be combined");
    if (o->diff_path && writer_unwritable(o->diff_path)) {
        snprintf(msg, sizeof msg,
                 "--diff '%.60s': raytrace-diff cannot write %s images; it writes " WRITER_FORMATS,
                 o->diff_path, writer_unwritable(o->diff_path));
        return diff_usage(msg);
    }
    return -1;
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

/* Writes the diff image of a and b to path. */
static int diff_write_image(const char *path, const Picture *a, const Picture *b,
                            double tolerance)
{
    WriterOptions wopts = {.format = writer_format_for(path), .png_deflate = DEFLATE_FIXED,
                           .jpeg_quality = 95, .jpeg_444 = 1};
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

/* Reads both pictures of o into *a and *b and makes them ready to compare
 * (clamped, masked or boxed as o says); returns 0, or -1 after saying why
 * not. */
static int diff_load(const DiffOptions *o, Picture *a, Picture *b)
{
    Error err;

    if (picture_load(o->paths[0], a, &err) != 0 || picture_load(o->paths[1], b, &err) != 0) {
        diff_report(&err);
        return -1;
    }
    for (int i = 0; i < 2 && !o->quiet; i++)
        if ((i ? b : a)->warning[0])
            fprintf(stderr, "raytrace-diff: %s: warning: %s\n", o->paths[i], (i ? b : a)->warning);
    if (a->width != b->width || a->height != b->height) {
        fprintf(stderr, "raytrace-diff: error: the sizes differ: %s is %d x %d, %s is %d x %d\n",
                o->paths[0], a->width, a->height, o->paths[1], b->width, b->height);
        return -1;
    }
    if (o->clamp) {
        picture_clamp(a);
        picture_clamp(b);
    }
    if (o->only)
        return diff_select(o->only, a, b);
    if (o->box && (o->box_w > a->width || o->box_h > a->height)) {
        fprintf(stderr, "raytrace-diff: error: --box %s: the images are %d x %d, fewer pixels "
                        "than boxes\n",
                o->box, a->width, a->height);
        return -1;
    }
    if (o->box && (picture_box(a, o->box_w, o->box_h, &err) != 0 ||
                   picture_box(b, o->box_w, o->box_h, &err) != 0)) {
        diff_report(&err);
        return -1;
    }
    return 0;
}

/* Prints comparison c of a and b (of size width x height before boxes). */
static void diff_print(const DiffOptions *o, const Picture *a, const Picture *b,
                       const Comparison *c, int width, int height)
{
    static const char *const channel[3] = {"red", "green", "blue"};
    const double *p = a->rgb + 3 * ((size_t)c->max_y * (size_t)a->width + (size_t)c->max_x);
    const double *q = b->rgb + 3 * ((size_t)c->max_y * (size_t)a->width + (size_t)c->max_x);
    double pixels = (double)c->pixels;

    printf("reference: %s: %d x %d, %s\n", o->paths[0], width, height, a->format);
    printf("image:     %s: %d x %d, %s\n", o->paths[1], width, height, b->format);
    if (o->only)
        printf("compared:  the %d pixels not black in %s (numbered in reading order)\n",
               a->width, o->only);
    if (o->box)
        printf("compared:  %d x %d boxes, each the mean of the pixels it covers\n", o->box_w,
               o->box_h);
    if (c->max_error > 0)
        printf("max error: %g at pixel (%d, %d), %s: reference (%g, %g, %g), image (%g, "
               "%g, %g)\n",
               c->max_error, c->max_x, c->max_y, channel[c->max_channel], p[0], p[1], p[2], q[0],
               q[1], q[2]);
    else
        printf("max error: 0 (identical pixels)\n");
    printf("mean error: %.6g, RMS error: %.6g, PSNR: ", c->mean_error, c->rms_error);
    if (isinf(c->psnr))
        printf("infinite\n");
    else
        printf("%.2f dB\n", c->psnr);
    printf("worst 1%% of pixels: error over %s%g (a pixel's: the RMS of its channels)\n",
           c->worst >= COMPARE_WORST_CAP ? "at least " : "", c->worst);
    printf("over tolerance %g: %zu of %zu pixels (%.4f%%), at most %zu allowed: %s\n",
           o->tolerance, c->over, c->pixels, pixels > 0 ? 100.0 * (double)c->over / pixels : 0,
           o->max_pixels, c->over <= o->max_pixels ? "same" : "DIFFERENT");
    printf("channels over tolerance %g: %zu of %zu (%.4f%%)\n", o->tolerance, c->channels_over,
           3 * c->pixels, pixels > 0 ? 100.0 * (double)c->channels_over / (3.0 * pixels) : 0);
}

int main(int argc, char **argv)
{
    DiffOptions o;
    Picture a = {0}, b = {0};
    Comparison c;
    int status = 2, width, height;

    process_init(&argc, &argv);
    if ((status = diff_options(argc, argv, &o)) >= 0)
        return status;
    status = 2;
    if (diff_load(&o, &a, &b) == 0) {
        width = a.width;
        height = a.height;
        c = compare_pictures(&a, &b, o.tolerance);
        status = c.over <= o.max_pixels ? 0 : 1;
        if (!o.quiet)
            diff_print(&o, &a, &b, &c, width, height);
        if (o.diff_path && diff_write_image(o.diff_path, &a, &b, o.tolerance) != 0)
            status = 2;
    }
    picture_free(&a);
    picture_free(&b);
    return status;
}
