/*
 * render.h: turning a scene into an image, tiles shared among threads.
 *
 * Each pixel is traced on its own from its own primary rays, so the bytes do
 * not depend on the number of threads or on how tiles are scheduled. With one
 * sample per pixel the ray goes through the pixel's centre (and the lens's
 * centre); with n, through n points of the pixel (and of the lens) placed by
 * sampler.h, and the pixel is the mean of their colours, taken before the
 * colour is clamped and rounded. Under --noise a pixel takes as many
 * samples as its own error estimate asks for (noise.h), so the bytes still
 * depend on nothing but the pixel.
 */
#ifndef RAYTRACE_RENDER_H
#define RAYTRACE_RENDER_H

#include "image/image.h"
#include "render/noise.h"
#include "render/trace.h"
#include "scene/scene.h"

/* Told, one call at a time, that done of the image's total parts (tiles)
 * are finished; ctx is RenderOptions' progress_ctx. */
typedef void (*RenderProgress)(void *ctx, int done, int total);

typedef struct {
    int max_depth;           /* deepest secondary ray traced, 0..TRACE_MAX_DEPTH_LIMIT */
    int samples;             /* samples per pixel, 1..SAMPLER_MAX */
    double cutoff;           /* leave out secondary and shadow rays that
                                could bring less than this many levels
                                (cut.h); the bytes stay those of an uncut
                                render, but not the colours before they are
                                quantised (so 0, none, for PFM) */
    int threads;             /* worker threads, >= 1; 1 without OpenMP */
    RenderProgress progress; /* called after each tile, or NULL */
    void *progress_ctx;      /* passed to progress */
    Indirect indirect;       /* ambient occlusion and global illumination
                                (tracer.h); zeros: none */
    int row_first, row_step; /* the image's row y is the picture's row
                                row_first + y row_step (a tile, tile.h);
                                row_step 0: the whole picture */
    int no_shadows;          /* 1: cast no shadow rays (every light reaches
                                every point facing it) */
    NoiseOptions noise;      /* adaptive sampling (noise.h): level 0, off
                                (samples a pixel then); else samples is
                                unused and the cut-off off */
    unsigned *spp;           /* under noise, receives the samples each pixel
                                took (img's layout, one a pixel), or NULL */
    float *error;            /* under noise, receives each pixel's
                                estimated error (noise_error()), or NULL */
    const struct GiCache *gicache; /* under indirect.gi_cache, the records
                                irradiance_build() placed (NULL: none, every
                                point gathers) */
    TracePass pass;          /* the picture, or one part of it (pass.h) */
} RenderOptions;

/* Renders scene into img, which must already be sized to the scene's
 * camera width and height (and gamma-encoded for a scene of the MPL ray tracer's
 * model: mpl_light.h); cannot fail. The cut-off applies to linear images
 * only. Adds the rays cast to *counts (may
 * be NULL). Returns the number of threads used. */
int render(const Scene *scene, const RenderOptions *opts, Image *img, RayCounts *counts);

#endif
