/* test_light_buffer.c: light buffers answer as the loops over every sphere. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "accel/light_buffer.h"
#include "render/visibility.h"
#include "rng.h"
#include "scene/scene.h"
#include "scene/scene_accel.h"
#include "test.h"

/* Fills spheres with n random spheres around the origin at scale s, every
 * tenth twice (exact ties), radii from s / 1000 to s / 10; the orders are
 * their indices. */
static void random_spheres(Sphere *spheres, int n, double s)
{
    for (int i = 0; i < n; i++) {
        Sphere *sp = &spheres[i];
        if (i % 10 == 9) {
            *sp = spheres[i - 1];
        } else {
            sp->centre = vec3_scale(rng_unit_vector(), s * rng_uniform());
            sp->radius = s * 0.1 * rng_log_scale(-2, 0);
        }
        sp->order = (unsigned)i;
    }
}

/* The loops' nearest crossing (the least t, then the least order). */
static int loop_nearest(const Sphere *spheres, int n, const Ray *ray, real *t, size_t *k)
{
    real best = INFINITY;
    int found = 0;

    for (int i = 0; i < n; i++) {
        real th;
        if (sphere_hit(spheres[i].centre, spheres[i].radius, ray, 0, best, &th)) {
            best = th;
            *k = (size_t)i;
            found = 1;
        }
    }
    *t = best;
    return found;
}

/* The loops' answer to a shadow ray. */
static int loop_occluded(const Sphere *spheres, int n, const Ray *ray, real tmax)
{
    real t;

    for (int i = 0; i < n; i++)
        if (sphere_hit(spheres[i].centre, spheres[i].radius, ray, 0, tmax, &t))
            return 1;
    return 0;
}

/* Returns a point on sphere s's rim as seen from p (a grazing ray from p
 * through it), or on its surface when i is odd. */
static Vec3 rim_point(const Sphere *s, Vec3 p, int i)
{
    Vec3 to = vec3_sub(s->centre, p), side = vec3_cross(to, rng_unit_vector());
    double d = vec3_length(to);

    if (i % 2 || !(d > s->radius) || !(vec3_length(side) > 0))
        return vec3_add(s->centre, vec3_scale(rng_unit_vector(), s->radius));
    /* The tangent from p touches the sphere at angle asin(r / d) off the
     * line of centres, at distance sqrt(d^2 - r^2) from p. */
    side = vec3_normalize(side);
    {
        double sn = s->radius / d, cs = sqrt(1 - sn * sn), len = sqrt(d * d - s->radius * s->radius);
        Vec3 dir = vec3_add(vec3_scale(vec3_normalize(to), cs), vec3_scale(side, sn));
        return vec3_add(p, vec3_scale(dir, len));
    }
}

/* Around a centre outside the field, in it, inside a sphere and on one,
 * at scales 10^-6 to 10^8 (one hierarchy-free resolution each): rays from
 * the centre towards spheres' rims (grazing), their surfaces, along axes
 * and cube diagonals (cells' borders) find the loops' nearest sphere, and
 * shadow rays from spheres' surfaces and rims to the centre the loops'
 * answer. */
static void light_buffer_answers_as_the_loops(void)
{
    static const double scales[] = {1e-6, 1, 1e8};
    enum { N = 400 };
    Sphere *spheres = malloc(N * sizeof *spheres);
    int differ = 0, hits = 0, blocked = 0, lit = 0, built = 0;

    for (int si = 0; si < 3 && spheres; si++)
        for (int where = 0; where < 4; where++) {
            double s = scales[si];
            LightBuffer lb;
            Vec3 c;
            random_spheres(spheres, N, s);
            c = where == 0   ? vec3(0.3 * s, 3 * s, -2 * s)
                : where == 1 ? vec3_scale(rng_unit_vector(), 0.5 * s)
                : where == 2 ? vec3_add(spheres[5].centre, vec3_scale(rng_unit_vector(),
                                                                      spheres[5].radius * 0.5))
                             : rim_point(&spheres[7], vec3(0, 0, 0), 1);
            if (light_buffer_build(&lb, c, spheres, N, SIZE_MAX, SIZE_MAX, 2) != 0)
                continue;
            built++;
            for (int i = 0; i < 3000; i++) {
                const Sphere *sp = &spheres[(int)(rng_uniform() * N)];
                Vec3 aim = rim_point(sp, c, i);
                Ray ray = {c, vec3_sub(aim, c)}, shadow;
                real ta, tb;
                size_t ka = 0, kb = 0;
                uint32_t cache = UINT32_MAX;
                int fa, fb;
                if (i % 7 == 0) { /* an axis or a cube's diagonal, tilted a little */
                    double e[3] = {i % 2 ? 1 : -1, i % 3 ? 1 : 0, i % 5 ? 1 : -1};
                    e[i % 3] *= 1 + (i % 4) * 1e-15;
                    ray.dir = vec3_scale(vec3(e[0], e[1], e[2]), s);
                }
                fa = loop_nearest(spheres, N, &ray, &ta, &ka);
                fb = light_buffer_nearest(&lb, &ray, INFINITY, &tb, &kb);
                differ += fa != fb || (fa && (ta != tb || spheres[ka].order != spheres[kb].order));
                hits += fa;
                /* A shadow ray from the aimed-at point back to the centre. */
                shadow.origin = aim;
                shadow.dir = vec3_sub(c, aim);
                fa = loop_occluded(spheres, N, &shadow, 1);
                fb = light_buffer_occluded(&lb, &shadow, 1, &cache);
                differ += fa != fb;
                blocked += fa;
                lit += !fa;
                /* The cache, tried first, changes nothing. */
                differ += fb != light_buffer_occluded(&lb, &shadow, 1, &cache);
                /* From the crossing the centre sees (lit, but for rounding). */
                if (ta < INFINITY) {
                    shadow.origin = vec3_add(c, vec3_scale(ray.dir, ta));
                    shadow.dir = vec3_sub(c, shadow.origin);
                    fa = loop_occluded(spheres, N, &shadow, 1);
                    fb = light_buffer_occluded(&lb, &shadow, 1, &cache);
                    /* -1: the crossing is the centre, left to the caller. */
                    differ += fb >= 0 ? fa != fb : !vec3_equal(shadow.origin, c);
                    lit += !fa;
                }
            }
            light_buffer_free(&lb);
        }
    CHECK_INT(12, built);
    CHECK(hits > 10000);
    CHECK(blocked > 5000 && lit > 5000);
    CHECK_INT(0, differ);
    free(spheres);
}

/* A field whose spheres outgrow the caches (more than 1 MiB): shadow
 * queries ask memory for spheres ahead of the one they test (a fewer
 * hold none), and still answer as the loops, lists of every length read
 * to their ends. */
static void light_buffer_reads_ahead_as_the_loops(void)
{
    enum { N = 30000 };
    Sphere *spheres = malloc(N * sizeof *spheres);
    Vec3 c = vec3(0.3, 3, -2);
    LightBuffer lb;
    int differ = 0, blocked = 0, lit = 0;

    if (!spheres) {
        CHECK(spheres != NULL);
        return;
    }
    random_spheres(spheres, N, 1);
    for (int i = 0; i < N; i++)
        spheres[i].radius *= 0.1; /* a field mostly lit, some points hidden */
    CHECK_INT(0, light_buffer_build(&lb, c, spheres, 1000, SIZE_MAX, SIZE_MAX, 2));
    CHECK(!lb.ahead);
    light_buffer_free(&lb);
    CHECK_INT(0, light_buffer_build(&lb, c, spheres, N, SIZE_MAX, SIZE_MAX, 2));
    CHECK(lb.ahead);
    for (int i = 0; i < 1000; i++) {
        const Sphere *sp = &spheres[(int)(rng_uniform() * N)];
        Vec3 at = rim_point(sp, c, i);
        Ray shadow = {at, vec3_sub(c, at)};
        uint32_t cache = UINT32_MAX;
        int fa = loop_occluded(spheres, N, &shadow, 1);

        differ += fa != light_buffer_occluded(&lb, &shadow, 1, &cache);
        blocked += fa;
        lit += !fa;
    }
    light_buffer_free(&lb);
    CHECK(blocked > 50 && lit > 50);
    CHECK_INT(0, differ);
    free(spheres);
}

/* Budgets: a buffer that would not fit is not built (nothing held), and a
 * ray with no direction is left to the caller. */
static void light_buffer_keeps_to_its_budget(void)
{
    enum { N = 2000 };
    Sphere *spheres = malloc(N * sizeof *spheres);
    LightBuffer lb;
    Ray ray = {{0, 0, 0}, {0, 0, 0}};
    real t;
    size_t k;
    uint32_t cache = UINT32_MAX;

    if (!spheres)
        return;
    random_spheres(spheres, N, 1);
    CHECK_INT(1, light_buffer_build(&lb, vec3(0, 5, 0), spheres, N, SIZE_MAX, 1000, 1));
    CHECK(lb.first == NULL && light_buffer_memory(&lb) == 0);
    CHECK_INT(0, light_buffer_build(&lb, vec3(0, 5, 0), spheres, N, SIZE_MAX, 1 << 20, 1));
    CHECK(light_buffer_memory(&lb) <= 1 << 20);
    ray.origin = lb.centre;
    CHECK_INT(-1, light_buffer_nearest(&lb, &ray, INFINITY, &t, &k));
    CHECK_INT(-1, light_buffer_occluded(&lb, &ray, 1, &cache));
    light_buffer_free(&lb);
    free(spheres);
}

/* A field of more spheres than the choice counts one by one (its small
 * spheres sampled, a large one near the centre counted whole): the buffer
 * keeps to each budget, coarser as it shrinks, and answers as the loops. */
static void light_buffer_sampled_choice_keeps_to_its_budget(void)
{
    enum { N = 70000 };
    Sphere *spheres = malloc(N * sizeof *spheres);
    Vec3 c = vec3(0.3, 3, -2);
    size_t budgets[] = {32u << 20, 12u << 20, 6u << 20};
    int last = INT32_MAX, differ = 0;

    if (!spheres) {
        CHECK(spheres != NULL);
        return;
    }
    random_spheres(spheres, N, 1);
    for (int i = 0; i < N; i++)
        spheres[i].radius *= 0.1;
    spheres[0].centre = vec3(0.3, 2, -2); /* seen across most of a face */
    spheres[0].radius = 0.5;
    for (size_t b = 0; b < sizeof budgets / sizeof budgets[0]; b++) {
        LightBuffer lb;
        CHECK_INT(0, light_buffer_build(&lb, c, spheres, N, SIZE_MAX, budgets[b], 2));
        CHECK(lb.first != NULL && light_buffer_memory(&lb) <= budgets[b]);
        CHECK(lb.res <= last);
        last = lb.res;
        for (int i = 0; i < 300; i++) {
            const Sphere *sp = &spheres[(int)(rng_uniform() * N)];
            Vec3 at = rim_point(sp, c, i);
            Ray shadow = {at, vec3_sub(c, at)};
            uint32_t cache = UINT32_MAX;
            differ += loop_occluded(spheres, N, &shadow, 1) !=
                      light_buffer_occluded(&lb, &shadow, 1, &cache);
        }
        light_buffer_free(&lb);
    }
    CHECK_INT(0, differ);
    free(spheres);
}

/* A scene of spheres alone builds its buffers (the eye's, the point
 * lights'), and renders' queries through them answer as without any
 * structure; a transparent scene keeps the eye's only, a lens none, and an
 * image of fewer than two pixels a sphere none. */
static void scene_buffers_answer_as_without(void)
{
    Scene sc, plain;
    int differ = 0, hits = 0;

    for (int pass = 0; pass < 3; pass++) {
        uint64_t seed = rng_state;
        for (int copy = 0; copy < 2; copy++) {
            Scene *s = copy ? &plain : &sc;
            Light light = light_point(vec3(2, 6, -1), colour(255, 255, 255));
            Light sun = light;
            rng_state = seed;
            scene_init(s);
            sun.distant = 1;
            sun.to_light = vec3(0, 1, 0);
            CHECK_INT(0, scene_add_light(s, &light));
            CHECK_INT(0, scene_add_light(s, &sun));
            s->camera.eye = vec3(0, 1, -8);
            s->camera.width = s->camera.height = pass == 0 ? 40 : 100; /* 1600, 10^4 pixels */
            s->camera.aperture = pass == 2 ? 0.1 : 0;
            for (int i = 0; i < (pass == 0 ? 800 : 300); i++) {
                Material m = material_plain(colour(100, 100, 100), 0.3);
                m.transparency = pass == 1 && i % 5 == 0 ? 0.5 : 0;
                CHECK_INT(0, scene_add_sphere(s, vec3_scale(rng_unit_vector(), 3 * rng_uniform()),
                                              0.05 + 0.2 * rng_uniform(), &m));
            }
        }
        CHECK_INT(0, scene_build_accel(&sc, 2));
        CHECK((sc.eye_buffer != NULL) == (pass != 2));
        CHECK((sc.light_buffers != NULL && sc.light_buffers[0].first != NULL) == (pass != 1));
        CHECK(sc.light_buffers == NULL || sc.light_buffers[1].first == NULL); /* distant */
        for (int i = 0; i < 3000; i++) {
            Ray ray = {sc.camera.eye, vec3_sub(vec3_scale(rng_unit_vector(), 3), sc.camera.eye)};
            Hit a, b;
            int fa = visibility_nearest(&plain, &ray, INFINITY, &a);
            int fb = visibility_nearest(&sc, &ray, INFINITY, &b);
            differ += fa != fb || (fa && (a.t != b.t || a.order != b.order));
            hits += fa;
            if (fa && pass == 0) {
                Vec3 p = vec3_add(ray.origin, vec3_scale(ray.dir, a.t));
                Ray shadow = {p, vec3_sub(sc.lights[0].position, p)};
                uint32_t cache = UINT32_MAX;
                differ += visibility_occluded(&plain, &shadow, 1) !=
                          visibility_light_occluded(&sc, 0, &shadow, 1, &cache);
            }
        }
        scene_free(&sc);
        scene_free(&plain);
    }
    CHECK(hits > 2000);
    CHECK_INT(0, differ);
    /* Fewer than two pixels a sphere: no buffers. */
    scene_init(&sc);
    {
        Light light = light_point(vec3(2, 6, -1), colour(255, 255, 255));
        Material m = material_plain(colour(100, 100, 100), 0);
        CHECK_INT(0, scene_add_light(&sc, &light));
        sc.camera.width = sc.camera.height = 20;
        for (int i = 0; i < 201; i++)
            CHECK_INT(0, scene_add_sphere(&sc, rng_unit_vector(), 0.1, &m));
        CHECK_INT(0, scene_build_accel(&sc, 1));
        CHECK(sc.accel != NULL && sc.eye_buffer == NULL && sc.light_buffers == NULL);
        scene_free(&sc);
    }
}

const TestCase light_buffer_tests[] = {
    {"light_buffer_answers_as_the_loops", light_buffer_answers_as_the_loops},
    {"light_buffer_reads_ahead_as_the_loops", light_buffer_reads_ahead_as_the_loops},
    {"light_buffer_keeps_to_its_budget", light_buffer_keeps_to_its_budget},
    {"light_buffer_sampled_choice_keeps_to_its_budget",
     light_buffer_sampled_choice_keeps_to_its_budget},
    {"scene_buffers_answer_as_without", scene_buffers_answer_as_without},
    {NULL, NULL},
};
