/* options.c: command-line parsing (see options.h). */
#include "cli/options.h"

#include <ctype.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "image/tile.h"
#include "image/writer.h"
#include "math/number.h"
#include "render/noise.h"
#include "render/sampler.h"
#include "render/tracer.h"
#include "scene/scene.h"

enum { OPTIONS_MAX_THREADS = 1024 };

const char *const *options_help(void)
{
    static const char *const parts[] = {
        "Usage: raytrace [OPTIONS] SCENE OUTPUT\n"
        "       raytrace --check SCENE\n"
        "       raytrace --save OUT SCENE\n"
        "Render SCENE, a scene file in the course format, seed 002's keyword format\n"
        "or seed 001's MPL format (told apart by content), to OUTPUT: a PPM (P6),\n"
        "PNG, PFM or JPEG image, chosen by OUTPUT's extension (.ppm, .png, .pfm,\n"
        ".jpg, .jpeg; PPM for any other) or by --format. Textures may be PPM, PNG,\n"
        "JPEG or BMP files. SCENE may be '-' for standard input, OUTPUT '-' for\n"
        "standard output. OUTPUT is replaced only when the whole image has been\n"
        "written.\n"
        "\n"
        "Options:\n",
        "  -d, --max-depth N  trace mirror and refracted rays down to depth N,\n"
        "                     0 to 1000 (default 10, seed 001's model 99; 0 traces\n"
        "                     none)\n"
        "  -s, --spp N        take N samples per pixel, 1 to 65536, averaged\n"
        "                     (anti-aliasing; a lens: record blurs with them);\n"
        "                     default: the scene's samples: record, else 1 (MPL\n"
        "                     scenes: 4)\n"
        "  --noise L          take as many samples a pixel as it needs for its\n"
        "                     estimated error to be at most L levels (0 to 255;\n"
        "                     one standard error: 68% of pixels within L of the\n"
        "                     converged picture; 0: off), camera, lens, occlusion\n"
        "                     and gathering rays together; wins over -s\n"
        "  --min-spp N        under --noise, at least N samples a pixel (default\n"
        "                     64 / L rounded up to a power of two, 16 to 256)\n"
        "  --max-spp N        under --noise, at most N samples a pixel (default\n"
        "                     4096; up to 1048576)\n"
        "  --spp-map FILE     under --noise, also write a heat map of the samples\n"
        "                     each pixel took (black: --min-spp, white: --max-spp)\n"
        "  --texture-filter F read every texture and seed 001's stripes with F:\n"
        "                     nearest, bilinear, trilinear (mip-maps: the pixel's\n"
        "                     footprint averaged, followed by ray differentials\n"
        "                     through mirrors and glass) or ewa (an elliptical\n"
        "                     Gaussian over the footprint, sharper at grazing\n"
        "                     angles); default: the scene's (course texture:\n"
        "                     records bilinear, MPL materials trilinear)\n",
        "  --size WxH         render W x H pixels (1 to 32768 each) of the scene's\n"
        "                     view, its height kept (default: the scene's size)\n"
        "  --model M          light an MPL scene by M: seed001 (the default: seed\n"
        "                     001's program's rules, its occlusion and gathering,\n"
        "                     gamma 2.2) or physical (the keyword format's\n"
        "                     Blinn-Phong, physically based occlusion and\n"
        "                     gathered light, linear bytes)\n"
        "  --no-shadows       cast no shadow rays: every light reaches every point\n"
        "                     that faces it\n"
        "  --strict           refuse the MPL lines seed 001's program read despite\n"
        "                     the format (1.5abc, words after a primitive's\n"
        "                     material, an unknown or repeated material, numbers\n"
        "                     after a light's), which are otherwise read as it\n"
        "                     read them, with a warning each\n"
        "  --cutoff L         leave out mirror, refracted and shadow rays that could\n"
        "                     add less than L levels (0 to 255, default 0.1) to a\n"
        "                     pixel; in pixels near a rounding boundary they are\n"
        "                     traced after all, with smaller cut-offs, then in\n"
        "                     full, so the bytes never change (0: off)\n"
        "  --ao N             ambient occlusion: N rays per point the camera sees\n"
        "                     (0 to 4096) darken its ambient light by the share\n"
        "                     they find hidden (default: the scene's, else 0;\n"
        "                     seed 001's model: 10 rays at every point, darkening\n"
        "                     all its light)\n"
        "  --ao-distance D    what is nearer than D hides (default: the scene's,\n"
        "                     else a tenth of the diagonal of its objects' box;\n"
        "                     seed 001's model: 2)\n"
        "  --gi N             global illumination: N rays per point the camera\n"
        "                     sees (0 to 4096) gather the light other surfaces\n"
        "                     reflect onto its diffuse part (default: 0; seed\n"
        "                     001's model: 10 rays gathering the colours they meet)\n"
        "  --gi-bounces B     diffuse bounces gathered, 1 to 64 (default 1)\n"
        "  --tile K/N         render only the K-th of N tiles (1 <= K <= N <= 65536)\n"
        "                     to OUTPUT, a PPM, PNG or PFM that records where it\n"
        "                     belongs; raytrace-merge puts the tiles together\n"
        "  --tile-layout L    rows (the default: every N-th row, even loads) or\n"
        "                     bands (N pieces, top to bottom)\n"
        "  --memory-limit M   fail early, before allocating, when the scene, its\n"
        "                     hierarchy and the image would need more than M\n"
        "                     bytes (suffix K, M or G: powers of 1024; default\n"
        "                     4G; 0: no limit)\n"
        "  -j, --threads N    read, build and render with N threads, 1 to 1024\n"
        "                     (default: one per processor; ignored in builds\n"
        "                     without OpenMP)\n",
        "  --format F         write F: ppm, png, pfm (linear floats, unclamped) or\n"
        "                     jpeg (lossy: smaller files, not the exact bytes)\n"
        "  --jpeg-quality Q   JPEG quality, 1 to 100 (default 90)\n"
        "  --jpeg-subsampling S  JPEG chroma: 420 (halved both ways, the default)\n"
        "                     or 444 (whole: sharp coloured edges)\n"
        "  --ascii            write PPM as ASCII (P3) instead of binary (P6)\n"
        "  --png-deflate M    compress PNG with M: fixed (Huffman codes, the\n"
        "                     default) or stored (no compression, faster)\n"
        "  --check            read SCENE, report any error, render nothing\n"
        "  --save OUT         read SCENE, a keyword- or MPL-format scene, and write\n"
        "                     it to OUT in its format, every number exact; render\n"
        "                     nothing\n"
        "  --scene-format F   read SCENE as F: course, keyword, mpl, or auto (the\n"
        "                     default: mpl when its first element is m, p, l or c,\n"
        "                     keyword when it is another word, else course)\n"
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
        "The scene formats are described in docs/scene-format.md.\n",
        NULL};

    return parts;
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

/* What an option is, and where its value goes. */
typedef enum {
    OPTION_FLAG, /* no value: the int field is set to 1 */
    OPTION_INT,  /* a whole number from lo to hi, into an int field */
    OPTION_REAL, /* a decimal number from lo to hi, into a double field */
    OPTION_SIZE, /* a size in bytes (options_size()), into a size_t field */
    OPTION_WORD, /* one of words, whose value goes into an int field */
    OPTION_TEXT, /* any string, into a const char * field */
    OPTION_ACT   /* no value: options_parse() returns `act` at once */
} OptionKind;

/* A word an option may take, and the value it stands for. */
typedef struct {
    const char *word;
    int value;
} OptionWord;

/* An option of the command line. */
typedef struct {
    const char *long_name;  /* "--max-depth" */
    const char *short_name; /* "-d", or NULL */
    OptionKind kind;
    size_t field;           /* offsetof(Options, its field) */
    double lo, hi;          /* INT and REAL: the accepted range */
    const OptionWord *words; /* WORD: its words, ending with a NULL word */
    OptionsAction act;      /* ACT: what it asks for */
} OptionSpec;

static const OptionWord options_formats[] = {{"ppm", FORMAT_PPM},   {"png", FORMAT_PNG},
                                             {"pfm", FORMAT_PFM},   {"jpeg", FORMAT_JPEG},
                                             {"jpg", FORMAT_JPEG}, {NULL, 0}};
static const OptionWord options_subsampling[] = {{"420", 0}, {"444", 1}, {NULL, 0}};
static const OptionWord options_layouts[] = {{"rows", TILE_ROWS}, {"bands", TILE_BANDS}, {NULL, 0}};
static const OptionWord options_filters[] = {{"nearest", TEXTURE_NEAREST},
                                            {"bilinear", TEXTURE_BILINEAR},
                                            {"trilinear", TEXTURE_TRILINEAR},
                                            {"ewa", TEXTURE_EWA},
                                            {NULL, 0}};
static const OptionWord options_deflates[] = {{"stored", 1}, {"fixed", 0}, {NULL, 0}};
static const OptionWord options_models[] = {{"seed001", SCENE_MODEL_SEED001},
                                           {"physical", SCENE_MODEL_PHYSICAL},
                                           {NULL, 0}};
static const OptionWord options_scene_formats[] = {{"course", SCENE_COURSE},
                                                    {"keyword", SCENE_KEYWORD},
                                                    {"mpl", SCENE_MPL},
                                                    {"auto", SCENE_AUTO},
                                                    {NULL, 0}};

#define OPT(name, kind, field) name, kind, offsetof(Options, field)
static const OptionSpec options_table[] = {
    {"--help", "-h", OPTION_ACT, 0, 0, 0, NULL, OPTIONS_HELP},
    {"--version", "-V", OPTION_ACT, 0, 0, 0, NULL, OPTIONS_VERSION},
    {"--quiet", OPT("-q", OPTION_FLAG, quiet), 0, 0, NULL, 0},
    {"--verbose", OPT("-v", OPTION_FLAG, verbose), 0, 0, NULL, 0},
    {"--check", OPT(NULL, OPTION_FLAG, check), 0, 0, NULL, 0},
    {"--ascii", OPT(NULL, OPTION_FLAG, ascii), 0, 0, NULL, 0},
    {"--no-accel", OPT(NULL, OPTION_FLAG, no_accel), 0, 0, NULL, 0},
    {"--no-shadows", OPT(NULL, OPTION_FLAG, no_shadows), 0, 0, NULL, 0},
    {"--strict", OPT(NULL, OPTION_FLAG, strict), 0, 0, NULL, 0},
    {"--model", OPT(NULL, OPTION_WORD, model), 0, 0, options_models, 0},
    {"--size", OPT(NULL, OPTION_TEXT, size), 0, 0, NULL, 0},
    {"--max-depth", OPT("-d", OPTION_INT, max_depth), 0, TRACE_MAX_DEPTH_LIMIT, NULL, 0},
    {"--threads", OPT("-j", OPTION_INT, threads), 1, OPTIONS_MAX_THREADS, NULL, 0},
    {"--spp", OPT("-s", OPTION_INT, samples), 1, SAMPLER_MAX, NULL, 0},
    {"--format", OPT(NULL, OPTION_WORD, format), 0, 0, options_formats, 0},
    {"--png-deflate", OPT(NULL, OPTION_WORD, png_stored), 0, 0, options_deflates, 0},
    {"--scene-format", OPT(NULL, OPTION_WORD, scene_format), 0, 0, options_scene_formats, 0},
    {"--save", OPT(NULL, OPTION_TEXT, save_path), 0, 0, NULL, 0},
    {"--cutoff", OPT(NULL, OPTION_REAL, cutoff), 0, 255, NULL, 0},
    {"--memory-limit", OPT(NULL, OPTION_SIZE, memory_limit), 0, 0, NULL, 0},
    {"--jpeg-quality", OPT(NULL, OPTION_INT, jpeg_quality), 1, 100, NULL, 0},
    {"--jpeg-subsampling", OPT(NULL, OPTION_WORD, jpeg_444), 0, 0, options_subsampling, 0},
    {"--tile", OPT(NULL, OPTION_TEXT, tile), 0, 0, NULL, 0},
    {"--tile-layout", OPT(NULL, OPTION_WORD, tile_layout), 0, 0, options_layouts, 0},
    {"--ao", OPT(NULL, OPTION_INT, ao), 0, SCENE_MAX_INDIRECT, NULL, 0},
    {"--ao-distance", OPT(NULL, OPTION_REAL, ao_distance), 0, 1e300, NULL, 0},
    {"--gi", OPT(NULL, OPTION_INT, gi), 0, SCENE_MAX_INDIRECT, NULL, 0},
    {"--gi-bounces", OPT(NULL, OPTION_INT, gi_bounces), 1, SCENE_MAX_BOUNCES, NULL, 0},
    {"--noise", OPT(NULL, OPTION_REAL, noise), 0, 255, NULL, 0},
    {"--min-spp", OPT(NULL, OPTION_INT, min_spp), 1, NOISE_SPP_LIMIT, NULL, 0},
    {"--max-spp", OPT(NULL, OPTION_INT, max_spp), 1, NOISE_SPP_LIMIT, NULL, 0},
    {"--spp-map", OPT(NULL, OPTION_TEXT, spp_map), 0, 0, NULL, 0},
    {"--texture-filter", OPT(NULL, OPTION_WORD, texture_filter), 0, 0, options_filters, 0},
};
#undef OPT

enum { OPTIONS_COUNT = sizeof options_table / sizeof options_table[0] };

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

/* Writes "option 'NAME' takes W1, W2 or W3, found 'VALUE'" to msg. */
static void options_fail_word(const OptionSpec *o, const char *value, char *msg, size_t msg_size)
{
    size_t n = (size_t)snprintf(msg, msg_size, "option '%s' takes ", o->long_name);
    int count = 0;

    while (o->words[count].word)
        count++;
    for (int k = 0; k < count && n < msg_size; k++)
        n += (size_t)snprintf(msg + n, msg_size - n, "%s%s",
                              k == 0 ? "" : k == count - 1 ? " or " : ", ", o->words[k].word);
    if (n < msg_size)
        snprintf(msg + n, msg_size - n, ", found '%.40s'", value);
}

/* Reads value, the value of option o, into its field of *opts; returns 0,
 * or -1 with msg set when it is not one o takes. */
static int options_store(const OptionSpec *o, const char *value, Options *opts, char *msg,
                         size_t msg_size)
{
    char *field = (char *)opts + o->field;
    double v;
    int n;

    switch (o->kind) {
    case OPTION_INT:
        if (options_int(value, (int)o->lo, (int)o->hi, &n) != 0) {
            snprintf(msg, msg_size, "option '%s' takes a whole number from %d to %d, found '%.40s'",
                     o->long_name, (int)o->lo, (int)o->hi, value);
            return -1;
        }
        memcpy(field, &n, sizeof n);
        return 0;
    case OPTION_REAL:
        if (number_parse(value, strlen(value), &v) != NUMBER_OK || !(v >= o->lo && v <= o->hi)) {
            snprintf(msg, msg_size, "option '%s' takes a number from %g to %g, found '%.40s'",
                     o->long_name, o->lo, o->hi, value);
            return -1;
        }
        memcpy(field, &v, sizeof v);
        return 0;
    case OPTION_SIZE: {
        size_t size;
        if (options_size(value, &size) != 0) {
            snprintf(msg, msg_size,
                     "option '%s' takes a size in bytes such as 512M or 8G (0: no limit), "
                     "found '%.40s'",
                     o->long_name, value);
            return -1;
        }
        memcpy(field, &size, sizeof size);
        return 0;
    }
    case OPTION_WORD:
        for (const OptionWord *w = o->words; w->word; w++)
            if (strcmp(value, w->word) == 0) {
                memcpy(field, &w->value, sizeof w->value);
                return 0;
            }
        options_fail_word(o, value, msg, msg_size);
        return -1;
    default: /* OPTION_TEXT */
        memcpy(field, &value, sizeof value);
        return 0;
    }
}

/* Reads the option at argv[*i] (and its value, which may be the next
 * argument) into *opts; returns 0, -1 with msg set on a usage error, or
 * 1 with *act set when it asks for something at once (--help). */
static int options_one(Options *opts, int argc, char **argv, int *i, OptionsAction *act,
                       char *msg, size_t msg_size)
{
    const char *arg = argv[*i], *value;

    for (int k = 0; k < OPTIONS_COUNT; k++) {
        const OptionSpec *o = &options_table[k];
        int m;

        if (o->kind == OPTION_ACT || o->kind == OPTION_FLAG) {
            if (strcmp(arg, o->long_name) != 0 && !(o->short_name && strcmp(arg, o->short_name) == 0))
                continue;
            if (o->kind == OPTION_ACT) {
                *act = o->act;
                return 1;
            }
            *(int *)(void *)((char *)opts + o->field) = 1;
            return 0;
        }
        m = options_match_value(o->long_name, o->short_name, argc, argv, i, &value, msg,
                                msg_size);
        if (m < 0)
            return -1;
        if (m > 0)
            return options_store(o, value, opts, msg, msg_size);
    }
    snprintf(msg, msg_size, "unknown option '%.40s'", arg);
    return -1;
}

/* Reads --tile K/N into opts (1 <= K <= N <= TILE_MAX), and checks that
 * the output can keep a tile's record; returns 0, or -1 with msg set. */
static int options_tile(Options *opts, char *msg, size_t msg_size)
{
    int k, n, end = 0;

    if (sscanf(opts->tile, "%d/%d%n", &k, &n, &end) != 2 || opts->tile[end] != '\0' ||
        !isdigit((unsigned char)opts->tile[0]) || !(k >= 1 && k <= n && n <= TILE_MAX)) {
        snprintf(msg, msg_size,
                 "option '--tile' takes K/N, the K-th of N tiles with 1 <= K <= N <= %d, "
                 "found '%.40s'",
                 TILE_MAX, opts->tile);
        return -1;
    }
    if (opts->output_path && opts->format == FORMAT_JPEG) {
        snprintf(msg, msg_size,
                 "--tile writes PPM, PNG or PFM tiles (lossless), which raytrace-merge puts "
                 "together in any format: not JPEG");
        return -1;
    }
    opts->tile_k = k;
    opts->tile_n = n;
    return 0;
}

/* Reads --size WxH into opts (each 1..CAMERA_MAX_SIZE); returns 0, or -1
 * with msg set. */
static int options_image_size(Options *opts, char *msg, size_t msg_size)
{
    const char *x = strchr(opts->size, 'x');
    char w[16];
    size_t n = x ? (size_t)(x - opts->size) : 0;

    if (x && n > 0 && n < sizeof w) {
        memcpy(w, opts->size, n);
        w[n] = '\0';
        if (options_int(w, 1, CAMERA_MAX_SIZE, &opts->width) == 0 &&
            options_int(x + 1, 1, CAMERA_MAX_SIZE, &opts->height) == 0)
            return 0;
    }
    snprintf(msg, msg_size,
             "option '--size' takes WxH, the image's width and height in pixels, each from 1 "
             "to %d (as 500x500), found '%.40s'",
             CAMERA_MAX_SIZE, opts->size);
    return -1;
}

OptionsAction options_parse(Options *opts, int argc, char **argv, int default_threads, char *msg,
                            size_t msg_size)
{
    const char *positional[2];
    int npos = 0, only_positional = 0;

    memset(opts, 0, sizeof *opts);
    opts->max_depth = -1;
    opts->model = -1;
    opts->threads = default_threads;
    opts->format = -1;
    opts->scene_format = SCENE_AUTO;
    opts->cutoff = OPTIONS_DEFAULT_CUTOFF;
    opts->memory_limit = OPTIONS_DEFAULT_MEMORY_LIMIT;
    opts->ao = opts->gi = -1;
    opts->noise = -1;
    opts->texture_filter = -1;
    opts->jpeg_quality = 90;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        OptionsAction act;
        int rc;

        if (only_positional || arg[0] != '-' || strcmp(arg, "-") == 0) {
            if (npos == 2) {
                snprintf(msg, msg_size, "too many arguments: '%.40s' after SCENE and OUTPUT",
                         arg);
                return OPTIONS_USAGE;
            }
            positional[npos++] = arg;
        } else if (strcmp(arg, "--") == 0) {
            only_positional = 1;
        } else if ((rc = options_one(opts, argc, argv, &i, &act, msg, msg_size)) != 0) {
            return rc > 0 ? act : OPTIONS_USAGE;
        }
    }
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
    if (opts->tile && options_tile(opts, msg, msg_size) != 0)
        return OPTIONS_USAGE;
    if (opts->size && options_image_size(opts, msg, msg_size) != 0)
        return OPTIONS_USAGE;
    if (opts->min_spp && opts->max_spp && opts->min_spp > opts->max_spp) {
        snprintf(msg, msg_size, "--min-spp %d is more than --max-spp %d", opts->min_spp,
                 opts->max_spp);
        return OPTIONS_USAGE;
    }
    if (opts->spp_map && !*opts->spp_map) {
        snprintf(msg, msg_size, "--spp-map needs a file name");
        return OPTIONS_USAGE;
    }
    return opts->check ? OPTIONS_CHECK : opts->save_path ? OPTIONS_SAVE : OPTIONS_RENDER;
}
