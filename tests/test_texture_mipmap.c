/* test_texture_mipmap.c: mip-maps, lookups over a footprint, filtered stripes, and
 * ray differentials. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/ray.h"
#include "scene/camera.h"
#include "scene/texture.h"
#include "test.h"

#define MIP_DEGREE 0.017453292519943295 /* radians */

/* Makes *t a w x h texture of pseudo-random texels (maxval 1000). */
static void mip_texture(Texture *t, int w, int h, unsigned seed)
{
    size_t n = 3 * (size_t)w * (size_t)h;

    memset(t, 0, sizeof *t);
    t->width = w;
    t->height = h;
    t->scale = 255.0 / 1000;
    t->texels = malloc(n * sizeof *t->texels);
    for (size_t i = 0; i < n; i++) {
        seed = seed * 1103515245u + 12345u;
        t->texels[i] = (unsigned short)((seed >> 16) % 1001);
    }
}

/* Returns channel c of texel (i, j) of level k of t as a colour level. */
static double mip_at(const Texture *t, int k, int i, int j, int c)
{
    if (k == 0)
        return t->texels[3 * ((size_t)j * (size_t)t->width + (size_t)i) + (size_t)c] * t->scale;
    return t->levels[k - 1].texels[3 * ((size_t)j * (size_t)t->levels[k - 1].width + (size_t)i) +
                                   (size_t)c];
}

static void mipmap_levels_are_the_means_of_the_level_below(void)
{
    static const int sizes[][2] = {{8, 8}, {16, 4}, {7, 5}, {1, 9}, {13, 1}, {64, 33}};

    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int w = sizes[s][0], h = sizes[s][1];
        Texture t;
        mip_texture(&t, w, h, (unsigned)s + 1);
        CHECK_INT(0, texture_build_mipmap(&t));
        CHECK(t.level_count > 0);
        CHECK_INT((long long)texture_mipmap_memory(&t) +
                      3 * (long long)w * h * (long long)sizeof *t.texels,
                  (long long)texture_memory(&t));
        /* The last level is 1 x 1 and each halves the one below. */
        CHECK_INT(1, t.levels[t.level_count - 1].width);
        CHECK_INT(1, t.levels[t.level_count - 1].height);
        for (int k = 1; k <= t.level_count; k++) {
            int pw = k == 1 ? w : t.levels[k - 2].width, ph = k == 1 ? h : t.levels[k - 2].height;
            int lw = t.levels[k - 1].width, lh = t.levels[k - 1].height;
            double total_below = 0, total = 0;
            CHECK_INT(pw > 1 ? pw / 2 : 1, lw);
            CHECK_INT(ph > 1 ? ph / 2 : 1, lh);
            /* Whole 2 x 2 boxes (even sides): exactly their mean. */
            if (pw % 2 == 0 && ph % 2 == 0)
                for (int j = 0; j < lh; j++)
                    for (int i = 0; i < lw; i++)
                        for (int c = 0; c < 3; c++) {
                            double m = (mip_at(&t, k - 1, 2 * i, 2 * j, c) +
                                        mip_at(&t, k - 1, 2 * i + 1, 2 * j, c) +
                                        mip_at(&t, k - 1, 2 * i, 2 * j + 1, c) +
                                        mip_at(&t, k - 1, 2 * i + 1, 2 * j + 1, c)) / 4;
                            CHECK_NEAR(m, mip_at(&t, k, i, j, c), 1e-4);
                        }
            /* Any sides: the level's mean is the level below's (each texel
             * of the level below shared out by the boxes that cover it). */
            for (int j = 0; j < ph; j++)
                for (int i = 0; i < pw; i++)
                    total_below += mip_at(&t, k - 1, i, j, 0);
            for (int j = 0; j < lh; j++)
                for (int i = 0; i < lw; i++)
                    total += mip_at(&t, k, i, j, 0);
            CHECK_NEAR(total_below / ((double)pw * ph), total / ((double)lw * lh), 1e-3);
        }
        texture_free(&t);
    }
}

static void footprint_of_a_texel_reads_as_bilinear(void)
{
    Texture t;

    mip_texture(&t, 32, 16, 7);
    CHECK_INT(0, texture_build_mipmap(&t));
    for (int k = 0; k < 50; k++) {
        double u = (k * 0.137) - 2, v = k * 0.0731;
        /* A footprint at most one texel wide. */
        double d[4] = {0.8 / 32, 0.1 / 16, -0.2 / 32, 0.9 / 16};
        Colour a = texture_lookup(&t, u, v, TEXTURE_BILINEAR, 0);
        Colour b = texture_lookup_footprint(&t, u, v, d, TEXTURE_TRILINEAR, 0);
        Colour e = texture_lookup_footprint(&t, u, v, d, TEXTURE_EWA, 0);
        CHECK(memcmp(&a, &b, sizeof a) == 0);
        CHECK(memcmp(&a, &e, sizeof a) == 0);
    }
    texture_free(&t);
}

static void footprint_of_the_whole_image_reads_its_mean(void)
{
    Texture t;
    double mean[3] = {0, 0, 0};
    double d[4] = {4, 0, 0, 4}; /* four images across */

    mip_texture(&t, 16, 16, 3);
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++)
            for (int c = 0; c < 3; c++)
                mean[c] += mip_at(&t, 0, i, j, c) / 256;
    CHECK_INT(0, texture_build_mipmap(&t));
    for (int f = TEXTURE_TRILINEAR; f <= TEXTURE_EWA; f++) {
        Colour c = texture_lookup_footprint(&t, 0.3, 0.6, d, (TextureFilter)f, 0);
        CHECK_NEAR(mean[0], c.r, 1e-3);
        CHECK_NEAR(mean[2], c.b, 1e-3);
    }
    /* Between: a footprint of 3 texels blends levels 1 and 2, 1/2 each. */
    {
        double d3[4] = {3.0 / 16, 0, 0, 0};
        Colour c = texture_lookup_footprint(&t, 0.5, 0.5, d3, TEXTURE_TRILINEAR, 0);
        CHECK(isfinite(c.r) && c.r >= 0 && c.r <= 255);
    }
    /* Without a mip-map, the averaging filters read as bilinear. */
    texture_free(&t);
    mip_texture(&t, 16, 16, 3);
    {
        Colour a = texture_lookup(&t, 0.3, 0.6, TEXTURE_BILINEAR, 0);
        Colour b = texture_lookup_footprint(&t, 0.3, 0.6, d, TEXTURE_TRILINEAR, 0);
        CHECK(memcmp(&a, &b, sizeof a) == 0);
    }
    texture_free(&t);
}

static void stripes_filtered_are_their_box_mean(void)
{
    /* The point's value without a footprint. */
    CHECK_NEAR(1, texture_stripe_cover(0.2, 0), 0);
    CHECK_NEAR(0, texture_stripe_cover(0.7, 0), 0);
    /* A footprint within a stripe: the stripe's value. */
    CHECK_NEAR(1, texture_stripe_cover(0.25, 0.1), 1e-12);
    CHECK_NEAR(0, texture_stripe_cover(0.75, 0.1), 1e-12);
    /* Across an edge: its share; whole periods: one half. */
    CHECK_NEAR(0.5, texture_stripe_cover(0.5, 0.2), 1e-12);
    CHECK_NEAR(0.75, texture_stripe_cover(0.45, 0.2), 1e-12);
    CHECK_NEAR(0.5, texture_stripe_cover(0.3, 1), 1e-12);
    CHECK_NEAR(0.5, texture_stripe_cover(-7.1, 10), 1e-12);
    CHECK_NEAR(0.5, texture_stripe_cover(3.3, 1e9), 1e-12);
    /* Against a fine numerical mean. */
    for (int k = 0; k < 20; k++) {
        double s = k * 0.173 - 1.5, w = 0.05 + k * 0.11, sum = 0;
        for (int i = 0; i < 100000; i++) {
            double x = s - w / 2 + w * (i + 0.5) / 100000;
            sum += x - floor(x) < 0.5;
        }
        CHECK_NEAR(sum / 100000, texture_stripe_cover(s, w), 1e-4);
    }
}

/* The differentials of a pinhole camera's ray through (x, y): central
 * differences of the rays half a pixel either side (so that a mirrored
 * camera's, taken the other way across, agree to rounding). */
static void mip_camera_diff(const Camera *cam, double x, double y, Ray *ray, RayDiff *d)
{
    static const double centre[2] = {0, 0};
    Ray right = camera_lens_ray(cam, x + 0.5, y, centre), left = camera_lens_ray(cam, x - 0.5, y, centre);
    Ray down = camera_lens_ray(cam, x, y + 0.5, centre), up = camera_lens_ray(cam, x, y - 0.5, centre);

    *ray = camera_lens_ray(cam, x, y, centre);
    d->dodx = vec3_sub(right.origin, left.origin);
    d->dody = vec3_sub(down.origin, up.origin);
    d->dddx = vec3_sub(right.dir, left.dir);
    d->dddy = vec3_sub(down.dir, up.dir);
}

/* Returns the largest difference between a and b's components. */
static double mip_far(Vec3 a, Vec3 b)
{
    Vec3 d = vec3_abs(vec3_sub(a, b));

    return fmax(fmax(d.x, d.y), d.z);
}

static void differentials_through_a_plane_mirror_are_the_mirrored_cameras(void)
{
    /* A camera at (0, 2, -4) looking along +z, a mirror z = 0 facing it:
     * the mirrored rays are the rays of the camera mirrored to (0, 2, 4)
     * looking along -z, so at the floor y = 0 behind the camera the
     * footprint of a reflected ray is that mirrored camera's direct one. */
    Camera cam, mirrored;
    Vec3 n = vec3(0, 0, -1);

    CHECK(camera_look_at(&cam, vec3(0, 2, -4), vec3(0, 1.2, 6), 50 * MIP_DEGREE, 64, 48) ==
          CAMERA_VIEW_OK);
    CHECK(camera_look_at(&mirrored, vec3(0, 2, 4), vec3(0, 1.2, -6), 50 * MIP_DEGREE, 64, 48) ==
          CAMERA_VIEW_OK);
    for (int k = 0; k < 12; k++) {
        double x = 3.5 + 5 * k, y = 30.5 + (k % 5) * 3;
        Ray ray, mray, r;
        RayDiff d, md, rd;
        Vec3 dp[2], dn[2] = {vec3(0, 0, 0), vec3(0, 0, 0)}, fp[2], mfp[2];
        real t, tf, mtf;

        mip_camera_diff(&cam, x, y, &ray, &d);
        /* The mirrored camera's pixel: flipped across (its right is our
         * left). */
        mip_camera_diff(&mirrored, 64 - x, y, &mray, &md);
        t = (0 - ray.origin.z) / ray.dir.z;
        ray_diff_transfer(&ray, &d, t, n, dp);
        r.origin = ray_at(&ray, t);
        r.dir = ray_reflect(ray.dir, n);
        ray_diff_reflect(ray.dir, &d, n, dn, dp, &rd);
        /* Both reach the floor y = 0: the same point, the same footprint
         * (x flipped). */
        tf = -r.origin.y / r.dir.y;
        mtf = -mray.origin.y / mray.dir.y;
        CHECK(tf > 0 && mtf > 0);
        ray_diff_transfer(&r, &rd, tf, vec3(0, 1, 0), fp);
        ray_diff_transfer(&mray, &md, mtf, vec3(0, 1, 0), mfp);
        CHECK(mip_far(ray_at(&r, tf), ray_at(&mray, mtf)) < 1e-9);
        CHECK(mip_far(fp[0], vec3_neg(mfp[0])) < 1e-9);
        CHECK(mip_far(fp[1], mfp[1]) < 1e-9);
    }
}

static void differentials_through_glass_follow_snell(void)
{
    /* A slab's two parallel faces (index 1.5): a ray through both keeps
     * its direction, and so do its differentials' directions. */
    Camera cam;
    Vec3 n = vec3(0, 0, -1), dn[2] = {vec3(0, 0, 0), vec3(0, 0, 0)};

    CHECK(camera_look_at(&cam, vec3(0, 0, -5), vec3(0.3, 0.1, 0), 60 * MIP_DEGREE, 32, 32) ==
          CAMERA_VIEW_OK);
    for (int k = 0; k < 8; k++) {
        Ray ray, in, out;
        RayDiff d, dd_in, dd_out;
        Vec3 dp[2], bent, again;
        real t;

        mip_camera_diff(&cam, 4.5 + 3 * k, 20.5 - 2 * k, &ray, &d);
        t = (0 - ray.origin.z) / ray.dir.z;
        ray_diff_transfer(&ray, &d, t, n, dp);
        CHECK(ray_refract(ray.dir, n, 1 / 1.5, &bent));
        ray_diff_refract(ray.dir, &d, n, dn, dp, 1 / 1.5, bent, &dd_in);
        in.origin = ray_at(&ray, t);
        in.dir = bent;
        /* Out through z = 1, the normal facing the ray still -z. */
        t = (1 - in.origin.z) / in.dir.z;
        ray_diff_transfer(&in, &dd_in, t, n, dp);
        CHECK(ray_refract(in.dir, n, 1.5, &again));
        ray_diff_refract(in.dir, &dd_in, n, dn, dp, 1.5, again, &dd_out);
        out.dir = again;
        /* The unit direction's derivative, as the camera's unit one. */
        {
            real len = vec3_length(ray.dir);
            Vec3 u = vec3_scale(ray.dir, 1 / len);
            Vec3 du = vec3_scale(vec3_sub(d.dddx, vec3_scale(u, vec3_dot(u, d.dddx))), 1 / len);
            CHECK(mip_far(out.dir, u) < 1e-12);
            CHECK(mip_far(dd_out.dddx, du) < 1e-9);
        }
    }
}

const TestCase texture_mipmap_tests[] = {
    {"mipmap_levels_are_the_means_of_the_level_below",
     mipmap_levels_are_the_means_of_the_level_below},
    {"footprint_of_a_texel_reads_as_bilinear", footprint_of_a_texel_reads_as_bilinear},
    {"footprint_of_the_whole_image_reads_its_mean", footprint_of_the_whole_image_reads_its_mean},
    {"stripes_filtered_are_their_box_mean", stripes_filtered_are_their_box_mean},
    {"differentials_through_a_plane_mirror_are_the_mirrored_cameras",
     differentials_through_a_plane_mirror_are_the_mirrored_cameras},
    {"differentials_through_glass_follow_snell", differentials_through_glass_follow_snell},
    {NULL, NULL},
};
