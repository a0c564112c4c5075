/* test_noise.c: the rounds and the error estimate of --noise. */
#include <math.h>
#include <string.h>

#include "render/noise.h"
#include "render/sampler.h"
#include "test.h"

static void noise_rounds_are_powers_of_two_within_the_bounds(void)
{
    CHECK_INT(16, noise_default_min(8));
    CHECK_INT(16, noise_default_min(4));
    CHECK_INT(32, noise_default_min(3));
    CHECK_INT(64, noise_default_min(1));
    CHECK_INT(128, noise_default_min(0.5));
    CHECK_INT(256, noise_default_min(0.01));
    NoiseOptions o = {1, 16, 4096};

    CHECK_INT(16, noise_first(&o));
    CHECK_INT(4096, noise_most(&o));
    o.min_spp = 17;
    o.max_spp = 1000;
    CHECK_INT(32, noise_first(&o));
    CHECK_INT(512, noise_most(&o)); /* 32 x 2^4 */
    o.min_spp = 1;
    o.max_spp = 1;
    CHECK_INT(NOISE_BLOCKS, noise_first(&o)); /* never fewer than the blocks */
    CHECK_INT(NOISE_BLOCKS, noise_most(&o));
    o = (NoiseOptions){1, 16, 4096};
    CHECK_INT(16, noise_next(&o, 16, 1.0));       /* within the level: stop */
    CHECK_INT(32, noise_next(&o, 16, 1.01));      /* above it: twice */
    CHECK_INT(32, noise_next(&o, 16, 1000));      /* however far */
    CHECK_INT(4096, noise_next(&o, 2048, 1000));  /* up to the most */
    CHECK_INT(4096, noise_next(&o, 4096, 1000));  /* and no further */
    o.max_spp = 1000;
    CHECK_INT(512, noise_next(&o, 512, 1000));    /* 512 is the most */
    CHECK_INT(16, noise_next(&o, 16, NAN));       /* no number: no more */
}

/* The samples of the synthetic pixel: sample k is (k, 2k, 3k) x scale. */
static Colour noise_ramp_sample(void *ctx, unsigned k)
{
    double s = *(const double *)ctx;

    return colour(k * s, 2 * k * s, 3 * k * s);
}

static void noise_blocks_follow_the_rounds(void)
{
    static const unsigned rounds[] = {16, 32, 128, 1024, 2048};
    NoisePixel p = {{{0, 0, 0}}, 0};
    double scale = 1;

    for (size_t i = 0; i < sizeof rounds / sizeof rounds[0]; i++) {
        unsigned n = rounds[i], q = n / NOISE_BLOCKS;
        noise_take(&p, n, noise_ramp_sample, &scale);
        CHECK_INT(n, p.n);
        /* ends[r] = 0 + 1 + ... + (r q - 1) in red. */
        for (unsigned r = 0; r <= NOISE_BLOCKS; r++) {
            double m = (double)r * q;
            CHECK_NEAR(m * (m - 1) / 2, p.ends[r].r, 0);
            CHECK_NEAR(3 * m * (m - 1) / 2, p.ends[r].b, 0);
        }
        CHECK_NEAR((n - 1) / 2.0, noise_mean(&p).r, 1e-12);
    }
}

static void noise_error_is_the_blocks_standard_error(void)
{
    NoiseScale linear = {1, 1}, raw = {1, 0}, gamma = {2.2, 1};
    NoisePixel p = {{{0, 0, 0}}, 2 * NOISE_BLOCKS};
    /* Block means 10, 12, ..., 24 in every channel (2 samples a block):
     * deviations -7 -5 ... 5 7, sum of squares 168, 168 / (8 x 7) = 3. */
    double run = 0;

    CHECK_INT(8, NOISE_BLOCKS);
    for (int r = 0; r < NOISE_BLOCKS; r++) {
        run += 2 * (10 + 2 * r);
        p.ends[r + 1] = colour(run, run, run);
    }
    CHECK_NEAR(sqrt(3.0), noise_error(&p, linear), 1e-12);
    CHECK_NEAR(17, noise_mean(&p).g, 1e-12);
    /* Far above white, the displayed value does not move: no error; the
     * unclamped one (PFM) still does. */
    for (int r = 1; r <= NOISE_BLOCKS; r++)
        p.ends[r] = colour_add(p.ends[r], colour(2000.0 * r, 2000.0 * r, 2000.0 * r));
    CHECK_NEAR(0, noise_error(&p, linear), 0);
    CHECK_NEAR(sqrt(3.0), noise_error(&p, raw), 1e-9);
    for (int r = 1; r <= NOISE_BLOCKS; r++)
        p.ends[r] = colour_add(p.ends[r], colour(-2000.0 * r, -2000.0 * r, -2000.0 * r));
    /* Gamma 2.2 stretches dark levels: the error on the display is larger
     * there than in linear levels. */
    CHECK(noise_error(&p, gamma) > 2 * noise_error(&p, linear));
}

/* The estimate against the truth: a pixel cut by an edge (x + 0.3 y <
 * 0.6 is 200 levels, the rest 0) sampled by Owen-scrambled Sobol points,
 * over many independent scramblings. The estimate must not fall short of
 * the true standard error (it errs on the safe side, noise.h), and not
 * exceed it by more than noise.h says (some 2 times at an edge, 1.6 to
 * 1.9 measured here; 2 is the bound tested). */
static void noise_estimate_errs_safe_but_not_far(void)
{
    NoiseScale raw = {1, 0};

    for (unsigned n = 16; n <= 1024; n *= 4) {
        double sq_err = 0, sq_est = 0;
        const int trials = 2000;

        for (int t = 0; t < trials; t++) {
            NoisePixel p = {{{0, 0, 0}}, 0};
            Colour run = colour(0, 0, 0);
            double v;

            for (unsigned k = 0; k < n; k++) {
                double xy[2];
                sampler_sobol(0x1234567ull + (uint64_t)t * 0x9e3779b97f4a7c15ull, k, xy);
                v = xy[0] + 0.3 * xy[1] < 0.6 ? 200 : 0;
                run = colour_add(run, colour(v, v, v));
                if ((k + 1) % (n / NOISE_BLOCKS) == 0)
                    p.ends[(k + 1) / (n / NOISE_BLOCKS)] = run;
            }
            p.n = n;
            /* The pixel's true value: 200 x the area below the line. */
            v = noise_mean(&p).r - 200 * (0.6 - 0.15);
            sq_err += v * v;
            v = noise_error(&p, raw);
            sq_est += v * v;
        }
        if (!(sq_est >= 0.9 * sq_err && sq_est <= 4 * sq_err))
            test_fail(__FILE__, __LINE__,
                      "n = %u: true standard error %.4g, estimated %.4g (ratio %.3g)", n,
                      sqrt(sq_err / trials), sqrt(sq_est / trials), sqrt(sq_est / sq_err));
    }
}

static void noise_summary_counts_and_bins(void)
{
    unsigned spp[6] = {16, 16, 32, 64, 4096, 5000};
    float error[6] = {0, 0.5f, 1, 1, 2, 3};
    NoiseSummary s;

    noise_summarise(spp, error, 6, &s);
    CHECK_NEAR((16 + 16 + 32 + 64 + 4096 + 5000) / 6.0, s.mean_spp, 1e-9);
    CHECK_INT(5000, s.max_spp);
    CHECK_NEAR(7.5 / 6, s.mean_error, 1e-6);
    CHECK_NEAR(3, s.worst_error, 0);
    CHECK_INT(2, s.bins[2]);  /* <= 16 */
    CHECK_INT(1, s.bins[3]);  /* <= 32 */
    CHECK_INT(1, s.bins[4]);  /* <= 64 */
    CHECK_INT(1, s.bins[10]); /* <= 4096 */
    CHECK_INT(1, s.bins[11]); /* <= 8192 */
}

static void noise_heat_map_runs_from_black_to_white(void)
{
    unsigned spp[4] = {16, 8, 4096, 9000};
    Image img;

    CHECK_INT(0, image_init(&img, 4, 1));
    noise_heat_map(spp, 16, 4096, &img);
    CHECK_INT(0, img.rgb[0] + img.rgb[1] + img.rgb[2]); /* the least: black */
    CHECK_INT(0, img.rgb[3] + img.rgb[4] + img.rgb[5]); /* fewer: black too */
    CHECK_INT(3 * 255, img.rgb[6] + img.rgb[7] + img.rgb[8]); /* the most: white */
    CHECK_INT(3 * 255, img.rgb[9] + img.rgb[10] + img.rgb[11]);
    image_free(&img);
}

const TestCase noise_tests[] = {
    {"noise_rounds_are_powers_of_two_within_the_bounds",
     noise_rounds_are_powers_of_two_within_the_bounds},
    {"noise_blocks_follow_the_rounds", noise_blocks_follow_the_rounds},
    {"noise_error_is_the_blocks_standard_error", noise_error_is_the_blocks_standard_error},
    {"noise_estimate_errs_safe_but_not_far", noise_estimate_errs_safe_but_not_far},
    {"noise_summary_counts_and_bins", noise_summary_counts_and_bins},
    {"noise_heat_map_runs_from_black_to_white", noise_heat_map_runs_from_black_to_white},
    {NULL, NULL},
};
