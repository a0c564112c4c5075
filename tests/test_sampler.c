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

const TestCase sampler_tests[] = {
    {"sampler_grid_is_the_squarest_factoring", sampler_grid_is_the_squarest_factoring},
    {"sampler_one_sample_is_the_centre", sampler_one_sample_is_the_centre},
    {"sampler_patterns_are_multi_jittered", sampler_patterns_are_multi_jittered},
    {"sampler_depends_only_on_pixel_sample_and_dimension",
     sampler_depends_only_on_pixel_sample_and_dimension},
    {"sampler_disk_keeps_area_and_centre", sampler_disk_keeps_area_and_centre},
    {NULL, NULL},
};
