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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/file.h"
#include "base/outfile.h"
#include "base/process.h"
#include "image/compare.h"
#include "image/image.h"
#include "image/pfm.h"
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

/* Copies the rows of t, a PFM tile (the len bytes at data, freed here),
 * into m's linear colours, exactly; returns 0, or -1 with *err. */
static int merge_linear(Merge *m, const char *path, char *data, size_t len, const Tile *t,
                        Error *err)
{
    PfmImage pfm;
    int rc = pfm_parse(path, data, len, &pfm, err);

    free(data);
    if (rc != 0)
        return -1;
    if (pfm.width != t->width || pfm.height != t->count) {
        error_set(err, path, "holds %d x %d pixels, where its record says %d x %d", pfm.width,
                  pfm.height, t->width, t->count);
        pfm_free(&pfm);
        return -1;
    }
    m->by_k[t->k - 1] = path;
    for (int i = 0; i < t->count; i++) {
        int y = t->first + i * t->step;
        size_t row = 3 * (size_t)t->width;
        m->owner[y] = path;
        memcpy(m->img.linear + (size_t)y * row, pfm.rgb + (size_t)i * row, row * sizeof(float));
    }
    pfm_free(&pfm);
    return 0;
}

/* Reads the tile at path into m; returns 0, or -1 with *err. */
static int merge_tile(Merge *m, const char *path, int index, Error *err)
{
    char *data;
    size_t len;
    Tile t;
    Picture pic;
    int found, linear;

    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    found = tile_find(path, (const unsigned char *)data, len, &t, err);
    if (found <= 0) {
        free(data);
        if (found == 0)
            error_set(err, path, "not a tile of raytrace --tile: it has no tile record");
        return -1;
    }
    linear = len >= 2 && data[0] == 'P' && (data[1] == 'F' || data[1] == 'f');
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
    if (linear)
        return merge_linear(m, path, data, len, &t, err);
    if (picture_parse(path, data, len, &pic, err) != 0) {
        free(data);
        return -1;
    }
    free(data);
    if (pic.width != t.width || pic.height != t.count) {
        error_set(err, path, "holds %d x %d pixels, where its record says %d x %d", pic.width,
                  pic.height, t.width, t.count);
        picture_free(&pic);
        return -1;
    }
    m->by_k[t.k - 1] = path;
    for (int i = 0; i < t.count; i++) {
        int y = t.first + i * t.step;
        const double *src = pic.rgb + 3 * (size_t)i * (size_t)t.width;
        unsigned char *dst = m->img.rgb + 3 * (size_t)y * (size_t)t.width;
        m->owner[y] = path;
        for (size_t c = 0; c < 3 * (size_t)t.width; c++)
            dst[c] = (unsigned char)(src[c] < 0 ? 0 : src[c] > 255 ? 255 : (int)(src[c] + 0.5));
    }
    picture_free(&pic);
    return 0;
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

int main(int argc, char **argv)
{
    const char *out_path = NULL;
    const char **tiles;
    int ntiles = 0, quiet = 0, quality = 90, only = 0;
    Merge m;
    Error err;
    OutFile out;
    WriterOptions w;

    process_init(&argc, &argv);
    tiles = calloc((size_t)argc, sizeof *tiles);
    if (!tiles)
        return 1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!only && (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0)) {
            fputs(merge_help, stdout);
            free(tiles);
            return 0;
        } else if (!only && (strcmp(a, "-V") == 0 || strcmp(a, "--version") == 0)) {
            printf("raytrace-merge %s\n", MERGE_VERSION);
            free(tiles);
            return 0;
        } else if (!only && (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0)) {
            quiet = 1;
        } else if (!only && strcmp(a, "--jpeg-quality") == 0) {
            char *end;
            long q = i + 1 < argc ? strtol(argv[i + 1], &end, 10) : 0;
            if (i + 1 >= argc || *end || end == argv[i + 1] || q < 1 || q > 100) {
                fprintf(stderr, "raytrace-merge: option '--jpeg-quality' takes a whole number "
                                "from 1 to 100\nTry 'raytrace-merge --help'.\n");
                free(tiles);
                return 2;
            }
            quality = (int)q;
            i++;
        } else if (!only && strcmp(a, "--") == 0) {
            only = 1;
        } else if (!only && a[0] == '-' && a[1]) {
            fprintf(stderr, "raytrace-merge: unknown option '%s'\nTry 'raytrace-merge --help'.\n",
                    a);
            free(tiles);
            return 2;
        } else if (!out_path) {
            out_path = a;
        } else {
            tiles[ntiles++] = a;
        }
    }
    if (!out_path || ntiles == 0) {
        fprintf(stderr, "raytrace-merge: %s\nTry 'raytrace-merge --help'.\n",
                out_path ? "missing TILE" : "missing OUT and TILE");
        free(tiles);
        return 2;
    }
    memset(&m, 0, sizeof m);
    memset(&err, 0, sizeof err);
    w.format = writer_format_for(out_path);
    w.ascii = 0;
    w.png_deflate = DEFLATE_FIXED;
    w.jpeg_quality = quality;
    w.jpeg_444 = 0;
    w.note = NULL;
    for (int i = 0; i < ntiles; i++)
        if (merge_tile(&m, tiles[i], i, &err) != 0)
            goto fail;
    /* 8-bit tiles make 8-bit pictures, PFM tiles a PFM: each kept exact. */
    if ((w.format == FORMAT_PFM) != m.linear) {
        error_set(&err, out_path,
                  m.linear ? "the tiles are PFM (linear colours): write a PFM"
                           : "the tiles hold 8-bit pixels: write PPM, PNG or JPEG, not PFM");
        goto fail;
    }
    if (merge_missing(&m, &err) != 0)
        goto fail;
    if (outfile_open(&out, out_path, &err) != 0)
        goto fail;
    if (writer_write(out.fp, &m.img, &w) != 0) {
        error_set(&err, out_path, "cannot write the picture");
        outfile_abort(&out, &err);
        goto fail;
    }
    if (outfile_commit(&out, &err) != 0)
        goto fail;
    if (!quiet && file_is_terminal(stderr))
        fprintf(stderr, "raytrace-merge: wrote %s: %d x %d pixels from %d tiles\n", out_path,
                m.img.width, m.img.height, ntiles);
    image_free(&m.img);
    free(m.owner);
    free(m.by_k);
    free(tiles);
    return 0;
fail:
    merge_report(&err);
    image_free(&m.img);
    free(m.owner);
    free(m.by_k);
    free(tiles);
    return 1;
}
