/* options.c: command-line parsing (see options.h). */
#include "cli/options.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "math/number.h"
#include "render/sampler.h"
#include "image/writer.h"
#include "render/trace.h"

enum { OPTIONS_MAX_THREADS = 1024 };

const char *options_help(void)
{
    return "Usage: raytrace [OPTIONS] SCENE OUTPUT\n"
           "       raytrace --check SCENE\n"
           "       raytrace --save OUT SCENE\n"
           "Render SCENE, a scene file in the course format or in seed 002's keyword\n"
           "format (told apart by content), to OUTPUT: a PPM (P6), PNG or PFM image,\n"
           "chosen by OUTPUT's extension (.ppm, .png, .pfm; PPM for any other) or\n"
           "by --format. SCENE may be '-' for standard input,\n"
           "OUTPUT '-' for standard output. OUTPUT is replaced only when the whole\n"
           "image has been written.\n"
           "\n"
           "Options:\n"
           "  -d, --max-depth N  trace mirror and refracted rays down to depth N,\n"
           "                     0 to 1000 (default 10; 0 traces none)\n"
           "  -s, --spp N        take N samples per pixel, 1 to 65536, averaged\n"
           "                     (anti-aliasing; a lens: record blurs with them);\n"
           "                     default: the scene's samples: record, else 1\n"
           "  --cutoff L         leave out mirror, refracted and shadow rays that could\n"
           "                     add less than L levels (0 to 255, default 0.1) to a\n"
           "                     pixel; in pixels near a rounding boundary they are\n"
           "                     traced after all, with smaller cut-offs, then in\n"
           "                     full, so the bytes never change (0: off)\n"
           "  --memory-limit M   fail early, before allocating, when the scene, its\n"
           "                     hierarchy and the image would need more than M\n"
           "                     bytes (suffix K, M or G: powers of 1024; default\n"
           "                     4G; 0: no limit)\n"
           "  -j, --threads N    read, build and render with N threads, 1 to 1024\n"
           "                     (default: one per processor; ignored in builds\n"
           "                     without OpenMP)\n"
           "  --format F         write F: ppm, png or pfm (linear floats, unclamped)\n"
           "  --ascii            write PPM as ASCII (P3) instead of binary (P6)\n"
           "  --png-deflate M    compress PNG with M: fixed (Huffman codes, the\n"
           "                     default) or stored (no compression, faster)\n"
           "  --check            read SCENE, report any error, render nothing\n"
           "  --save OUT         read SCENE, a keyword-format scene, and write it to OUT\n"
           "                     in the keyword format, every number exact; render\n"
           "                     nothing\n"
           "  --scene-format F   read SCENE as F: course, keyword, or auto (the\n"
           "                     default: keyword when its first element is a word)\n"
           "  --no-accel         test every ray against every object (no bounding\n"
           "                     volume hierarchy): slower, the same image\n"
           "  -v, --verbose      after rendering, print the image size, threads, rays\n"
           "                     cast by kind, time and speed\n"
           "  -q, --quiet        print nothing on success, not even the progress bar\n"
           "  -h, --help         print this help and exit\n"
           "  -V, --version      print the version and exit\n"
           "\n"
           "Exit status: 0 the image was written; 1 the scene or an output could not be\n"
           "read or written (the message says where); 2 the command line is wrong;\n"
           "130 or 143 interrupted by SIGINT or SIGTERM.\n"
           "\n"
           "The scene format is described in docs/scene-format.md.\n";
}

/* Reads the whole number in text, between lo and hi, into *out. */
static int options_int(const char *text, int lo, int hi, int *out)
{
    long v = 0;

    if (!*text)
        return -1;
    for (const char *p = text; *p; p++) {
        if (*p < '0' || *p > '9')
            return -1;
        v = v * 10 + (*p - '0');
        if (v > hi)
            return -1;
    }
    if (v < lo)
        return -1;
    *out = (int)v;
    return 0;
}

/* Reads a size in bytes, "0" or whole digits with an optional K, M or G
 * (powers of 1024), into *out; returns 0, or -1 when it is none or too large. */
static int options_size(const char *text, size_t *out)
{
    size_t v = 0, unit = 1;
    const char *p = text;

    if (*p < '0' || *p > '9')
        return -1;
    for (; *p >= '0' && *p <= '9'; p++) {
        if (v > (SIZE_MAX - 9) / 10)
            return -1;
        v = v * 10 + (size_t)(*p - '0');
    }
    if (*p == 'K' || *p == 'k')
        unit = (size_t)1 << 10;
    else if (*p == 'M' || *p == 'm')
        unit = (size_t)1 << 20;
    else if (*p == 'G' || *p == 'g')
        unit = (size_t)1 << 30;
    if (unit > 1)
        p++;
    if (*p || v > SIZE_MAX / unit)
        return -1;
    *out = v * unit;
    return 0;
}

/* An option that takes a whole number. */
typedef struct {
    const char *long_name;  /* "--max-depth" */
    const char *short_name; /* "-d" */
    int lo, hi;             /* accepted range */
} IntOption;

/* If argv[*i] is the option long_name (or short_name, which may be NULL),
 * as "--name V", "--name=V", "-x V" or "-xV", points *value at V and
 * returns 1 (or -1 when V is missing, with msg set); returns 0 when
 * argv[*i] is another argument. */
static int options_match_value(const char *long_name, const char *short_name, int argc,
                               char **argv, int *i, const char **value, char *msg,
                               size_t msg_size)
{
    const char *arg = argv[*i];
    size_t ln = strlen(long_name), sn = short_name ? strlen(short_name) : 0;

    if (strcmp(arg, long_name) == 0 || (short_name && strcmp(arg, short_name) == 0)) {
        if (*i + 1 >= argc) {
            snprintf(msg, msg_size, "option '%s' needs a value", arg);
            return -1;
        }
        *value = argv[++*i];
    } else if (strncmp(arg, long_name, ln) == 0 && arg[ln] == '=') {
        *value = arg + ln + 1;
    } else if (short_name && strncmp(arg, short_name, sn) == 0 && arg[sn] != '\0' &&
               arg[1] != '-') {
        *value = arg + sn;
    } else {
        return 0;
    }
    return 1;
}

/* If argv[*i] is the option long_name, reads its value, a decimal number
 * from lo to hi, into *out and returns 1 (or -1 on a bad value, with msg
 * set); returns 0 when argv[*i] is another argument. */
static int options_match_real(const char *long_name, double lo, double hi, int argc, char **argv,
                              int *i, double *out, char *msg, size_t msg_size)
{
    const char *value;
    int m = options_match_value(long_name, NULL, argc, argv, i, &value, msg, msg_size);
    double v;

    if (m <= 0)
        return m;
    if (number_parse(value, strlen(value), &v) != NUMBER_OK || !(v >= lo && v <= hi)) {
        snprintf(msg, msg_size, "option '%s' takes a number from %g to %g, found '%.40s'",
                 long_name, lo, hi, value);
        return -1;
    }
    *out = v;
    return 1;
}

/* If argv[*i] is the option long_name, reads its value, a size (see
 * options_size()), into *out and returns 1 (or -1 on a bad value, with msg
 * set); returns 0 when argv[*i] is another argument. */
static int options_match_size(const char *long_name, int argc, char **argv, int *i, size_t *out,
                              char *msg, size_t msg_size)
{
    const char *value;
    int m = options_match_value(long_name, NULL, argc, argv, i, &value, msg, msg_size);

    if (m <= 0)
        return m;
    if (options_size(value, out) != 0) {
        snprintf(msg, msg_size, "option '%s' takes a size in bytes such as 512M or 8G (0: no "
                                "limit), found '%.40s'", long_name, value);
        return -1;
    }
    return 1;
}

/* If argv[*i] is opt, reads its value into *out and returns 1 (or -1 on a
 * bad value, with msg set); returns 0 when argv[*i] is another argument. */
static int options_match_int(const IntOption *opt, int argc, char **argv, int *i, int *out,
                             char *msg, size_t msg_size)
{
    const char *value;
    int m = options_match_value(opt->long_name, opt->short_name, argc, argv, i, &value, msg,
                                msg_size);

    if (m <= 0)
        return m;
    if (options_int(value, opt->lo, opt->hi, out) != 0) {
        snprintf(msg, msg_size, "option '%s' takes a whole number from %d to %d, found '%.40s'",
                 opt->long_name, opt->lo, opt->hi, value);
        return -1;
    }
    return 1;
}

/* If argv[*i] is the option long_name, whose value must be one of the
 * count words of choices, stores the index of the word in *out and returns
 * 1 (or -1 on another value, with msg set); returns 0 for another argument. */
static int options_match_word(const char *long_name, const char *const *choices, int count,
                              int argc, char **argv, int *i, int *out, char *msg,
                              size_t msg_size)
{
    const char *value;
    int m = options_match_value(long_name, NULL, argc, argv, i, &value, msg, msg_size);

    if (m <= 0)
        return m;
    for (int k = 0; k < count; k++) {
        if (strcmp(value, choices[k]) == 0) {
            *out = k;
            return 1;
        }
    }
    {
        size_t n = (size_t)snprintf(msg, msg_size, "option '%s' takes ", long_name);
        for (int k = 0; k < count && n < msg_size; k++)
            n += (size_t)snprintf(msg + n, msg_size - n, "%s%s",
                                  k == 0 ? "" : k == count - 1 ? " or " : ", ", choices[k]);
        if (n < msg_size)
            snprintf(msg + n, msg_size - n, ", found '%.40s'", value);
    }
    return -1;
}

OptionsAction options_parse(Options *opts, int argc, char **argv, int default_threads, char *msg,
                            size_t msg_size)
{
    static const IntOption depth = {"--max-depth", "-d", 0, TRACE_MAX_DEPTH_LIMIT};
    static const IntOption threads = {"--threads", "-j", 1, OPTIONS_MAX_THREADS};
    static const IntOption spp = {"--spp", "-s", 1, SAMPLER_MAX};
    static const char *const formats[] = {"ppm", "png", "pfm"};
    static const char *const deflates[] = {"stored", "fixed"};
    static const char *const scene_formats[] = {"course", "keyword", "auto"};
    const char *positional[2];
    int npos = 0, only_positional = 0, deflate = 1, scene_format = 2;

    opts->scene_path = opts->output_path = NULL;
    opts->max_depth = 10;
    opts->threads = default_threads;
    opts->quiet = 0;
    opts->verbose = 0;
    opts->check = 0;
    opts->samples = 0;
    opts->format = -1;
    opts->ascii = 0;
    opts->no_accel = 0;
    opts->save_path = NULL;
    opts->cutoff = OPTIONS_DEFAULT_CUTOFF;
    opts->memory_limit = OPTIONS_DEFAULT_MEMORY_LIMIT;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        int m;

        if (only_positional || arg[0] != '-' || strcmp(arg, "-") == 0) {
            if (npos == 2) {
                snprintf(msg, msg_size, "too many arguments: '%.40s' after SCENE and OUTPUT",
                         arg);
                return OPTIONS_USAGE;
            }
            positional[npos++] = arg;
        } else if (strcmp(arg, "--") == 0) {
            only_positional = 1;
        } else if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
            return OPTIONS_HELP;
        } else if (strcmp(arg, "-V") == 0 || strcmp(arg, "--version") == 0) {
            return OPTIONS_VERSION;
        } else if (strcmp(arg, "-q") == 0 || strcmp(arg, "--quiet") == 0) {
            opts->quiet = 1;
        } else if (strcmp(arg, "-v") == 0 || strcmp(arg, "--verbose") == 0) {
            opts->verbose = 1;
        } else if (strcmp(arg, "--check") == 0) {
            opts->check = 1;
        } else if (strcmp(arg, "--ascii") == 0) {
            opts->ascii = 1;
        } else if (strcmp(arg, "--no-accel") == 0) {
            opts->no_accel = 1;
        } else if ((m = options_match_int(&depth, argc, argv, &i, &opts->max_depth, msg,
                                          msg_size)) != 0 ||
                   (m = options_match_int(&threads, argc, argv, &i, &opts->threads, msg,
                                          msg_size)) != 0 ||
                   (m = options_match_int(&spp, argc, argv, &i, &opts->samples, msg,
                                          msg_size)) != 0 ||
                   (m = options_match_word("--format", formats, 3, argc, argv, &i,
                                           &opts->format, msg, msg_size)) != 0 ||
                   (m = options_match_word("--png-deflate", deflates, 2, argc, argv, &i,
                                           &deflate, msg, msg_size)) != 0 ||
                   (m = options_match_word("--scene-format", scene_formats, 3, argc, argv, &i,
                                           &scene_format, msg, msg_size)) != 0 ||
                   (m = options_match_value("--save", NULL, argc, argv, &i, &opts->save_path,
                                            msg, msg_size)) != 0 ||
                   (m = options_match_real("--cutoff", 0, 255, argc, argv, &i, &opts->cutoff,
                                           msg, msg_size)) != 0 ||
                   (m = options_match_size("--memory-limit", argc, argv, &i,
                                           &opts->memory_limit, msg, msg_size)) != 0) {
            if (m < 0)
                return OPTIONS_USAGE;
        } else {
            snprintf(msg, msg_size, "unknown option '%.40s'", arg);
            return OPTIONS_USAGE;
        }
    }
    opts->png_stored = deflate == 0;
    opts->scene_format = scene_format == 2 ? -1 : scene_format;
    if (opts->check && opts->save_path) {
        snprintf(msg, msg_size, "--check and --save cannot be combined");
        return OPTIONS_USAGE;
    }
    if (opts->save_path && !*opts->save_path) {
        snprintf(msg, msg_size, "--save needs a file name");
        return OPTIONS_USAGE;
    }
    if (npos < (opts->check || opts->save_path ? 1 : 2)) {
        snprintf(msg, msg_size, npos == 0 ? "missing SCENE and OUTPUT" : "missing OUTPUT");
        if (opts->check || opts->save_path)
            snprintf(msg, msg_size, "missing SCENE");
        return OPTIONS_USAGE;
    }
    if ((opts->check || opts->save_path) && npos > 1) {
        snprintf(msg, msg_size, "%s takes only SCENE, found '%.40s' after it",
                 opts->check ? "--check" : "--save OUT", positional[1]);
        return OPTIONS_USAGE;
    }
    if (!*positional[0] || (npos > 1 && !*positional[1])) {
        snprintf(msg, msg_size, "%s is an empty file name", *positional[0] ? "OUTPUT" : "SCENE");
        return OPTIONS_USAGE;
    }
    opts->scene_path = positional[0];
    opts->output_path = npos > 1 ? positional[1] : NULL;
    if (opts->format < 0 && opts->output_path)
        opts->format = (int)writer_format_for(opts->output_path);
    if (opts->ascii && opts->output_path && opts->format != FORMAT_PPM) {
        snprintf(msg, msg_size, "--ascii applies to PPM output only");
        return OPTIONS_USAGE;
    }
    return opts->check ? OPTIONS_CHECK : opts->save_path ? OPTIONS_SAVE : OPTIONS_RENDER;
}
