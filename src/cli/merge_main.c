/*
 * merge_main.c: the raytrace-merge command: puts the tiles of a render
 * (raytrace --tile K/N) back together into one picture. The only code of
 * the command that prints or exits; the tiles' records are read by tile.c,
 * their pixels by compare.c's readers.
 *
 * Exit status: 0 the picture was written; 1 a tile is missing, repeated,
 * foreign, truncated or unreadable, or OUT could not be written (OUT is
 * then left as it was); 2 a bad command line.
 */
#include <inttypes.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/file.h"
#include "base/outfile.h"
#include "base/process.h"
#include "cli/args.h"
#include "image/image.h"
#include "image/decode.h"
#include "image/tile.h"
#include "image/writer.h"

#define MERGE_VERSION "0.2.0"

static const char merge_help[] =
    "Usage: raytrace-merge [OPTIONS] OUT TILE...\n"
    "Put the tiles of one render (raytrace --tile K/N: PPM, PNG or PFM files)\n"
    "back together into OUT, by its extension: PPM, PNG or JPEG from PPM or PNG\n"
    "tiles, PFM from PFM tiles; the same bytes as rendering the whole picture\n"
    "at once.\n"
    "Every tile 1/N to N/N must be given once, all of the same render (the same\n"
    "scene, options and size, as their records' fingerprints say).\n"
    "\n"
    "Options:\n"
    "  --jpeg-quality Q   JPEG quality, 1 to 100 (default 90)\n"
    "  -q, --quiet        print nothing on success (on a terminal it says what\n"
    "                     it wrote)\n"
    "  -h, --help         print this help and exit\n"
    "  -V, --version      print the version and exit\n"
    "\n"
    "Exit status: 0 OUT was written; 1 a tile is missing, repeated, from\n"
    "another render, truncated or unreadable, or OUT could not be written (it\n"
    "is then left as it was); 2 the command line is wrong.\n";

/* Prints "raytrace-merge: FILE: error: MESSAGE" for err. */
static void merge_report(const Error *err)
{
    char message[4 * ERROR_MESSAGE_MAX];

    error_escape(message, sizeof message, err->message, strlen(err->message), 0, NULL);
    fprintf(stderr, "raytrace-merge: %s: error: %s\n", err->file, message);
}

/* What the tiles read so far say about the picture. */
typedef struct {
    Tile first;            /* the first tile's record */
    int linear;            /* the tiles are PFM: linear colours, kept exact */
    const char *first_path;
    const char **owner;    /* per row of the picture: the tile file that gave
                              it, or NULL */
    const char **by_k;     /* per tile number - 1: its file, or NULL */
    Image img;             /* the picture */
} Merge;

/* Copies the rows of t, a PFM tile decoded in *pfm (freed here), into m's
 * linear colours, exactly; returns 0, or -1 with *err. */
static int merge_linear(Merge *m, const char *path, Decoded *pfm, const Tile *t, Error *err)
{
    if (pfm->width != t->width || pfm->height != t->count) {
        error_set(err, path, "holds %d x %d pixels, where its record says %d x %d", pfm->width,
                  pfm->height, t->width, t->count);
        decoded_free(pfm);
        return -1;
    }
    m->by_k[t->k - 1] = path;
    for (int i = 0; i < t->count; i++) {
        int y = t->first + i * t->step;
        size_t row = 3 * (size_t)t->width;
        m->owner[y] = path;
        memcpy(m->img.linear + (size_t)y * row, pfm->linear + (size_t)i * row, row * sizeof(float));
    }
    decoded_free(pfm);
    return 0;
}

/* Copies the rows of t, an 8-bit tile (PPM or PNG) decoded in *img (freed
 * here), into m's picture; returns 0, or -1 with *err. */
static int merge_rows(Merge *m, const char *path, Decoded *img, const Tile *t, Error *err)
{
    if (img->width != t->width || img->height != t->count) {
        error_set(err, path, "holds %d x %d pixels, where its record says %d x %d", img->width,
                  img->height, t->width, t->count);
        decoded_free(img);
        return -1;
    }
    m->by_k[t->k - 1] = path;
    for (int i = 0; i < t->count; i++) {
        int y = t->first + i * t->step;
        const unsigned short *src = img->samples + 3 * (size_t)i * (size_t)t->width;
        unsigned char *dst = m->img.rgb + 3 * (size_t)y * (size_t)t->width;
        m->owner[y] = path;
        for (size_t c = 0; c < 3 * (size_t)t->width; c++)
            dst[c] = (unsigned char)(int)(src[c] * 255.0 / img->maxval + 0.5);
    }
    decoded_free(img);
    return 0;
}

/* Reads the tile at path into m; returns 0, or -1 with *err. */
static int merge_tile(Merge *m, const char *path, int index, Error *err)
{
    char *data;
    size_t len;
    Tile t;
    Decoded d;
    int found, linear, rc;

    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    found = tile_find(path, (const unsigned char *)data, len, &t, err);
    if (found <= 0) {
        free(data);
        if (found == 0)
            error_set(err, path, "not a tile of raytrace --tile: it has no tile record");
        return -1;
    }
    linear = decoded_is_linear(data, len);
    if (index == 0) {
        m->first = t;
        m->first_path = path;
        m->linear = linear;
        m->owner = calloc((size_t)t.height, sizeof *m->owner);
        m->by_k = calloc((size_t)t.n, sizeof *m->by_k);
        if (!m->owner || !m->by_k || image_init(&m->img, t.width, t.height) != 0 ||
            (linear && image_keep_linear(&m->img) != 0)) {
            free(data);
            error_set(err, path, "out of memory for a %d x %d picture", t.width, t.height);
            return -1;
        }
    } else if (linear != m->linear) {
        error_set(err, path, "a %s tile among %s ones (%s): 8-bit and linear tiles do not mix",
                  linear ? "PFM" : "PPM or PNG", m->linear ? "PFM" : "PPM or PNG", m->first_path);
        found = -1;
    } else if (t.fingerprint != m->first.fingerprint) {
        error_set(err, path,
                  "a tile of another render than %s (fingerprint %016" PRIx64 ", not %016" PRIx64
                  "): another scene, other options or another build",
                  m->first_path, t.fingerprint, m->first.fingerprint);
        found = -1;
    } else if (t.width != m->first.width || t.height != m->first.height) {
        error_set(err, path, "a tile of a %d x %d picture, not %d x %d as %s", t.width, t.height,
                  m->first.width, m->first.height, m->first_path);
        found = -1;
    } else if (t.n != m->first.n) {
        error_set(err, path, "tile %d of %d, but %s is one of %d", t.k, t.n, m->first_path,
                  m->first.n);
        found = -1;
    } else if (m->by_k[t.k - 1]) {
        error_set(err, path, "tile %d/%d again: %s is that tile already", t.k, t.n,
                  m->by_k[t.k - 1]);
        found = -1;
    }
    if (found < 0) {
        free(data);
        return -1;
    }
    for (int i = 0; i < t.count; i++)
        if (m->owner[t.first + i * t.step]) {
            free(data);
            error_set(err, path, "overlaps %s: both hold row %d", m->owner[t.first + i * t.step],
                      t.first + i * t.step);
            return -1;
        }
    rc = decoded_parse(path, data, len, 0, &d, err);
    free(data);
    if (rc != 0)
        return -1;
    return linear ? merge_linear(m, path, &d, &t, err) : merge_rows(m, path, &d, &t, err);
}

/* Says which tiles are missing, in err; returns -1, or 0 when none is. */
static int merge_missing(const Merge *m, Error *err)
{
    char list[200] = "";
    size_t used = 0;
    int missing = 0;

    for (int k = 1; k <= m->first.n; k++)
        if (!m->by_k[k - 1]) {
            if (missing < 8 && used < sizeof list)
                used += (size_t)snprintf(list + used, sizeof list - used, "%s%d/%d",
                                         missing ? ", " : "", k, m->first.n);
            missing++;
        }
    if (!missing)
        return 0;
    error_set(err, m->first_path, "%d tile%s of this render %s missing: %s%s", missing,
              missing == 1 ? "" : "s", missing == 1 ? "is" : "are", list,
              missing > 8 ? "..." : "");
    return -1;
}

/* The command line. */
typedef struct {
    int quiet;             /* -q */
    int jpeg_quality;      /* --jpeg-quality, 1..100 */
    const char **paths;    /* OUT, then the tiles */
    int npaths;
} MergeOptions;

enum { MERGE_HELP = 1, MERGE_SHOW_VERSION };

static const ArgSpec merge_specs[] = {
    {"--jpeg-quality", NULL, ARG_INT, offsetof(MergeOptions, jpeg_quality), 1, 100, NULL, 0},
    {"--quiet", "-q", ARG_FLAG, offsetof(MergeOptions, quiet), 0, 0, NULL, 0},
    {"--help", "-h", ARG_ACT, 0, 0, 0, NULL, MERGE_HELP},
    {"--version", "-V", ARG_ACT, 0, 0, 0, NULL, MERGE_SHOW_VERSION},
};

/* Reads the command line into *o (o->paths, room for argc paths, given);
 * returns -1 to go on, else the exit status after printing the help, the
 * version or a usage error. */
static int merge_options(int argc, char **argv, MergeOptions *o)
{
    static const ArgTable table = {merge_specs, sizeof merge_specs / sizeof merge_specs[0], 0,
                                   "OUT and TILE"};
    char msg[512];
    int rc = args_parse(&table, o, argc, argv, o->paths, &o->npaths, msg, sizeof msg);

    if (rc == MERGE_HELP) {
        fputs(merge_help, stdout);
        return 0;
    }
    if (rc == MERGE_SHOW_VERSION) {
        printf("raytrace-merge %s\n", MERGE_VERSION);
        return 0;
    }
    if (rc == 0 && o->npaths < 2)
        snprintf(msg, sizeof msg, "%s", o->npaths ? "missing TILE" : "missing OUT and TILE");
    else if (rc == 0 && writer_unwritable(o->paths[0]))
        snprintf(msg, sizeof msg, "OUT '%.60s': raytrace-merge cannot write %s images; it writes "
                 WRITER_FORMATS, o->paths[0], writer_unwritable(o->paths[0]));
    if (rc < 0 || o->npaths < 2 || writer_unwritable(o->paths[0])) {
        fprintf(stderr, "raytrace-merge: %s\nTry 'raytrace-merge --help'.\n", msg);
        return 2;
    }
    return -1;
}

/* Puts the tiles of o together and writes the picture to o's OUT; returns
 * 0, or -1 with *err saying why not (OUT then left as it was). */
static int merge_run(const MergeOptions *o, Merge *m, Error *err)
{
    const char *out_path = o->paths[0];
    WriterOptions w = {.format = writer_format_for(out_path), .png_deflate = DEFLATE_FIXED,
                       .jpeg_quality = o->jpeg_quality};
    OutFile out;

    for (int i = 1; i < o->npaths; i++)
        if (merge_tile(m, o->paths[i], i - 1, err) != 0)
            return -1;
    /* 8-bit tiles make 8-bit pictures, PFM tiles a PFM: each kept exact. */
    if ((w.format == FORMAT_PFM) != m->linear) {
        error_set(err, out_path,
                  m->linear ? "the tiles are PFM (linear colours): write a PFM"
                            : "the tiles hold 8-bit pixels: write PPM, PNG, JPEG or BMP, not PFM");
        return -1;
    }
    if (merge_missing(m, err) != 0 || outfile_open(&out, out_path, err) != 0)
        return -1;
    if (writer_write(out.fp, &m->img, &w) != 0) {
        error_set(err, out_path, "cannot write the picture");
        outfile_abort(&out, err);
        return -1;
    }
    return outfile_commit(&out, err);
}

int main(int argc, char **argv)
{
    MergeOptions o = {0, 90, NULL, 0};
    Merge m;
    Error err;
    int status;

    process_init(&argc, &argv);
    o.paths = calloc((size_t)argc, sizeof *o.paths);
    if (!o.paths)
        return 1;
    status = merge_options(argc, argv, &o);
    if (status < 0) {
        memset(&m, 0, sizeof m);
        memset(&err, 0, sizeof err);
        status = merge_run(&o, &m, &err) == 0 ? 0 : 1;
        if (status != 0)
            merge_report(&err);
        else if (!o.quiet && file_is_terminal(stderr))
            fprintf(stderr, "raytrace-merge: wrote %s: %d x %d pixels from %d tiles\n",
                    o.paths[0], m.img.width, m.img.height, o.npaths - 1);
        image_free(&m.img);
        free(m.owner);
        free(m.by_k);
    }
    free(o.paths);
    return status;
}
