/* test_gicache.c: the irradiance cache's records: a furnace, the validity
 * radius, the gradients of known fields, the interpolation's weights. */
#include <math.h>
#include <string.h>

#include "render/gicache.h"
#include "test.h"

/* A field of light around a point: what a gathering ray brings back. */
typedef struct {
    Vec3 origin;   /* the point gathered at */
    int kind;      /* 0: uniform, 1: a sky brightening along +x, 2: a
                      ceiling at height 1 lit by tanh(x), 3: uniform at a
                      distance of 1 + dir.z, 4: a wall x = 0.5 */
    double inverse; /* sum of 1 / distance returned */
} GiField;

static double field_sample(void *ctx, Vec3 dir, Colour *c)
{
    GiField *f = ctx;
    double d = INFINITY;

    switch (f->kind) {
    case 0:
        *c = colour(100, 50, 25);
        d = 2;
        break;
    case 1:
        *c = colour(100 + 60 * (double)dir.x, 100, 100);
        break;
    case 2:
        d = 1 / (double)dir.z;
        *c = colour(100 + 80 * tanh((double)(f->origin.x + d * dir.x)), 100, 100);
        break;
    case 4: /* a wall x = 0.5 standing on the point's plane, nothing else */
        d = dir.x > 0 ? 0.5 / (double)dir.x : INFINITY;
        *c = colour(50, 50, 50);
        break;
    default:
        d = 1 + (double)dir.z;
        *c = colour(10, 10, 10);
        break;
    }
    f->inverse += 1 / d;
    return d;
}

/* Gathers field kind at point p, normal nz, with m x n strata. */
static GiValue field_gather(int kind, Vec3 p, Vec3 normal, int m, int n, double *radius)
{
    GiField f = {p, kind, 0};
    GiValue v;
    double r, open;
    float sees[GICACHE_SECTORS];

    CHECK(gicache_gather(normal, m, n, 7, 0, field_sample, &f, &v, &r, &open, sees) == 0);
    if (radius)
        *radius = r;
    return v;
}

static void gicache_strata_cover_the_rays(void)
{
    int m, n;

    gicache_strata(1, &m, &n);
    CHECK_INT(1, m * n);
    gicache_strata(64, &m, &n);
    CHECK_INT(5, m);
    CHECK_INT(13, n);
    gicache_strata(4096, &m, &n);
    CHECK(fabs(m * n - 4096.0) <= m / 2.0);
    CHECK(n >= 3 * m && n <= 4 * m);
}

/* A furnace: the same light from everywhere. A record holds it exactly, no
 * gradient, and every lookup near it returns it. */
static void gicache_furnace_gives_the_light_everywhere(void)
{
    double r;
    GiValue v = field_gather(0, vec3(0, 0, 0), vec3(0, 0, 1), 5, 13, &r);
    GiCache c;
    GiValue levels[1];
    GiPlace place = {vec3(0, 0, 0), vec3(0, 0, 1), 0, 0, 0, {0}};
    Colour out = {0, 0, 0};

    CHECK_NEAR(100, v.g.r, 1e-9);
    CHECK_NEAR(50, v.g.g, 1e-9);
    CHECK_NEAR(25, v.g.b, 1e-9);
    CHECK_NEAR(2, r, 1e-12);
    for (int k = 0; k < 3; k++) {
        CHECK(vec3_length(v.trans[k]) < 1e-9);
        CHECK(vec3_length(v.rot[k]) < 1e-9);
    }
    gicache_init(&c, 0.3, 1, 0);
    place.radius = r;
    levels[0] = v;
    CHECK(gicache_add(&c, &place, levels) == 0);
    CHECK(gicache_lookup(&c, 0, 1, vec3(0.3, 0.2, 0), vec3(0, 0, 1), &out) == 1);
    CHECK_NEAR(100, out.r, 1e-9);
    CHECK_NEAR(25, out.b, 1e-9);
    gicache_free(&c);
}

/* The radius is the harmonic mean of the distances the rays met. */
static void gicache_radius_is_the_harmonic_mean_distance(void)
{
    GiField f = {vec3(0, 0, 0), 3, 0};
    GiValue v;
    double r, open;
    float sees[GICACHE_SECTORS];

    CHECK(gicache_gather(vec3(0, 0, 1), 6, 19, 3, 0, field_sample, &f, &v, &r, &open, sees) == 0);
    CHECK_NEAR(6 * 19 / f.inverse, r, 1e-12);
    CHECK_NEAR(0, open, 0);
    CHECK(r > 1 && r < 2);
}

/* A sky brightening along +x: G(N) = 100 + 40 N.x, so turning the normal
 * from +z towards +x (about +y) adds 40 per radian. */
static void gicache_rotation_gradient_of_a_sky(void)
{
    GiValue v = field_gather(1, vec3(0, 0, 0), vec3(0, 0, 1), 36, 113, NULL);
    Vec3 turned = vec3_normalize(vec3(0.1, 0, 1));
    GiPlace place = {vec3(0, 0, 0), vec3(0, 0, 1), 1, 0, 0, {0}};
    Colour guess = gicache_extrapolate(&place, &v, vec3(0, 0, 0), turned);
    GiValue there = field_gather(1, vec3(0, 0, 0), turned, 36, 113, NULL);

    CHECK_NEAR(100, v.g.r, 0.05);
    CHECK_NEAR(40, v.rot[0].y, 1.0);
    CHECK_NEAR(0, v.rot[0].x, 0.5);
    CHECK_NEAR(0, v.rot[1].y, 1e-9); /* green is the same everywhere */
    CHECK_NEAR(there.g.r, guess.r, 0.1);
}

/* A ceiling at height 1 lit by 100 + 80 tanh(x): the translational
 * gradient against the difference of two gatherings 0.02 apart. */
static void gicache_translation_gradient_of_a_ceiling(void)
{
    GiValue v = field_gather(2, vec3(0, 0, 0), vec3(0, 0, 1), 40, 126, NULL);
    GiValue left = field_gather(2, vec3(-0.01, 0, 0), vec3(0, 0, 1), 40, 126, NULL);
    GiValue right = field_gather(2, vec3(0.01, 0, 0), vec3(0, 0, 1), 40, 126, NULL);
    double slope = (right.g.r - left.g.r) / 0.02;

    CHECK(slope > 20);
    CHECK_NEAR(slope, v.trans[0].x, 0.05 * slope);
    CHECK_NEAR(0, v.trans[0].y, 0.05 * slope);
    CHECK_NEAR(0, v.trans[1].x, 1e-9);
}

/* Error and weight: the distance over the radius plus the normals'
 * deviation; nothing at or beyond a, nothing in front. */
static void gicache_error_and_weight(void)
{
    GiPlace place = {vec3(0, 0, 0), vec3(0, 0, 1), 2, 0, 0, {0}};

    CHECK_NEAR(0.5, gicache_error(&place, vec3(1, 0, 0), vec3(0, 0, 1)), 1e-12);
    CHECK_NEAR(sqrt(1 - cos(0.2)), gicache_error(&place, vec3(0, 0, 0),
                                                 vec3(sin(0.2), 0, cos(0.2))), 1e-12);
    CHECK(isinf(gicache_error(&place, vec3(1, 0, -0.5), vec3(0, 0, 1)))); /* record in front */
    CHECK_NEAR(1 / 0.1 - 1 / 0.3, gicache_weight(0.1, 0.3), 1e-12);
    CHECK(gicache_weight(0.3, 0.3) == 0);
    CHECK(gicache_weight(0.5, 0.3) == 0);
    CHECK(gicache_weight(0, 0.3) > 1e11);
}

/* A record half a unit from a wall standing on its plane (as on a floor
 * beside a thin wall) sees it that way: no lookup past the wall reads it
 * (it sees as far as the wall along its plane and 30 degrees above, by
 * eighths of the plane: along the wall, as far as the wall is seen at 45
 * degrees), but away from it the record reaches as far as its error
 * allows. */
static void gicache_sees_no_farther_than_a_wall(void)
{
    GiField f = {vec3(0, 0, 0), 4, 0};
    GiPlace place = {vec3(0, 0, 0), vec3(0, 0, 1), 10, 0, 0, {0}};
    GiValue v;
    double r, open;

    CHECK(gicache_gather(vec3(0, 0, 1), 25, 80, 5, 0, field_sample, &f, &v, &r, &open,
                         place.near) == 0);
    CHECK_NEAR(2, place.near[0], 0.01); /* 1 / 0.5, head on (frame: t1 = x) */
    CHECK_NEAR(2, place.near[7], 0.01);
    CHECK(place.near[2] == 0 && place.near[3] == 0 && place.near[4] == 0 && place.near[5] == 0);
    CHECK(isinf(gicache_error(&place, vec3(0.6, 0, 0), vec3(0, 0, 1))));
    CHECK(isinf(gicache_error(&place, vec3(0.55, 0.2, 0), vec3(0, 0, 1))));
    CHECK_NEAR(0.04, gicache_error(&place, vec3(0.4, 0, 0), vec3(0, 0, 1)), 1e-12);
    CHECK_NEAR(0.3, gicache_error(&place, vec3(-3, 0, 0), vec3(0, 0, 1)), 1e-12);
    CHECK_NEAR(0.06, gicache_error(&place, vec3(0, 0.6, 0), vec3(0, 0, 1)), 1e-12);
    CHECK(isinf(gicache_error(&place, vec3(0, 0.8, 0), vec3(0, 0, 1))));
    CHECK_NEAR(0.2, gicache_error(&place, vec3(-1.2, -1.6, 0), vec3(0, 0, 1)), 1e-12);
}

/* Adds records at p[0..n) to c, record i of value values[i] (red) at its
 * first level, 0 elsewhere, without gradients. */
static void add_records(GiCache *c, const GiPlace *p, const double *values, int n)
{
    for (int i = 0; i < n; i++) {
        GiValue v[2];

        memset(v, 0, sizeof v);
        v[0].g = colour(values[i], 0, 0);
        CHECK(c->levels <= 2 && gicache_add(c, &p[i], v) == 0);
    }
}

/* Interpolation is the mean of the valid records' values by their weights
 * (which sum to one once normalised); records out of reach add nothing. */
static void gicache_lookup_is_the_weighted_mean(void)
{
    GiCache c;
    GiPlace p[4] = {{vec3(0, 0, 0), vec3(0, 0, 1), 1, 0, 0, {0}},
                    {vec3(0.2, 0, 0), vec3(0, 0, 1), 2, 0, 0, {0}},
                    {vec3(0, 0.1, 0), vec3(0, 0, 1), 0.5, 0, 0, {0}},
                    {vec3(50, 0, 0), vec3(0, 0, 1), 1, 0, 0, {0}}};
    double values[4] = {10, 20, 40, 1000}, want = 0, total = 0;
    Vec3 x = vec3(0.05, 0.03, 0), n = vec3(0, 0, 1);
    Colour out = {0, 0, 0};

    gicache_init(&c, 0.4, 2, 0);
    add_records(&c, p, values, 4);
    for (int i = 0; i < 4; i++) { /* the radii as neighbour clamping left them */
        double w = gicache_weight(gicache_error(&c.places[i], x, n), 0.4);
        want += w * values[i];
        total += w;
    }
    CHECK_NEAR(0.5 + 0.1, c.places[0].radius, 1e-12); /* no more than record 2's + 0.1 */
    CHECK_INT(3, gicache_lookup(&c, 0, 1, x, n, &out));
    CHECK_NEAR(want / total, out.r, 1e-9);
    CHECK(out.r > 10 && out.r < 40);
    CHECK_INT(3, gicache_lookup(&c, 1, 1, x, n, &out)); /* the second level: zeros */
    CHECK_NEAR(0, out.r, 1e-12);
    CHECK_INT(0, gicache_lookup(&c, 0, 1, vec3(10, 10, 10), n, &out));
    CHECK_INT(0, gicache_lookup(&c, 0, 1, x, vec3(0, 0, -1), &out)); /* facing away */
    c.places[2].first = 1; /* a record holding only the second level on */
    CHECK_INT(2, gicache_lookup(&c, 0, 1, x, n, &out));
    CHECK_INT(3, gicache_lookup(&c, 1, 1, x, n, &out));
    CHECK(gicache_memory(&c) > 0);
    gicache_free(&c);
}

/* gicache_any() gives one valid record's value (none out of reach, none
 * not holding the level), and finds one wherever a lookup finds any. */
static void gicache_any_gives_one_valid_record(void)
{
    GiCache c;
    GiPlace p[3] = {{vec3(0, 0, 0), vec3(0, 0, 1), 1, 0, 0, {0}},
                    {vec3(0.2, 0, 0), vec3(0, 0, 1), 2, 0, 0, {0}},
                    {vec3(50, 0, 0), vec3(0, 0, 1), 1, 0, 0, {0}}};
    double values[3] = {10, 20, 1000};
    Vec3 x = vec3(0.05, 0.03, 0), n = vec3(0, 0, 1);
    Colour out = {-1, 0, 0}, blend;
    uint64_t h = 99;
    int agree = 0;

    gicache_init(&c, 0.4, 1, 0);
    add_records(&c, p, values, 3);
    CHECK_INT(1, gicache_any(&c, 0, 1, x, n, NULL, &out));
    CHECK(out.r == 10 || out.r == 20);
    out.r = -1;
    CHECK_INT(0, gicache_any(&c, 0, 1, vec3(10, 10, 10), n, NULL, &out));
    CHECK_NEAR(-1, out.r, 0); /* untouched */
    /* Each record holding only later levels in turn: the other it is
     * (whichever the grid lists first). */
    c.places[0].first = 1;
    CHECK_INT(1, gicache_any(&c, 0, 1, x, n, NULL, &out));
    CHECK_NEAR(20, out.r, 0);
    c.places[0].first = 0;
    c.places[1].first = 1;
    CHECK_INT(1, gicache_any(&c, 0, 1, x, n, NULL, &out));
    CHECK_NEAR(10, out.r, 0);
    c.places[1].first = 0;
    /* A hint valid at x is the record read (the first of the two that is);
     * none valid there (out of reach, or none yet) gives way to the grid's
     * first, which is kept in hint[0]. */
    for (uint32_t i = 0; i < 2; i++) {
        uint32_t hint[2] = {i, 1 - i}, second[2] = {2, i};
        CHECK_INT(1, gicache_any(&c, 0, 1, x, n, hint, &out));
        CHECK_NEAR(values[i], out.r, 0);
        CHECK_INT((int)i, (int)hint[0]);
        CHECK_INT(1, gicache_any(&c, 0, 1, x, n, second, &out));
        CHECK_NEAR(values[i], out.r, 0);
        CHECK_INT((int)i, (int)second[0]);
    }
    {
        uint32_t hint[2] = {2, 2}, none[2] = {GICACHE_NO_HINT, GICACHE_NO_HINT};
        Colour first;
        CHECK_INT(1, gicache_any(&c, 0, 1, x, n, NULL, &first));
        CHECK_INT(1, gicache_any(&c, 0, 1, x, n, hint, &out));
        CHECK_NEAR(first.r, out.r, 0);
        CHECK(hint[0] < 2 && values[hint[0]] == first.r);
        CHECK_INT(1, gicache_any(&c, 0, 1, x, n, none, &out));
        CHECK(none[0] < 2 && values[none[0]] == first.r);
        /* Out of every record's reach: 0, the hints left as they were. */
        CHECK_INT(0, gicache_any(&c, 0, 1, vec3(10, 10, 10), n, hint, &out));
        CHECK(hint[0] < 2 && hint[1] == 2);
    }
    gicache_free(&c);
    gicache_init(&c, 0.3, 1, 0);
    for (int i = 0; i < 200; i++) {
        GiPlace q = {vec3(0, 0, 0), vec3(0, 0, 1), 0, 0, 0, {0}};
        GiValue v[1];
        memset(v, 0, sizeof v);
        h = h * 6364136223846793005ULL + 1442695040888963407ULL;
        q.point = vec3((double)(h >> 40 & 1023) / 100, (double)(h >> 20 & 1023) / 100, 0);
        q.radius = 0.05 + (double)(h >> 8 & 255) / 100;
        v[0].g = colour(i, 0, 0);
        CHECK(gicache_add(&c, &q, v) == 0);
    }
    gicache_refile(&c);
    /* Without a hint, and with one carried from lookup to lookup along a
     * walk of short steps (as a gathering's rays meet points): a record
     * wherever a lookup finds any, and a valid one. */
    uint32_t hint[2] = {GICACHE_NO_HINT, GICACHE_NO_HINT};
    for (int k = 0; k < 800; k++) {
        int any, all;
        h = h * 6364136223846793005ULL + 1442695040888963407ULL;
        if (k < 400)
            x = vec3((double)(h >> 40 & 1023) / 100, (double)(h >> 20 & 1023) / 100, 0);
        else
            x = vec3(fmod(x.x + (double)(h >> 40 & 63) / 400, 10.24),
                     fmod(x.y + (double)(h >> 20 & 63) / 400, 10.24), 0);
        any = gicache_any(&c, 0, 1, x, n, k < 400 ? NULL : hint, &out);
        all = gicache_lookup(&c, 0, 1, x, n, &blend);
        /* A record's value is its number: the one found must be valid. */
        agree += any == (all > 0) &&
                 (!any || gicache_weight(gicache_error(&c.places[(size_t)out.r], x, n), 0.3) > 0);
    }
    CHECK_INT(800, agree);
    gicache_free(&c);
}

/* A lookup reads every record whose reach holds the point, wherever the
 * point falls among the grid's cells: a record whose reach spans three
 * cells of its scale is found from the third (it was missed there), and
 * over a field of records and points the lookups count what testing every
 * record counts, before and after the records are filed again. */
static void gicache_lookup_finds_every_record_in_reach(void)
{
    GiCache c;
    /* Reach 2 x 0.3 x 1 = 0.6: cells of side 1; its box, -0.1 to 1.1
     * across, spans three. */
    GiPlace edge = {vec3(0.5, 0.5, 0.5), vec3(0, 0, 1), 1, 0, 0, {0}};
    GiValue v[1];
    Colour out;
    uint64_t h = 12345;
    int same = 0;

    memset(v, 0, sizeof v);
    gicache_init(&c, 0.3, 1, 0);
    CHECK(gicache_add(&c, &edge, v) == 0);
    CHECK_INT(1, gicache_lookup(&c, 0, 2, vec3(1.05, 0.5, 0.5), vec3(0, 0, 1), &out));
    CHECK_INT(1, gicache_lookup(&c, 0, 2, vec3(0.5, -0.05, 0.5), vec3(0, 0, 1), &out));
    gicache_free(&c);
    gicache_init(&c, 0.3, 1, 0);
    for (int i = 0; i < 300; i++) {
        GiPlace p = {vec3(0, 0, 0), vec3(0, 0, 1), 0, 0, 0, {0}};
        h = h * 6364136223846793005ULL + 1442695040888963407ULL;
        p.point = vec3((double)(h >> 40 & 1023) / 100, (double)(h >> 20 & 1023) / 100, 0);
        p.radius = 0.05 + (double)(h >> 8 & 255) / 100;
        CHECK(gicache_add(&c, &p, v) == 0);
    }
    for (int pass = 0; pass < 2; pass++) {
        for (int k = 0; k < 400; k++) {
            Vec3 x, n = vec3(0, 0, 1);
            int brute = 0, near = 0;
            h = h * 6364136223846793005ULL + 1442695040888963407ULL;
            x = vec3((double)(h >> 40 & 1023) / 100, (double)(h >> 20 & 1023) / 100, 0);
            for (size_t i = 0; i < c.count; i++) {
                brute += gicache_weight(gicache_error(&c.places[i], x, n), 0.6) > 0;
                near += gicache_weight(gicache_error(&c.places[i], x, n), 0.3) > 0;
            }
            /* Reach 2 reads the wider grid, reach 1 the finer. */
            same += gicache_lookup(&c, 0, 2, x, n, &out) == brute &&
                    gicache_lookup(&c, 0, 1, x, n, &out) == near;
        }
        gicache_refile(&c);
    }
    CHECK_INT(800, same);
    gicache_free(&c);
}

/* A cache whose limit is too small refuses the record, unchanged. */
static void gicache_limit_refuses_records(void)
{
    GiCache c;
    GiPlace p = {vec3(0, 0, 0), vec3(0, 0, 1), 1, 0, 0, {0}};
    GiValue v[1];

    memset(v, 0, sizeof v);
    gicache_init(&c, 0.3, 1, 1000);
    CHECK_INT(-2, gicache_add(&c, &p, v));
    CHECK_INT(0, (int)c.count);
    gicache_free(&c);
}

const TestCase gicache_tests[] = {
    {"gicache_strata_cover_the_rays", gicache_strata_cover_the_rays},
    {"gicache_any_gives_one_valid_record", gicache_any_gives_one_valid_record},
    {"gicache_furnace_gives_the_light_everywhere", gicache_furnace_gives_the_light_everywhere},
    {"gicache_radius_is_the_harmonic_mean_distance", gicache_radius_is_the_harmonic_mean_distance},
    {"gicache_rotation_gradient_of_a_sky", gicache_rotation_gradient_of_a_sky},
    {"gicache_translation_gradient_of_a_ceiling", gicache_translation_gradient_of_a_ceiling},
    {"gicache_error_and_weight", gicache_error_and_weight},
    {"gicache_sees_no_farther_than_a_wall", gicache_sees_no_farther_than_a_wall},
    {"gicache_lookup_is_the_weighted_mean", gicache_lookup_is_the_weighted_mean},
    {"gicache_limit_refuses_records", gicache_limit_refuses_records},
    {"gicache_lookup_finds_every_record_in_reach", gicache_lookup_finds_every_record_in_reach},
    {NULL, NULL},
};
