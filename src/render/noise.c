/* noise.c: rounds of samples and the error estimate of --noise (see
 * noise.h). */
#include "render/noise.h"

#include <math.h>

#include "math/power.h"

NoiseScale noise_scale_of(const Image *img)
{
    NoiseScale s = {img->encode ? img->gamma : 1, img->linear == NULL};

    return s;
}

unsigned noise_default_min(double level)
{
    unsigned n = NOISE_MIN_SPP;

    while (n < NOISE_MIN_SPP_TOP && n * level < 64)
        n *= 2;
    return n;
}

unsigned noise_first(const NoiseOptions *o)
{
    unsigned n = NOISE_BLOCKS;

    while (n < o->min_spp)
        n *= 2;
    return n;
}

unsigned noise_most(const NoiseOptions *o)
{
    unsigned n = noise_first(o);

    while (n <= o->max_spp / 2)
        n *= 2;
    return n;
}

unsigned noise_next(const NoiseOptions *o, unsigned n, double error)
{
    if (!(error > o->level) || n >= noise_most(o))
        return n;
    return 2 * n;
}

void noise_take(NoisePixel *p, unsigned m, Colour (*sample)(void *ctx, unsigned k), void *ctx)
{
    Colour ends[NOISE_BLOCKS + 1], run = p->ends[NOISE_BLOCKS];
    unsigned block = m / NOISE_BLOCKS, f = p->n ? m / p->n : 0;

    /* The new blocks' ends within the old samples are old ends: block r
     * ends at r m / R = (r f) n / R. */
    ends[0] = colour(0, 0, 0);
    for (unsigned r = 1; r * f <= NOISE_BLOCKS && p->n; r++)
        ends[r] = p->ends[r * f];
    for (unsigned k = p->n; k < m; k++) {
        run = colour_add(run, sample(ctx, k));
        if ((k + 1) % block == 0)
            ends[(k + 1) / block] = run;
    }
    for (int r = 0; r <= NOISE_BLOCKS; r++)
        p->ends[r] = ends[r];
    p->n = m;
}

Colour noise_mean(const NoisePixel *p)
{
    Colour s = p->ends[NOISE_BLOCKS];

    return colour(s.r / p->n, s.g / p->n, s.b / p->n);
}

/* Returns the colour value x as displayed on scale s. */
static double noise_display(double x, NoiseScale s)
{
    if (!s.clamp)
        return x;
    if (!(x > 0))
        return 0;
    if (x >= 255)
        return 255;
    return s.gamma == 1 ? x : 255 * power(x / 255, 1 / s.gamma);
}

/* Returns the sum of squared deviations from their mean of the blocks'
 * displayed means in one channel (v[r]). */
static double noise_spread(const double v[NOISE_BLOCKS])
{
    double mean = 0, ss = 0;

    for (int r = 0; r < NOISE_BLOCKS; r++)
        mean += v[r];
    mean /= NOISE_BLOCKS;
    for (int r = 0; r < NOISE_BLOCKS; r++)
        ss += (v[r] - mean) * (v[r] - mean);
    return ss;
}

double noise_error(const NoisePixel *p, NoiseScale scale)
{
    double r[NOISE_BLOCKS], g[NOISE_BLOCKS], b[NOISE_BLOCKS], ss;
    double per = (double)p->n / NOISE_BLOCKS;

    for (int k = 0; k < NOISE_BLOCKS; k++) {
        Colour a = p->ends[k], z = p->ends[k + 1];
        Colour c = colour(z.r - a.r, z.g - a.g, z.b - a.b);
        r[k] = noise_display(c.r / per, scale);
        g[k] = noise_display(c.g / per, scale);
        b[k] = noise_display(c.b / per, scale);
    }
    ss = noise_spread(r) + noise_spread(g) + noise_spread(b);
    /* Each channel's variance of the mean of all, ss / (R (R - 1)); the
     * mean of the three. */
    return sqrt(ss / (3.0 * NOISE_BLOCKS * (NOISE_BLOCKS - 1)));
}

void noise_summarise(const unsigned *spp, const float *error, size_t n, NoiseSummary *s)
{
    double samples = 0, errors = 0;

    *s = (NoiseSummary){0};
    for (size_t i = 0; i < n; i++) {
        int bin = 0;

        samples += spp[i];
        errors += error[i];
        if (spp[i] > s->max_spp)
            s->max_spp = spp[i];
        if (error[i] > s->worst_error)
            s->worst_error = error[i];
        while (bin < NOISE_BINS - 1 && spp[i] > (4u << bin))
            bin++;
        s->bins[bin]++;
    }
    s->mean_spp = n ? samples / n : 0;
    s->mean_error = n ? errors / n : 0;
}

/* The heat map's colours, evenly spaced from few samples to many. */
static const Colour noise_ramp[] = {
    {0, 0, 0}, {90, 0, 110}, {200, 30, 60}, {250, 130, 0}, {250, 230, 60}, {255, 255, 255},
};

void noise_heat_map(const unsigned *spp, unsigned lo, unsigned hi, Image *img)
{
    const int stops = (int)(sizeof noise_ramp / sizeof noise_ramp[0]) - 1;
    double span = hi > lo ? power_log((double)hi / lo) : 1;

    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            unsigned n = spp[(size_t)y * img->width + x];
            double f = n <= lo ? 0 : n >= hi ? 1 : power_log((double)n / lo) / span, at = f * stops;
            int k = at >= stops ? stops - 1 : (int)at;
            double w = at - k;
            Colour a = noise_ramp[k], b = noise_ramp[k + 1];

            image_set(img, x, y,
                      colour(a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b)));
        }
}
