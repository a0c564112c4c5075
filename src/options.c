/* options.c: command-line parsing (see options.h). */
#include "options.h"

#include <stdio.h>
#include <string.h>

#include "sampler.h"
#include "trace.h"

enum { OPTIONS_MAX_THREADS = 1024 };

const char *options_help(void)
{
    return "Usage: raytrace [OPTIONS] SCENE OUTPUT\n"
           "Render SCENE, a scene file in the course format, to OUTPUT, a binary PPM\n"
           "image (P6). SCENE may be '-' for standard input, OUTPUT '-' for standard\n"
           "output. OUTPUT is replaced only when the whole image has been written.\n"
           "\n"
           "Options:\n"
           "  -d, --max-depth N  trace mirror and refracted rays down to depth N,\n"
           "                     0 to 1000 (default 10; 0 traces none)\n"
           "  -s, --spp N        take N samples per pixel, 1 to 65536, averaged\n"
           "                     (anti-aliasing; a lens: record blurs with them);\n"
           "                     default: the scene's samples: record, else 1\n"
           "  -j, --threads N    render with N threads, 1 to 1024 (default: one per\n"
           "                     processor; ignored in builds without OpenMP)\n"
           "  -q, --quiet        print nothing on success, even on a terminal\n"
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

/* An option that takes a whole number. */
typedef struct {
    const char *long_name;  /* "--max-depth" */
    const char *short_name; /* "-d" */
    int lo, hi;             /* accepted range */
} IntOption;

/* If argv[*i] is opt (as "--name N", "--name=N", "-x N" or "-xN"), reads its
 * value into *out and returns 1 (or -1 on a bad value, with msg set);
 * returns 0 when argv[*i] is another argument. */
static int options_match_int(const IntOption *opt, int argc, char **argv, int *i, int *out,
                             char *msg, size_t msg_size)
{
    const char *arg = argv[*i], *value;
    size_t ln = strlen(opt->long_name), sn = strlen(opt->short_name);

    if (strcmp(arg, opt->long_name) == 0 || strcmp(arg, opt->short_name) == 0) {
        if (*i + 1 >= argc) {
            snprintf(msg, msg_size, "option '%s' needs a value", arg);
            return -1;
        }
        value = argv[++*i];
    } else if (strncmp(arg, opt->long_name, ln) == 0 && arg[ln] == '=') {
        value = arg + ln + 1;
    } else if (strncmp(arg, opt->short_name, sn) == 0 && arg[sn] != '\0' && arg[1] != '-') {
        value = arg + sn;
    } else {
        return 0;
    }
    if (options_int(value, opt->lo, opt->hi, out) != 0) {
        snprintf(msg, msg_size, "option '%s' takes a whole number from %d to %d, found '%.40s'",
                 opt->long_name, opt->lo, opt->hi, value);
        return -1;
    }
    return 1;
}

OptionsAction options_parse(Options *opts, int argc, char **argv, int default_threads, char *msg,
                            size_t msg_size)
{
    static const IntOption depth = {"--max-depth", "-d", 0, TRACE_MAX_DEPTH_LIMIT};
    static const IntOption threads = {"--threads", "-j", 1, OPTIONS_MAX_THREADS};
    static const IntOption spp = {"--spp", "-s", 1, SAMPLER_MAX};
    const char *positional[2];
    int npos = 0, only_positional = 0;

    opts->scene_path = opts->output_path = NULL;
    opts->max_depth = 10;
    opts->threads = default_threads;
    opts->quiet = 0;
    opts->samples = 0;
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
        } else if ((m = options_match_int(&depth, argc, argv, &i, &opts->max_depth, msg,
                                          msg_size)) != 0 ||
                   (m = options_match_int(&threads, argc, argv, &i, &opts->threads, msg,
                                          msg_size)) != 0 ||
                   (m = options_match_int(&spp, argc, argv, &i, &opts->samples, msg,
                                          msg_size)) != 0) {
            if (m < 0)
                return OPTIONS_USAGE;
        } else {
            snprintf(msg, msg_size, "unknown option '%.40s'", arg);
            return OPTIONS_USAGE;
        }
    }
    if (npos < 2) {
        snprintf(msg, msg_size, npos == 0 ? "missing SCENE and OUTPUT" : "missing OUTPUT");
        return OPTIONS_USAGE;
    }
    if (!*positional[0] || !*positional[1]) {
        snprintf(msg, msg_size, "%s is an empty file name", *positional[0] ? "OUTPUT" : "SCENE");
        return OPTIONS_USAGE;
    }
    opts->scene_path = positional[0];
    opts->output_path = positional[1];
    return OPTIONS_RENDER;
}
