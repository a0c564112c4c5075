/*
 * options.h: the command line of raytrace.
 */
#ifndef RAYTRACE_OPTIONS_H
#define RAYTRACE_OPTIONS_H

#include <stddef.h>

#define OPTIONS_DEFAULT_CUTOFF 0.1 /* levels */
#define OPTIONS_DEFAULT_MEMORY_LIMIT ((size_t)4 << 30) /* bytes: 4 GiB */

typedef struct {
    const char *scene_path;  /* scene file, "-" for standard input */
    const char *output_path; /* image file, "-" for standard output */
    int max_depth;           /* deepest reflected ray traced; -1: the
                                model's default (main.c) */
    int threads;             /* render threads, >= 1 */
    int samples;             /* samples per pixel from --spp, 0 when not given */
    int quiet;               /* 1: no progress or summary even on a terminal */
    int verbose;             /* 1: print statistics after rendering */
    int check;               /* 1: only read the scene */
    int format;              /* an ImageFormat: --format, else from output_path */
    int ascii;               /* 1: PPM as P3 */
    int png_stored;          /* 1: PNG with stored deflate blocks */
    int no_accel;            /* 1: no acceleration structure */
    int scene_format;        /* a SceneFormat: --scene-format, else SCENE_AUTO */
    const char *save_path;   /* --save OUT, or NULL */
    double cutoff;           /* --cutoff: levels below which secondary rays
                                are left out (render.h) */
    size_t memory_limit;     /* --memory-limit: bytes the scene, its
                                hierarchy and the image may take; 0: none */
    int ao;                  /* --ao: occlusion rays per primary hit; -1:
                                the scene's (0 unless it sets them) */
    double ao_distance;      /* --ao-distance; 0: the scene's, else a tenth
                                of its size */
    int gi;                  /* --gi: gathering rays; -1: the scene's */
    int gi_bounces;          /* --gi-bounces; 0: the scene's, else 1 */
    int gi_cache;            /* --gi-cache: gathered light through the
                                irradiance cache (else the scene's choice) */
    double gi_cache_error;   /* --gi-cache-error E; 0: the scene's, else
                                GICACHE_DEFAULT_ERROR */
    const char *gi_cache_map; /* --gi-cache-map FILE: where the records
                                fell, or NULL */
    int jpeg_quality;        /* --jpeg-quality, 1..100 (default 90) */
    int jpeg_444;            /* --jpeg-subsampling 444: chroma kept whole */
    const char *tile;        /* --tile K/N as given, or NULL */
    int tile_k, tile_n;      /* its K and N, 1 <= K <= N <= TILE_MAX */
    int tile_layout;         /* --tile-layout: a TileLayout (tile.h) */
    int model;               /* --model: a SceneModel; -1: the scene's */
    const char *size;        /* --size WxH as given, or NULL */
    int width, height;       /* its W and H, 1..CAMERA_MAX_SIZE; 0: the
                                scene's */
    int no_shadows;          /* --no-shadows: no shadow rays */
    int strict;              /* --strict: the MPL ray tracer's lenient lines refused */
    double noise;            /* --noise L: the error a pixel may keep, in
                                levels (noise.h); -1: the scene's (none
                                unless it asks); 0: none */
    int min_spp, max_spp;    /* --min-spp, --max-spp; 0: the scene's, else
                                NOISE_MIN_SPP and NOISE_MAX_SPP */
    const char *spp_map;     /* --spp-map FILE: where the samples went, or
                                NULL */
    int texture_filter;      /* --texture-filter: a TextureFilter for every
                                texture and stripes; -1: the scene's */
    int pass;                /* --pass: a TracePass (pass.h); 0, the
                                picture */
} Options;

/* What options_parse() found the command line asks for. */
typedef enum {
    OPTIONS_RENDER,  /* render scene_path to output_path */
    OPTIONS_CHECK,   /* only read scene_path (output_path is NULL) */
    OPTIONS_SAVE,    /* read scene_path, write it to save_path */
    OPTIONS_HELP,    /* print the help text */
    OPTIONS_VERSION, /* print the version */
    OPTIONS_USAGE    /* a usage error, described in the message buffer */
} OptionsAction;

/* Reads argv into *opts, starting from defaults (threads = default_threads);
 * on a usage error writes a one-line message to msg. */
OptionsAction options_parse(Options *opts, int argc, char **argv, int default_threads, char *msg,
                            size_t msg_size);

/* Returns the text printed by --help, in parts (NULL after the last):
 * C11 compilers need only take string literals of 4095 bytes. */
const char *const *options_help(void);

#endif
