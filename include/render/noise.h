/*
 * noise.h: under --noise, how many samples a pixel takes and how far from
 * converged its value is.
 *
 * A pixel's n samples are the first n points of its low-discrepancy
 * sequences (sampler.h; n a power of two), and its value is their mean.
 * The error of that mean is estimated from the pixel's own samples alone,
 * so the bytes do not depend on threads, tiles or the order pixels are
 * rendered in: the n points fall into NOISE_BLOCKS consecutive blocks,
 * each itself a randomised net of n / NOISE_BLOCKS points (sampler.h),
 * whose means m_1..m_R each estimate the pixel; with m their mean, the
 * standard error of m is taken as sqrt(sum (m_r - m)^2 / (R (R - 1))),
 * randomised quasi-Monte Carlo's replicate estimate (Owen 1997). The
 * blocks are not independent: each fills the gaps the others leave, so
 * the mean of all is closer than independent blocks would be, and the
 * estimate errs on the safe side (by up to some 2 times where the
 * picture has edges, and more where it is smooth and its error small);
 * unlike the samples' own variance over n it still credits the sequence
 * for its spread, by as much as the blocks' means agree.
 *
 * The error is that of the displayed value (the colour clamped to 0..255,
 * gamma-encoded where the image is; unclamped where the image keeps its
 * linear colours), root-mean-square over the three channels: one standard
 * error, so about 68% of pixels lie within it of the converged picture,
 * and a picture's RMSE against that is at most about the level asked for.
 *
 * Rounds: the first takes noise_first() samples; after each round, a
 * pixel whose error exceeds the level takes as many again (noise_next()),
 * until its error is at most the level or it has noise_most() samples.
 * Its last round's error is then between the level and about 0.6 of it
 * (the error of a doubled count falls by 2^-0.5 to 2^-0.75).
 */
#ifndef RAYTRACE_NOISE_H
#define RAYTRACE_NOISE_H

#include <stddef.h>

#include "image/image.h"
#include "math/colour.h"
#include "scene/scene.h"

enum {
    NOISE_BLOCKS = 8,           /* blocks a pixel's samples are compared in:
                                   eight, seven degrees of freedom, so that
                                   a pixel seldom stops on a lucky low
                                   estimate (four stopped focus.txt's
                                   pixels at 1.46 L, eight at 1.17 L;
                                   docs/log.md) */
    NOISE_MIN_SPP = 16,         /* least default first round (noise_default_min()) */
    NOISE_MIN_SPP_TOP = 256,    /* most default first round */
    NOISE_MAX_SPP = 4096,       /* default most samples a pixel */
    NOISE_SPP_LIMIT = SCENE_MAX_SPP, /* largest --max-spp accepted */
    NOISE_BINS = 16             /* histogram bins: samples up to 4 x 2^k */
};

/* What the user accepts: level 0 turns adaptive sampling off. */
typedef struct {
    double level;     /* the error accepted, in levels of 0..255 (> 0) */
    unsigned min_spp; /* least samples a pixel, 1..max_spp */
    unsigned max_spp; /* most samples a pixel, .. NOISE_SPP_LIMIT */
} NoiseOptions;

/* The samples a pixel has taken: their sums, block by block. */
typedef struct {
    Colour ends[NOISE_BLOCKS + 1]; /* ends[r]: the sum of the first r n / R
                                      samples' colours (ends[0] zero) */
    unsigned n;                    /* samples taken, a multiple of R */
} NoisePixel;

/* How colours are displayed: what the error is measured on. */
typedef struct {
    double gamma; /* bytes encode colours with this gamma; 1: linear */
    int clamp;    /* 1: values clamp to 0..255 (bytes); 0: kept (PFM) */
} NoiseScale;

/* Returns the display scale of img (image.h). */
NoiseScale noise_scale_of(const Image *img);

/* Returns the default least samples a pixel for level: 64 / level rounded
 * up to a power of two, from NOISE_MIN_SPP to NOISE_MIN_SPP_TOP. A pixel
 * whose first round agrees everywhere stops there, so a feature that
 * round misses (a quarter of a pixel and lens in defocus blur, measured:
 * 1% of pixels at 16 samples) goes uncorrected; the first round grows as
 * the level falls, so that what it misses shrinks with the error
 * accepted (docs/log.md). */
unsigned noise_default_min(double level);

/* Returns the samples of the first round: min_spp rounded up to a power
 * of two (the sequences' best-spread counts), at least NOISE_BLOCKS. */
unsigned noise_first(const NoiseOptions *o);

/* Returns the most samples a pixel takes: max_spp rounded down to
 * noise_first() times a power of two, at least noise_first(). */
unsigned noise_most(const NoiseOptions *o);

/* Returns the samples a pixel has after the next round when it has n and
 * its error is `error`: n when the error is within the level (or is not a
 * number) or no more may be taken; else twice as many. (Jumping by 4 or
 * 8 where the error is far above the level, as an error falling as
 * 1 / sqrt(n) would need, overshoots: the sequences' errors fall faster;
 * measured, docs/log.md.) */
unsigned noise_next(const NoiseOptions *o, unsigned n, double error);

/* Adds to p, whose n samples have block sums for n, the colours of samples
 * n to m - 1 (m a power-of-two multiple of n, or the first round's when n
 * is 0), given in order by `sample` (called with ctx and each sample's
 * number); p's blocks are then m's. */
void noise_take(NoisePixel *p, unsigned m, Colour (*sample)(void *ctx, unsigned k), void *ctx);

/* Returns the pixel's value: the mean of all its samples. */
Colour noise_mean(const NoisePixel *p);

/* Returns the estimated standard error of the pixel's displayed value on
 * scale, root-mean-square over the channels, in levels. */
double noise_error(const NoisePixel *p, NoiseScale scale);

/* A render's samples and errors, summed up for -v. */
typedef struct {
    double mean_spp;           /* samples a pixel, mean */
    unsigned max_spp;          /* most samples a pixel took */
    double mean_error;         /* estimated error, mean over pixels */
    double worst_error;        /* estimated error, largest */
    size_t bins[NOISE_BINS];   /* pixels with at most 4 x 2^k samples
                                  (and more than half that) */
} NoiseSummary;

/* Sums up n pixels' samples and errors. */
void noise_summarise(const unsigned *spp, const float *error, size_t n, NoiseSummary *s);

/* Paints into img (width x height, initialised) a heat map of the samples
 * each pixel took: black at lo or fewer, through red and yellow, to white
 * at hi, on a logarithmic scale (lo <= hi). */
void noise_heat_map(const unsigned *spp, unsigned lo, unsigned hi, Image *img);

#endif
