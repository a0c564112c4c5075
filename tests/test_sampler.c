/* test_sampler.c: pixel and lens sample positions. */
#include <math.h>
#include <string.h>

#include "render/sampler.h"
#include "test.h"

static void sampler_grid_is_the_squarest_factoring(void)
{
    static const unsigned n[] = {1, 2, 7, 12, 16, 18, 65536};
    static const unsigned cols[] = {1, 1, 1, 3, 4, 3, 256};

    for (size_t i = 0; i < sizeof n / sizeof n[0]; i++) {
        SamplerGrid g = sampler_grid(n[i]);
        CHECK_INT(cols[i], g.cols);
        CHECK_INT(n[i], g.cols * g.rows);
    }
}

static void sampler_one_sample_is_the_centre(void)
{
    SamplerGrid g = sampler_grid(1);
    double xy[2];

    sampler_sample(&g, 17, 3, 0, SAMPLER_DIM_PIXEL, xy);
    CHECK_NEAR(0.5, xy[0], 0);
    CHECK_NEAR(0.5, xy[1], 0);
}

/* Checks that the n samples of pixel (px, py) in dimension dim are
 * multi-jittered: one per cell of the grid, one per column strip and one
 * per row strip of width 1 / n. */
static void check_multi_jittered(unsigned n, int px, int py, unsigned dim)
{
    SamplerGrid g = sampler_grid(n);
    unsigned char cell[256] = {0}, xs[256] = {0}, ys[256] = {0};
    int bad = 0;

    for (unsigned k = 0; k < n; k++) {
        double xy[2];
        unsigned cx, cy, sx, sy;

        sampler_sample(&g, px, py, k, dim, xy);
        if (!(xy[0] >= 0 && xy[0] < 1 && xy[1] >= 0 && xy[1] < 1)) {
            bad++;
            continue;
        }
        cx = (unsigned)(xy[0] * g.cols);
        cy = (unsigned)(xy[1] * g.rows);
        sx = (unsigned)(xy[0] * n);
        sy = (unsigned)(xy[1] * n);
        cell[cy * g.cols + cx]++;
        xs[sx]++;
        ys[sy]++;
    }
    for (unsigned i = 0; i < n; i++)
        bad += cell[i] != 1 || xs[i] != 1 || ys[i] != 1;
    if (bad)
        test_fail(__FILE__, __LINE__, "n = %u, pixel (%d, %d), dim %u: %d faults", n, px, py,
                  dim, bad);
}

static void sampler_patterns_are_multi_jittered(void)
{
    static const unsigned n[] = {2, 3, 4, 6, 7, 12, 16, 64, 100, 255};

    for (size_t i = 0; i < sizeof n / sizeof n[0]; i++)
        for (unsigned dim = 0; dim < 2; dim++) {
            check_multi_jittered(n[i], 0, 0, dim);
            check_multi_jittered(n[i], 5, 9, dim);
            check_multi_jittered(n[i], 32767, 32767, dim);
        }
}

static void sampler_depends_only_on_pixel_sample_and_dimension(void)
{
    SamplerGrid g = sampler_grid(16);
    double a[2], b[2], c[2], d[2];

    sampler_sample(&g, 10, 20, 5, SAMPLER_DIM_PIXEL, a);
    sampler_sample(&g, 10, 20, 5, SAMPLER_DIM_PIXEL, b);
    CHECK(memcmp(a, b, sizeof a) == 0);
    sampler_sample(&g, 11, 20, 5, SAMPLER_DIM_PIXEL, c);
    sampler_sample(&g, 10, 20, 5, SAMPLER_DIM_LENS, d);
    CHECK(memcmp(a, c, sizeof a) != 0);
    CHECK(memcmp(a, d, sizeof a) != 0);
}

static void sampler_disk_keeps_area_and_centre(void)
{
    double centre[2] = {0.5, 0.5}, corner[2] = {1, 0}, out[2];
    int inner = 0, total = 0, outside = 0;

    sampler_disk(centre, out);
    CHECK_NEAR(0, out[0], 0);
    CHECK_NEAR(0, out[1], 0);
    sampler_disk(corner, out);
    CHECK_NEAR(1, hypot(out[0], out[1]), 1e-15);
    /* The square's middle quarter (a square ring map) fills radius 1/2: a
     * quarter of the area, as it should. */
    for (int i = 0; i < 200; i++)
        for (int j = 0; j < 200; j++) {
            double p[2] = {(i + 0.5) / 200, (j + 0.5) / 200};
            double r;
            sampler_disk(p, out);
            r = hypot(out[0], out[1]);
            outside += r > 1 + 1e-15;
            inner += r < 0.5;
            total++;
        }
    CHECK_INT(0, outside);
    CHECK_INT(total / 4, inner);
}

/* Counts the elementary boxes of shape 2^a x 2^(m - a), for every a,
 * that do not hold exactly one of the 2^m points xy (a (0, m, 2)-net
 * holds one in each). */
static int sobol_net_faults(double (*xy)[2], unsigned m)
{
    unsigned n = 1u << m;
    int faults = 0;

    for (unsigned a = 0; a <= m; a++) {
        unsigned char count[1024] = {0};
        for (unsigned k = 0; k < n; k++) {
            unsigned i = (unsigned)(xy[k][0] * (1u << a)), j = (unsigned)(xy[k][1] * (1u << (m - a)));
            count[(j << a) | i]++;
        }
        for (unsigned b = 0; b < n; b++)
            faults += count[b] != 1;
    }
    return faults;
}

static void sampler_sobol_prefixes_and_their_blocks_are_nets(void)
{
    static double xy[1024][2];

    for (uint64_t seed = 1; seed <= 40; seed++) {
        for (unsigned k = 0; k < 1024; k++) {
            sampler_sobol(seed * 0x9e3779b97f4a7c15u, k, xy[k]);
            if (!(xy[k][0] >= 0 && xy[k][0] < 1 && xy[k][1] >= 0 && xy[k][1] < 1))
                test_fail(__FILE__, __LINE__, "seed %u, point %u outside the square",
                          (unsigned)seed, k);
        }
        /* Every prefix of 2^m points, and every aligned block of 2^m
         * (noise.h's eighths), one point a box. */
        for (unsigned m = 0; m <= 10; m++)
            for (unsigned start = 0; start + (1u << m) <= 1024; start += 1u << m) {
                int f = sobol_net_faults(xy + start, m);
                if (f)
                    test_fail(__FILE__, __LINE__, "seed %u, points %u..%u: %d boxes off",
                              (unsigned)seed, start, start + (1u << m) - 1, f);
            }
    }
}

static void sampler_sobol_sequences_differ_by_seed_and_agree_by_seed(void)
{
    double a[2], b[2], c[2];
    int same = 0;

    for (unsigned k = 0; k < 64; k++) {
        sampler_sobol(7, k, a);
        sampler_sobol(7, k, b);
        sampler_sobol(8, k, c);
        CHECK_NEAR(a[0], b[0], 0);
        CHECK_NEAR(a[1], b[1], 0);
        same += a[0] == c[0] || a[1] == c[1];
    }
    CHECK_INT(0, same);
}

static void sampler_progressive_layout_draws_sobol_points(void)
{
    SamplerGrid g = sampler_progressive();
    double p[2], l[2], sq[2];
    int same = 0;

    /* Pixel, lens and a path's directions: each its own sequence, the
     * same for the same pixel, sample and dimension. */
    for (unsigned k = 0; k < 32; k++) {
        double again[2];
        sampler_sample(&g, 3, 4, k, SAMPLER_DIM_PIXEL, p);
        sampler_sample(&g, 3, 4, k, SAMPLER_DIM_PIXEL, again);
        sampler_sample(&g, 3, 4, k, SAMPLER_DIM_LENS, l);
        sampler_square(&g, 3, 4, k, 12345, sq);
        CHECK_NEAR(p[0], again[0], 0);
        same += p[0] == l[0] || p[0] == sq[0] || l[0] == sq[0];
    }
    CHECK_INT(0, same);
}

const TestCase sampler_tests[] = {
    {"sampler_sobol_prefixes_and_their_blocks_are_nets",
     sampler_sobol_prefixes_and_their_blocks_are_nets},
    {"sampler_sobol_sequences_differ_by_seed_and_agree_by_seed",
     sampler_sobol_sequences_differ_by_seed_and_agree_by_seed},
    {"sampler_progressive_layout_draws_sobol_points", sampler_progressive_layout_draws_sobol_points},
    {"sampler_grid_is_the_squarest_factoring", sampler_grid_is_the_squarest_factoring},
    {"sampler_one_sample_is_the_centre", sampler_one_sample_is_the_centre},
    {"sampler_patterns_are_multi_jittered", sampler_patterns_are_multi_jittered},
    {"sampler_depends_only_on_pixel_sample_and_dimension",
     sampler_depends_only_on_pixel_sample_and_dimension},
    {"sampler_disk_keeps_area_and_centre", sampler_disk_keeps_area_and_centre},
    {NULL, NULL},
};
