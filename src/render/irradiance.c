/* irradiance.c: the irradiance cache's pre-pass (see irradiance.h). */
#include "render/irradiance.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh.h"
#include "base/hash.h"
#include "base/process.h"
#include "render/model.h"
#include "render/sampler.h"
#include "render/trace.h"
#include "scene/camera.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* A point is covered when a record's error there is below IRR_PLACE a:
 * the margin leaves room for the samples between the pixels' centres
 * (their lookups may also reach twice as far). On the room, -s 16, E 0.3:
 * 0.9 makes 0.72 of the records that 0.75 made, for 0.74 of the time and
 * an RMSE of 0.998 against 0.978 (docs/log.md, "The irradiance cache's
 * frontier"): the best trade measured within a level. */
#define IRR_PLACE 0.9

/* A record's validity radius a R: at least IRR_FINEST pixels (POV-Ray's
 * minimum_reuse, 1.5% of a 200-pixel picture), at most
 * IRR_WIDEST of the picture's width, seen at its distance from the eye. */
#define IRR_FINEST 3
#define IRR_WIDEST 0.25

/* Where in its pixel a round traces: its centre, where the camera's one
 * sample a pixel looks, so that at one sample a pixel each pixel's light
 * tends to its own gathering's as the accuracy does. (Off the centre, a
 * record at every pixel still left its pixel's centre to extrapolation
 * or to a fallback's fewer rays: up to 10 levels off at E 0.05.) */
#define IRR_AT_X 0.5
#define IRR_AT_Y 0.5

/* Pixels traced at once in a round, and points of a generation computed
 * at once: each batch sees the records of those before it. */
enum { IRR_PIXELS = 4096, IRR_BATCH = 64 };

/* The fewest rays a deeper level's gathering casts (irr_strata()). */
#define IRR_DEEPEST 128

/* A record being computed: where, its key, and what came of it. */
typedef struct {
    GatherPoint at;
    uint64_t key;
    GiValue value;
    double radius;
    double open;       /* the share of its rays that met nothing */
    float near[GICACHE_SECTORS]; /* how far along its plane it sees (GiPlace) */
    GatherPoints hits; /* the diffuse points its rays met, when collected */
    int failed;
} IrrWork;

/* The pre-pass's state. */
typedef struct {
    const Scene *scene;
    const RenderOptions *opts;
    GiCache *cache;
    int rays;            /* the rays a record's first level gathers */
    int bounces;         /* the levels a record keeps */
    int generation;      /* of the records being placed: 0 the camera's */
    double pixel;        /* a pixel's width seen from the eye, per unit of
                            distance */
    GatherPoint *points; /* each record's point (cache->count of them) */
    uint64_t *keys;      /* and key */
    size_t capacity;
    uint64_t serial;     /* records started so far */
    GatherPoints next;   /* the points the next generation covers */
    uint32_t covering[2]; /* the record that covered the last point asked
                            about (gicache_any()'s hint) */
    RayCounts counts;
} Irr;

/* A gathering in progress: the tracer, the point, the bounce its rays
 * take and their key, the rays cast so far. */
typedef struct {
    const Tracer *t;
    const GatherPoint *at;
    int bounce;
    uint64_t key;
    unsigned i;
    unsigned n;        /* wedges: ray i is wedge i % n's */
    uint32_t *wedges;  /* the record that served each wedge's last ray */
} IrrRay;

/* GiSample for a record: the colour a ray from the point brings back (none
 * below its surface). */
static double irr_sample(void *ctx, Vec3 dir, Colour *c)
{
    IrrRay *r = ctx;
    unsigned i = r->i++;
    TraceMet met;
    Ray ray;

    if (!(vec3_dot(dir, r->at->n) > 0)) {
        *c = colour(0, 0, 0);
        return INFINITY;
    }
    ray.dir = dir;
    ray.origin = ray_offset_origin(r->at->point, r->at->error, r->at->back, r->at->n, dir);
    r->t->counts->gather++;
    r->t->gicache_hint[1] = r->wedges[i % r->n];
    *c = trace_gathered(r->t, &ray, r->bounce, sampler_branch(r->key, i), &met);
    r->wedges[i % r->n] = r->t->gicache_hint[0];
    /* A surface met from behind: the point is outside what encloses it
     * (on a seam, a hair outside a corner): counted as open. */
    return met.behind ? INFINITY : met.t;
}

/* Returns the tracer of one thread of the pre-pass. */
static Tracer irr_tracer(const Irr *irr, RayCounts *counts, TraceSample *sample,
                         uint32_t *occluders)
{
    Tracer t = model_tracer(irr->scene, irr->opts->max_depth, counts);

    t.indirect = irr->opts->indirect;
    t.indirect.ao_samples = 0;
    t.sample = sample;
    t.ao_grid = sampler_grid(1);
    t.gi_grid = sampler_grid((unsigned)t.indirect.gi_samples);
    t.path_grid = sampler_grid(1);
    t.occluders = occluders;
    t.no_shadows = irr->opts->no_shadows;
    t.footprint_scale = 1;
    for (int k = 0; k < TRACE_OCCLUDERS; k++)
        occluders[k] = BVH_NO_SLOT;
    return t;
}

/* Returns the least radius of a record at `at`: IRR_FINEST pixels of
 * validity seen from the eye; for a point the camera sees, at the default
 * accuracy or a coarser one only, fewer at a finer one (its reach a R
 * shrinks with a below the default, so that every pixel's light tends to
 * gathering's as a does). A deeper generation's light reaches the picture
 * averaged over a record's rays: its reach keeps its pixels. */
static double irr_least(const Irr *irr, const GatherPoint *at)
{
    double seen = (double)vec3_length(vec3_sub(at->point, irr->scene->camera.eye)) * irr->pixel;
    double a = irr->cache->a;

    if (at->bounce > 0 || a > GICACHE_DEFAULT_ERROR)
        return IRR_FINEST * seen / a;
    return IRR_FINEST * seen / GICACHE_DEFAULT_ERROR;
}

/* Returns the radius of a record at `at` of value v whose rays met things
 * at harmonic mean distance `harmonic`: no more than its brightest
 * channel over that channel's gradient, within the pixel bounds. */
static double irr_radius(const Irr *irr, const GatherPoint *at, const GiValue *v,
                         double harmonic)
{
    double g[3] = {v->g.r, v->g.g, v->g.b}, a = irr->cache->a, r = harmonic;
    double seen = (double)vec3_length(vec3_sub(at->point, irr->scene->camera.eye)) * irr->pixel;
    double lo = irr_least(irr, at), hi = IRR_WIDEST * irr->scene->camera.width * seen / a;
    int c = g[1] > g[0] ? 1 : 0;
    double slope;

    c = g[2] > g[c] ? 2 : c;
    slope = (double)vec3_length(v->trans[c]);
    if (slope > 0 && g[c] / slope < r)
        r = g[c] / slope;
    if (hi > 0 && r > hi)
        r = hi;
    if (r < lo)
        r = lo;
    if (!(r > 0) || !isfinite(r))
        r = hi > 0 && isfinite(hi) ? hi : 1;
    return r;
}

/* Sets w's radius from its rays' harmonic mean distance and limits its
 * gradients to it (also those of the levels gathered later, whose rays
 * met the same points). */
static void irr_settle(const Irr *irr, IrrWork *w, double harmonic, int placing)
{
    if (placing)
        w->radius = irr_radius(irr, &w->at, &w->value, harmonic);
    gicache_limit(&w->value, irr->cache->a * w->radius);
}

/* Stores in *m and *n the strata of a record's gathering of level
 * `level`: --gi N rays for the first, a quarter as many for each level
 * deeper, and never fewer than IRR_DEEPEST (or N). A deeper level's light
 * reaches the picture only averaged by the rays of the levels above it. */
static void irr_strata(const Irr *irr, int level, int *m, int *n)
{
    int rays = irr->rays, least = irr->rays < IRR_DEEPEST ? irr->rays : IRR_DEEPEST;

    for (int l = 0; l < level && rays / 4 >= least; l++)
        rays /= 4;
    gicache_strata(rays > least ? rays : least, m, n);
}

/* Computes works[0..count) in parallel: each gathers with rays of bounce
 * `bounce`, looking the next level up in the cache unless `collect`, in
 * which case the diffuse points its rays meet are kept instead (and gather
 * nothing); sets their radii when placing (else they hold them). Returns
 * 0, or -1 when memory ran out. */
static int irr_compute(Irr *irr, IrrWork *works, size_t count, int bounce, int collect,
                       int placing)
{
    int failed = 0, m, n;

    /* Bounce b's rays gather level b - 1; placing, the deepest level. */
    irr_strata(irr, placing ? irr->bounces - 1 : bounce - 1, &m, &n);

#ifdef _OPENMP
#pragma omp parallel num_threads(irr->opts->threads)
#endif
    {
        RayCounts mine = {0};
        TraceSample sample = {0, 0, 0, 1, NULL};
        uint32_t occluders[TRACE_OCCLUDERS];
        Tracer t = irr_tracer(irr, &mine, &sample, occluders);
        uint32_t hint[2], wedges[SCENE_MAX_INDIRECT]; /* n <= the rays <= that */

        t.gicache = collect ? NULL : irr->cache;
        t.gicache_hint = hint;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (long i = 0; i < (long)count; i++) {
            IrrWork *w = &works[i];
            IrrRay r = {&t, &w->at, bounce, w->key, 0, (unsigned)n, wedges};
            double harmonic;

            hint[0] = hint[1] = GICACHE_NO_HINT; /* each record's rays alike on any thread */
            for (int k = 0; k < n; k++)
                wedges[k] = GICACHE_NO_HINT;
            sample.x = (int)(w->key & 0x3fffffff);
            sample.y = bounce;
            t.collect = collect ? &w->hits : NULL;
            if (gicache_gather(w->at.ns, m, n, w->key, irr_least(irr, &w->at),
                               irr_sample, &r, &w->value, &harmonic, &w->open, w->near) != 0 ||
                w->hits.failed)
                w->failed = 1;
            else
                irr_settle(irr, w, harmonic, placing);
        }
#ifdef _OPENMP
#pragma omp critical(irradiance_counts)
#endif
        ray_counts_add(&irr->counts, &mine);
    }
    for (size_t i = 0; i < count; i++)
        failed |= works[i].failed;
    return failed ? -1 : 0;
}

/* Says whether a record holding the current generation's level covers
 * point p (whichever: the one that covered the last point asked about is
 * tried first). */
static int irr_covered(Irr *irr, const GatherPoint *p)
{
    Colour g;

    irr->covering[1] = GICACHE_NO_HINT;
    return gicache_any(irr->cache, irr->generation, IRR_PLACE, p->point, p->ns, irr->covering,
                       &g);
}

/* Starts the work of a record at p. */
static IrrWork irr_work(Irr *irr, const GatherPoint *p)
{
    IrrWork w;

    memset(&w, 0, sizeof w);
    w.at = *p;
    w.key = hash_u64(0x6972726164ULL, irr->serial++);
    return w;
}

/* Adds the records of works[0..count), in order, every level holding its
 * value; moves the points their rays met to the next generation's. Returns
 * 0, -1 or SCENE_OVER_LIMIT. */
static int irr_add(Irr *irr, IrrWork *works, size_t count)
{
    GiValue *levels = malloc((size_t)irr->cache->levels * sizeof *levels);

    if (!levels)
        return -1;
    for (size_t i = 0; i < count; i++) {
        IrrWork *w = &works[i];
        GiPlace place = {w->at.point, w->at.ns, w->radius, w->open, irr->generation, {0}};
        int rc;

        memcpy(place.near, w->near, sizeof place.near);
        if (irr->cache->count == irr->capacity) {
            size_t cap = irr->capacity ? 2 * irr->capacity : 256;
            GatherPoint *p = realloc(irr->points, cap * sizeof *p);
            uint64_t *k = p ? realloc(irr->keys, cap * sizeof *k) : NULL;

            if (p)
                irr->points = p;
            if (!k) {
                free(levels);
                return -1;
            }
            irr->keys = k;
            irr->capacity = cap;
        }
        for (int l = 0; l < irr->cache->levels; l++)
            levels[l] = w->value;
        rc = gicache_add(irr->cache, &place, levels);
        if (rc != 0) {
            free(levels);
            return rc == -2 ? SCENE_OVER_LIMIT : -1;
        }
        irr->points[irr->cache->count - 1] = w->at;
        irr->keys[irr->cache->count - 1] = w->key;
        for (size_t j = 0; j < w->hits.count; j++)
            gather_points_add(&irr->next, &w->hits.items[j]);
        if (irr->next.failed) {
            free(levels);
            return -1;
        }
    }
    free(levels);
    return 0;
}

/* Computes and adds the records of works[0..count) (their rays' points
 * kept when collect); frees what they hold. Returns 0, -1 or
 * SCENE_OVER_LIMIT. */
static int irr_place(Irr *irr, IrrWork *works, size_t count, int collect)
{
    /* A record's first gathering is its deepest level: its rays' hits
     * bring their direct light only, which collecting does; their points
     * are kept for the next generation when it comes. */
    int rc = count ? irr_compute(irr, works, count, 1, collect || irr->bounces > 1, 1) : 0;

    for (size_t i = 0; !collect && i < count; i++)
        works[i].hits.count = 0;
    if (rc == 0)
        rc = irr_add(irr, works, count);
    for (size_t i = 0; i < count; i++)
        free(works[i].hits.items);
    return rc;
}

/* Traces the centre rays of pixels xy[0..count) (pairs), collecting into
 * pts[i] the diffuse points pixel i's ray reaches. */
static void irr_trace_pixels(Irr *irr, const int *xy, size_t count, GatherPoints *pts)
{
#ifdef _OPENMP
#pragma omp parallel num_threads(irr->opts->threads)
#endif
    {
        RayCounts mine = {0};
        TraceSample sample = {0, 0, 0, 1, NULL};
        uint32_t occluders[TRACE_OCCLUDERS];
        Tracer t = irr_tracer(irr, &mine, &sample, occluders);

#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
        for (long i = 0; i < (long)count; i++) {
            Ray ray = camera_ray(&irr->scene->camera, xy[2 * i] + IRR_AT_X, xy[2 * i + 1] + IRR_AT_Y);

            t.collect = &pts[i];
            mine.primary++;
            t.model->trace(&t, &ray, NULL);
        }
#ifdef _OPENMP
#pragma omp critical(irradiance_counts)
#endif
        ray_counts_add(&irr->counts, &mine);
    }
}

/* Places the records of pixels xy[0..count): traced, then those of their
 * points no record covers, in order. Returns 0, -1 or SCENE_OVER_LIMIT. */
static int irr_pixels(Irr *irr, const int *xy, size_t count, int collect)
{
    GatherPoints *pts = calloc(count ? count : 1, sizeof *pts);
    IrrWork *works = NULL;
    size_t n = 0, cap = 0;
    int rc = 0;

    if (!pts)
        return -1;
    irr_trace_pixels(irr, xy, count, pts);
    for (size_t i = 0; i < count && rc == 0; i++) {
        rc = pts[i].failed ? -1 : 0;
        for (size_t j = 0; j < pts[i].count && rc == 0; j++) {
            if (irr_covered(irr, &pts[i].items[j]))
                continue;
            if (n == cap) {
                IrrWork *grown = realloc(works, (cap ? 2 * cap : 64) * sizeof *works);
                if (!grown) {
                    rc = -1;
                    break;
                }
                works = grown;
                cap = cap ? 2 * cap : 64;
            }
            works[n++] = irr_work(irr, &pts[i].items[j]);
        }
    }
    for (size_t i = 0; i < count; i++)
        free(pts[i].items);
    free(pts);
    if (rc == 0)
        rc = irr_place(irr, works, n, collect);
    else
        for (size_t i = 0; i < n; i++)
            free(works[i].hits.items);
    free(works);
    return rc;
}

/* Places the records the camera's rays need: rounds of pixels on grids
 * of 2^k down to 1 pixel, each new pixel of a round once. */
static int irr_rounds(Irr *irr, int collect)
{
    const Camera *cam = &irr->scene->camera;
    int least = cam->width < cam->height ? cam->width : cam->height, first = 1;
    int *xy = malloc(2 * IRR_PIXELS * sizeof *xy);
    int rc = 0;

    if (!xy)
        return -1;
    while (2 * first <= least / 8 && first < 64)
        first *= 2;
    for (int s = first; s >= 1 && rc == 0; s /= 2) {
        size_t n = 0;

        for (int y = 0; y < cam->height && rc == 0; y += s)
            for (int x = 0; x < cam->width && rc == 0; x += s) {
                if (s != first && x % (2 * s) == 0 && y % (2 * s) == 0)
                    continue; /* an earlier round's */
                xy[2 * n] = x;
                xy[2 * n + 1] = y;
                if (++n == IRR_PIXELS) {
                    rc = irr_pixels(irr, xy, n, collect);
                    n = 0;
                }
            }
        if (rc == 0 && n)
            rc = irr_pixels(irr, xy, n, collect);
    }
    free(xy);
    return rc;
}

/* Covers the points the last generation's rays met, in batches; keeps
 * their own rays' points when collect. */
static int irr_generation(Irr *irr, int collect)
{
    GatherPoints queue = irr->next;
    IrrWork works[IRR_BATCH];
    size_t i = 0;
    int rc = 0;

    memset(&irr->next, 0, sizeof irr->next);
    while (i < queue.count && rc == 0) {
        size_t n = 0;

        while (i < queue.count && n < IRR_BATCH) {
            if (!irr_covered(irr, &queue.items[i]))
                works[n++] = irr_work(irr, &queue.items[i]);
            i++;
        }
        rc = irr_place(irr, works, n, collect);
    }
    free(queue.items);
    return rc;
}

/* Gathers level `level` again for the records that hold it (placed in
 * generation `level` or before), their rays' hits looking up level + 1. */
static int irr_level(Irr *irr, int level)
{
    size_t count = irr->cache->count, n = 0;
    IrrWork *works = calloc(count ? count : 1, sizeof *works);
    size_t *which = malloc((count ? count : 1) * sizeof *which);
    int rc;

    if (!works || !which) {
        free(works);
        free(which);
        return -1;
    }
    for (size_t i = 0; i < count; i++) {
        if (irr->cache->places[i].first > level)
            continue;
        works[n].at = irr->points[i];
        works[n].key = irr->keys[i];
        works[n].radius = irr->cache->places[i].radius;
        which[n++] = i;
    }
    rc = irr_compute(irr, works, n, level + 1, 0, 0);
    for (size_t i = 0; rc == 0 && i < n; i++)
        gicache_set(irr->cache, which[i], level, &works[i].value);
    free(works);
    free(which);
    return rc;
}

int irradiance_build(const Scene *scene, const RenderOptions *opts, GiCache *cache,
                     RayCounts *counts, IrradianceStats *stats)
{
    const Camera *cam = &scene->camera;
    int bounces = opts->indirect.gi_bounces > 0 ? opts->indirect.gi_bounces : 1;
    size_t left = scene->memory_limit ? scene_memory_left(scene) : 0;
    double start = process_seconds();
    Vec3 centre = vec3_add(cam->top_left, vec3_scale(vec3_add(cam->u, cam->v), 0.5));
    Irr irr;
    int rc;

    memset(&irr, 0, sizeof irr);
    memset(stats, 0, sizeof *stats);
    gicache_init(cache, opts->indirect.gi_cache_error, bounces,
                 scene->memory_limit ? (left ? left : 1) : 0);
    irr.scene = scene;
    irr.opts = opts;
    irr.cache = cache;
    irr.covering[0] = GICACHE_NO_HINT;
    irr.rays = opts->indirect.gi_samples;
    irr.bounces = bounces;
    irr.pixel = (double)vec3_length(cam->u) / cam->width /
                (double)vec3_length(vec3_sub(centre, cam->eye));
    rc = irr_rounds(&irr, bounces > 1);
    stats->seen = cache->count;
    for (int g = 1; g < bounces && rc == 0; g++) {
        irr.generation = g;
        rc = irr_generation(&irr, g + 1 < bounces);
    }
    if (rc == 0) {
        rc = gicache_refile(cache);
        rc = rc == -2 ? SCENE_OVER_LIMIT : rc;
    }
    for (int level = bounces - 2; level >= 0 && rc == 0; level--)
        rc = irr_level(&irr, level);
    free(irr.next.items);
    free(irr.points);
    free(irr.keys);
    stats->records = cache->count;
    stats->rays = irr.counts.primary + irr.counts.shadow + irr.counts.reflection +
                  irr.counts.refraction + irr.counts.gather;
    stats->seconds = process_seconds() - start;
    if (counts) {
        counts->shadow += irr.counts.shadow;
        counts->reflection += irr.counts.reflection;
        counts->refraction += irr.counts.refraction;
        counts->gather += irr.counts.gather;
    }
    if (rc != 0)
        gicache_free(cache);
    return rc;
}

void irradiance_map(const Scene *scene, const GiCache *cache, size_t seen, Image *map)
{
    const Camera *cam = &scene->camera;
    size_t bytes = 3 * (size_t)map->width * (size_t)map->height;

    for (size_t i = 0; i < bytes; i++)
        map->rgb[i] = (unsigned char)(map->rgb[i] / 3);
    for (size_t i = 0; i < seen && i < cache->count; i++) {
        /* Where the eye's ray to the record crosses the screen. */
        Vec3 d = vec3_sub(cache->places[i].point, cam->eye);
        Vec3 n = vec3_cross(cam->u, cam->v);
        double along = (double)vec3_dot(d, n), t, fx, fy;
        Vec3 on, rel;
        int x, y;

        if (along == 0)
            continue;
        t = (double)vec3_dot(vec3_sub(cam->top_left, cam->eye), n) / along;
        if (!(t > 0))
            continue;
        on = vec3_add(cam->eye, vec3_scale(d, (real)t));
        rel = vec3_sub(on, cam->top_left);
        fx = (double)vec3_dot(rel, cam->u) / (double)vec3_dot(cam->u, cam->u) * map->width;
        fy = (double)vec3_dot(rel, cam->v) / (double)vec3_dot(cam->v, cam->v) * map->height;
        if (!(fx >= 0 && fx < map->width && fy >= 0 && fy < map->height))
            continue;
        x = (int)fx;
        y = (int)fy;
        map->rgb[3 * ((size_t)y * (size_t)map->width + (size_t)x)] = 255;
        map->rgb[3 * ((size_t)y * (size_t)map->width + (size_t)x) + 1] = 0;
        map->rgb[3 * ((size_t)y * (size_t)map->width + (size_t)x) + 2] = 0;
    }
}
