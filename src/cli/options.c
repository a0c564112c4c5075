/* options.c: command-line parsing (see options.h). */
#include "cli/options.h"

#include "cli/args.h"

#include <stddef.h>
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
        "Render SCENE, a scene file in the course format, the keyword format of\n"
        "the OCaml course project or the MPL format of the MPL ray tracer (told\n"
        "apart by content), to OUTPUT: a PPM (P6), PNG, PFM, JPEG or BMP image,\n"
        "chosen by OUTPUT's extension (.ppm, .png, .pfm, .jpg, .jpeg, .bmp; PPM\n"
        "for a name without one; another image format's, as .tif, is refused)\n"
        "or by --format. Textures may be PPM, PNG, JPEG or BMP files. SCENE may\n"
        "be '-' for standard input, OUTPUT '-' for standard output. OUTPUT is\n"
        "replaced only when the whole image has been written.\n"
        "\n"
        "Options:\n",
        "  -d, --max-depth N  trace mirror and refracted rays down to depth N,\n"
        "                     0 to 1000 (default 10, the MPL model 99; 0 traces\n"
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
        "  --texture-filter F read every texture and the MPL format's stripes with F:\n"
        "                     nearest, bilinear, trilinear (mip-maps: the pixel's\n"
        "                     footprint averaged, followed by ray differentials\n"
        "                     through mirrors and glass) or ewa (an elliptical\n"
        "                     Gaussian over the footprint, sharper at grazing\n"
        "                     angles); default: the scene's (course texture:\n"
        "                     records bilinear, MPL materials trilinear)\n",
        "  --size WxH         render W x H pixels (1 to 32768 each) of the scene's\n"
        "                     view, its height kept (default: the scene's size)\n"
        "  --model M          light an MPL scene by M: mpl (the default: the MPL\n"
        "                     ray tracer's rules, its occlusion and gathering,\n"
        "                     gamma 2.2) or physical (the keyword format's\n"
        "                     Blinn-Phong, physically based occlusion and\n"
        "                     gathered light, linear bytes)\n"
        "  --no-shadows       cast no shadow rays: every light reaches every point\n"
        "                     that faces it\n"
        "  --strict           refuse the lines the MPL ray tracer read despite\n"
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
        "                     the MPL model: 10 rays at every point, darkening\n"
        "                     all its light)\n"
        "  --ao-distance D    what is nearer than D hides (default: the scene's,\n"
        "                     else a tenth of the diagonal of its objects' box;\n"
        "                     the MPL model: 2)\n"
        "  --gi N             global illumination: N rays per point the camera\n"
        "                     sees (0 to 4096) gather the light other surfaces\n"
        "                     reflect onto its diffuse part (default: 0; with\n"
        "                     --gi-cache 2048 a record; the MPL model: 10 rays\n"
        "                     gathering the colours they meet)\n"
        "  --gi-bounces B     diffuse bounces gathered, 1 to 64 (default 1)\n"
        "  --gi-cache         gather through an irradiance cache: --gi N rays at\n"
        "                     a few points placed before the render (default\n"
        "                     2048), their light interpolated between them\n"
        "                     (smooth, faster; biased)\n"
        "  --gi-cache-error E the cache's accuracy, 0.01 to 2 (default 0.3;\n"
        "                     smaller: more records, and every pixel's light\n"
        "                     closer to gathering's; at 0.3 a few pixels by\n"
        "                     corners and contacts are biased, by up to tens\n"
        "                     of levels: docs/gicache.md)\n"
        "  --gi-cache-map FILE also write where the cache's records fell\n",
        "  --pass P           write one part of the picture alone: direct (all\n"
        "                     but the gathered light) or indirect (the gathered\n"
        "                     light: in PFM the two add up to the picture), or\n"
        "                     of the first surface seen: ao (the share of the\n"
        "                     ambient light occlusion keeps, grey), albedo (its\n"
        "                     colour), normal ((n + 1) / 2: x red, y green, z\n"
        "                     blue) or depth (grey s / (s + d): s the distance\n"
        "                     the picture's centre sees, mid-grey); default\n"
        "                     full, the picture\n"
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
        "  --format F         write F: ppm, png, pfm (linear floats, unclamped),\n"
        "                     jpeg (lossy: smaller files, not the exact bytes) or\n"
        "                     bmp (24-bit Windows bitmap)\n"
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
        "  -v, --verbose      say when the scene is read, then after rendering the\n"
        "                     image size, threads, rays cast by kind, time and speed\n"
        "  -q, --quiet        print nothing on success, not even the progress bar\n"
        "  -h, --help         print this help and exit\n"
        "  -V, --version      print the version and exit\n"
        "\n"
        "Exit status: 0 the image was written; 1 the scene or an output could not be\n"
        "read or written (the message says where); 2 the command line is wrong;\n"
        "130 or 143 interrupted by SIGINT or SIGTERM (at any moment; one the parent\n"
        "set to be ignored, as a shell's background job has it, stays ignored).\n"
        "\n"
        "The scene formats are described in docs/scene-format.md.\n",
        NULL};

    return parts;
}

static const ArgWord options_formats[] = {
    {"ppm", FORMAT_PPM, 0},  {"png", FORMAT_PNG, 0}, {"pfm", FORMAT_PFM, 0},
    {"jpeg", FORMAT_JPEG, 0}, {"jpg", FORMAT_JPEG, 0}, {"bmp", FORMAT_BMP, 0},
    {NULL, 0, 0}};
static const ArgWord options_subsampling[] = {{"420", 0, 0}, {"444", 1, 0}, {NULL, 0, 0}};
static const ArgWord options_layouts[] = {
    {"rows", TILE_ROWS, 0}, {"bands", TILE_BANDS, 0}, {NULL, 0, 0}};
static const ArgWord options_filters[] = {{"nearest", TEXTURE_NEAREST, 0},
                                            {"bilinear", TEXTURE_BILINEAR, 0},
                                            {"trilinear", TEXTURE_TRILINEAR, 0},
                                            {"ewa", TEXTURE_EWA, 0},
                                            {NULL, 0, 0}};
static const ArgWord options_deflates[] = {{"stored", 1, 0}, {"fixed", 0, 0}, {NULL, 0, 0}};
static const ArgWord options_models[] = {{"mpl", SCENE_MODEL_MPL, 0},
                                           {"seed001", SCENE_MODEL_MPL, 1},
                                           {"physical", SCENE_MODEL_PHYSICAL, 0},
                                           {NULL, 0, 0}};
static const ArgWord options_passes[] = {
    {"full", TRACE_PASS_FULL, 0},      {"direct", TRACE_PASS_DIRECT, 0},
    {"indirect", TRACE_PASS_INDIRECT, 0}, {"ao", TRACE_PASS_AO, 0},
    {"albedo", TRACE_PASS_ALBEDO, 0},  {"normal", TRACE_PASS_NORMAL, 0},
    {"depth", TRACE_PASS_DEPTH, 0},    {NULL, 0, 0}};
static const ArgWord options_scene_formats[] = {{"course", SCENE_COURSE, 0},
                                                    {"keyword", SCENE_KEYWORD, 0},
                                                    {"mpl", SCENE_MPL, 0},
                                                    {"auto", SCENE_AUTO, 0},
                                                    {NULL, 0, 0}};

#define OPT(name, kind, field) name, kind, offsetof(Options, field)
static const ArgSpec options_table[] = {
    {"--help", "-h", ARG_ACT, 0, 0, 0, NULL, OPTIONS_HELP},
    {"--version", "-V", ARG_ACT, 0, 0, 0, NULL, OPTIONS_VERSION},
    {"--quiet", OPT("-q", ARG_FLAG, quiet), 0, 0, NULL, 0},
    {"--verbose", OPT("-v", ARG_FLAG, verbose), 0, 0, NULL, 0},
    {"--check", OPT(NULL, ARG_FLAG, check), 0, 0, NULL, 0},
    {"--ascii", OPT(NULL, ARG_FLAG, ascii), 0, 0, NULL, 0},
    {"--no-accel", OPT(NULL, ARG_FLAG, no_accel), 0, 0, NULL, 0},
    {"--no-shadows", OPT(NULL, ARG_FLAG, no_shadows), 0, 0, NULL, 0},
    {"--strict", OPT(NULL, ARG_FLAG, strict), 0, 0, NULL, 0},
    {"--model", OPT(NULL, ARG_WORD, model), 0, 0, options_models, 0},
    {"--size", OPT(NULL, ARG_TEXT, size), 0, 0, NULL, 0},
    {"--max-depth", OPT("-d", ARG_INT, max_depth), 0, TRACE_MAX_DEPTH_LIMIT, NULL, 0},
    {"--threads", OPT("-j", ARG_INT, threads), 1, OPTIONS_MAX_THREADS, NULL, 0},
    {"--spp", OPT("-s", ARG_INT, samples), 1, SAMPLER_MAX, NULL, 0},
    {"--format", OPT(NULL, ARG_WORD, format), 0, 0, options_formats, 0},
    {"--png-deflate", OPT(NULL, ARG_WORD, png_stored), 0, 0, options_deflates, 0},
    {"--scene-format", OPT(NULL, ARG_WORD, scene_format), 0, 0, options_scene_formats, 0},
    {"--save", OPT(NULL, ARG_TEXT, save_path), 0, 0, NULL, 0},
    {"--cutoff", OPT(NULL, ARG_REAL, cutoff), 0, 255, NULL, 0},
    {"--memory-limit", OPT(NULL, ARG_SIZE, memory_limit), 0, 0, NULL, 0},
    {"--jpeg-quality", OPT(NULL, ARG_INT, jpeg_quality), 1, 100, NULL, 0},
    {"--jpeg-subsampling", OPT(NULL, ARG_WORD, jpeg_444), 0, 0, options_subsampling, 0},
    {"--tile", OPT(NULL, ARG_TEXT, tile), 0, 0, NULL, 0},
    {"--tile-layout", OPT(NULL, ARG_WORD, tile_layout), 0, 0, options_layouts, 0},
    {"--ao", OPT(NULL, ARG_INT, ao), 0, SCENE_MAX_INDIRECT, NULL, 0},
    {"--ao-distance", OPT(NULL, ARG_REAL, ao_distance), 0, 1e300, NULL, 0},
    {"--gi", OPT(NULL, ARG_INT, gi), 0, SCENE_MAX_INDIRECT, NULL, 0},
    {"--gi-bounces", OPT(NULL, ARG_INT, gi_bounces), 1, SCENE_MAX_BOUNCES, NULL, 0},
    {"--gi-cache", OPT(NULL, ARG_FLAG, gi_cache), 0, 0, NULL, 0},
    {"--gi-cache-error", OPT(NULL, ARG_REAL, gi_cache_error), SCENE_GI_CACHE_MIN_ERROR,
     SCENE_GI_CACHE_MAX_ERROR, NULL, 0},
    {"--gi-cache-map", OPT(NULL, ARG_TEXT, gi_cache_map), 0, 0, NULL, 0},
    {"--noise", OPT(NULL, ARG_REAL, noise), 0, 255, NULL, 0},
    {"--min-spp", OPT(NULL, ARG_INT, min_spp), 1, NOISE_SPP_LIMIT, NULL, 0},
    {"--max-spp", OPT(NULL, ARG_INT, max_spp), 1, NOISE_SPP_LIMIT, NULL, 0},
    {"--spp-map", OPT(NULL, ARG_TEXT, spp_map), 0, 0, NULL, 0},
    {"--texture-filter", OPT(NULL, ARG_WORD, texture_filter), 0, 0, options_filters, 0},
    {"--pass", OPT(NULL, ARG_WORD, pass), 0, 0, options_passes, 0},
};
#undef OPT

/* Says in msg, of the file `what` names, that path's extension names an
 * image format raytrace cannot write; returns -1 then, else 0. */
static int options_unwritable(const char *what, const char *path, char *msg, size_t msg_size)
{
    const char *format = writer_unwritable(path);

    if (!format)
        return 0;
    snprintf(msg, msg_size,
             "%s '%.60s': raytrace cannot write %s images; it writes " WRITER_FORMATS
             ", chosen by the extension (PPM for a name without one)",
             what, path, format);
    return -1;
}

/* Reads --tile K/N into opts (1 <= K <= N <= TILE_MAX), and checks that
 * the output can keep a tile's record; returns 0, or -1 with msg set. */
static int options_tile(Options *opts, char *msg, size_t msg_size)
{
    int k, n;

    if (args_pair(opts->tile, '/', 1, TILE_MAX, &k, &n) != 0 || k > n) {
        snprintf(msg, msg_size,
                 "option '--tile' takes K/N, the K-th of N tiles with 1 <= K <= N <= %d, "
                 "found '%.40s'",
                 TILE_MAX, opts->tile);
        return -1;
    }
    if (opts->output_path && (opts->format == FORMAT_JPEG || opts->format == FORMAT_BMP)) {
        snprintf(msg, msg_size,
                 "--tile writes PPM, PNG or PFM tiles (each keeps its place in the picture), "
                 "which raytrace-merge puts together in any format: not %s",
                 opts->format == FORMAT_JPEG ? "JPEG" : "BMP");
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
    if (args_pair(opts->size, 'x', 1, CAMERA_MAX_SIZE, &opts->width, &opts->height) == 0)
        return 0;
    snprintf(msg, msg_size,
             "option '--size' takes WxH, the image's width and height in pixels, each from 1 "
             "to %d (as 500x500), found '%.40s'",
             CAMERA_MAX_SIZE, opts->size);
    return -1;
}

OptionsAction options_parse(Options *opts, int argc, char **argv, int default_threads, char *msg,
                            size_t msg_size)
{
    static const ArgTable table = {options_table, sizeof options_table / sizeof options_table[0],
                                   2, "SCENE and OUTPUT"};
    const char *positional[2];
    int npos, rc;

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
    rc = args_parse(&table, opts, argc, argv, positional, &npos, msg, msg_size);
    if (rc != 0)
        return rc > 0 ? (OptionsAction)rc : OPTIONS_USAGE;
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
    if (opts->format < 0 && opts->output_path) {
        if (options_unwritable("OUTPUT", opts->output_path, msg, msg_size) != 0)
            return OPTIONS_USAGE;
        opts->format = (int)writer_format_for(opts->output_path);
    }
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
    if (opts->spp_map && (!*opts->spp_map ||
                          options_unwritable("--spp-map", opts->spp_map, msg, msg_size) != 0)) {
        if (!*opts->spp_map)
            snprintf(msg, msg_size, "--spp-map needs a file name");
        return OPTIONS_USAGE;
    }
    if (opts->gi_cache_map &&
        (!*opts->gi_cache_map ||
         options_unwritable("--gi-cache-map", opts->gi_cache_map, msg, msg_size) != 0)) {
        if (!*opts->gi_cache_map)
            snprintf(msg, msg_size, "--gi-cache-map needs a file name");
        return OPTIONS_USAGE;
    }
    return opts->check ? OPTIONS_CHECK : opts->save_path ? OPTIONS_SAVE : OPTIONS_RENDER;
}
