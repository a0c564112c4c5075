/* render.c: the pixel loop (see render.h). */
#include "render/render.h"

#include <math.h>
#include <stdlib.h>

#include "accel/bvh.h"
#include "render/cut.h"
#include "render/gicache.h"
#include "render/model.h"
#include "render/noise.h"
#include "render/pass.h"
#include "render/sampler.h"
#include "render/trace.h"
#include "render/visibility.h"
#include "scene/camera.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* The pixel's steps, folded into the tile loop: their calls were a share
 * of the course scene's instructions (docs/log.md). */
#if defined(__GNUC__)
#define RENDER_INLINE static inline __attribute__((always_inline))
#else
#define RENDER_INLINE static inline
#endif

/* What a row's pixels share: camera_column() of every pixel's centre (NULL
 * when not made: camera_ray() then) and camera_row() of the row's. */
typedef struct {
    const CameraStep *columns;
    CameraStep row;
} RenderRow;

/* Returns the colour seen along the primary ray `ray` by the rules of the
 * scene's model (model.h). */
RENDER_INLINE Colour render_trace(const Tracer *t, const Ray *ray, const RayDiff *diff)
{
    return t->primary_misses ? t->model->miss(t, ray) : t->model->trace(t, ray, diff);
}

/* Stores in *out the differentials of pixel (x, y)'s primary rays when
 * the scene reads textures or stripes over a footprint, and returns out;
 * else returns NULL. They are the centre ray's: the rays through the
 * centres of the pixels right of and below it (through the lens's
 * centre), as differences, times `scale`, which shrinks the footprint as
 * the pixel's samples share it; every sample of the pixel takes them (a
 * sample's own would differ by a second-order term, at three camera rays
 * a sample). */
RENDER_INLINE const RayDiff *render_pixel_diff(const Tracer *t, int x, int y, double scale,
                                               RayDiff *out)
{
    static const double centre[2] = {0, 0};
    const Camera *cam = &t->scene->camera;
    Ray ray, right, down;

    if (!t->scene->reads_footprint)
        return NULL;
    ray = camera_lens_ray(cam, x + 0.5, y + 0.5, centre);
    right = camera_lens_ray(cam, x + 1.5, y + 0.5, centre);
    down = camera_lens_ray(cam, x + 0.5, y + 1.5, centre);
    out->dodx = vec3_scale(vec3_sub(right.origin, ray.origin), scale);
    out->dody = vec3_scale(vec3_sub(down.origin, ray.origin), scale);
    out->dddx = vec3_scale(vec3_sub(right.dir, ray.dir), scale);
    out->dddy = vec3_scale(vec3_sub(down.dir, ray.dir), scale);
    return out;
}

/* Returns the share of a pixel's width a sample's footprint spans when
 * the pixel takes n samples: 1 / sqrt(n), at least 1/8 (as pbrt scales
 * its differentials). Under --noise n is the most a pixel may take, so
 * that its value tends to the converged picture's: a first round's wider
 * footprint would blur a far texture by more than the estimate sees
 * (a bias, not noise: docs/log.md). */
static double render_footprint_scale(unsigned n)
{
    double s = 1 / sqrt((double)n);

    return s > 0.125 ? s : 0.125;
}

/* Returns the colour of sample k of pixel (x, y) (the grid's point k of
 * the pixel, through its point k of the lens), traced by t with the
 * pixel's differentials t->sample->diff. */
RENDER_INLINE Colour render_sample(const Tracer *t, const SamplerGrid *g, int x, int y,
                                   unsigned k)
{
    const Camera *cam = &t->scene->camera;
    double p[2], l[2], disk[2] = {0, 0};
    Ray ray;

    sampler_sample(g, x, y, k, SAMPLER_DIM_PIXEL, p);
    if (cam->aperture > 0) {
        sampler_sample(g, x, y, k, SAMPLER_DIM_LENS, l);
        sampler_disk(l, disk);
    }
    ray = camera_lens_ray(cam, x + p[0], y + p[1], disk);
    t->sample->k = k;
    return render_trace(t, &ray, t->sample->diff);
}

/* Returns the mean colour of the grid's samples of pixel (x, y) of row,
 * traced by t (leaving out what its cut-off allows). One sample is the
 * pixel's centre through the lens's centre. */
RENDER_INLINE Colour render_samples(const Tracer *t, const SamplerGrid *g, const RenderRow *row,
                                    int x, int y)
{
    const Camera *cam = &t->scene->camera;
    Colour sum = colour(0, 0, 0);
    RayDiff diff;

    t->counts->primary += g->n;
    t->sample->x = x;
    t->sample->y = y;
    t->sample->k = 0;
    t->sample->diff = render_pixel_diff(t, x, y, t->footprint_scale, &diff);
    if (g->n == 1) {
        Ray ray = row->columns ? camera_ray_through(cam, row->columns[x], row->row)
                               : camera_ray(cam, x + 0.5, y + 0.5);
        return render_trace(t, &ray, t->sample->diff);
    }
    for (unsigned k = 0; k < g->n; k++)
        sum = colour_add(sum, render_sample(t, g, x, y, k));
    return colour(sum.r / g->n, sum.g / g->n, sum.b / g->n);
}

/* A pixel under --noise: what its samples are traced with. */
typedef struct {
    const Tracer *t;
    const SamplerGrid *g; /* progressive */
    int x, y;
} RenderAdaptive;

/* Returns the colour of sample k of the pixel ctx (a RenderAdaptive). */
static Colour render_adaptive_sample(void *ctx, unsigned k)
{
    const RenderAdaptive *a = ctx;

    return render_sample(a->t, a->g, a->x, a->y, k);
}

/* Returns pixel (x, y) sampled under opts->noise: rounds of samples of its
 * sequences (g progressive) until its error on scale is within the level
 * or it has taken the most (noise.h); stores in *spp the samples taken and
 * in *error the error reached. */
static Colour render_adaptive(const Tracer *t, const RenderOptions *opts, const SamplerGrid *g,
                              NoiseScale scale, int x, int y, unsigned *spp, float *error)
{
    RenderAdaptive a = {t, g, x, y};
    NoisePixel p = {{{0, 0, 0}}, 0};
    unsigned n = noise_first(&opts->noise);
    double e;

    RayDiff diff;

    t->sample->x = x;
    t->sample->y = y;
    t->sample->diff = render_pixel_diff(t, x, y, t->footprint_scale, &diff);
    for (;;) {
        t->counts->primary += n - p.n;
        noise_take(&p, n, render_adaptive_sample, &a);
        e = noise_error(&p, scale);
        n = noise_next(&opts->noise, p.n, e);
        if (n == p.n)
            break;
    }
    *spp = p.n;
    *error = (float)e;
    return noise_mean(&p);
}

/* Says whether every value from x - eta to x + slack + eta quantises to the
 * byte x does. */
static int render_same_byte(double x, double slack, double eta)
{
    return colour_quantise(x - eta) == colour_quantise(x + slack + eta);
}

/* A pass that cannot prove its pixel's bytes is followed by one that
 * traces the rays it left out with a cut-off RENDER_REFINE times smaller;
 * below RENDER_CUT_FLOOR levels, the pixel is traced anew with every ray. */
enum { RENDER_REFINE = 16 };
#define RENDER_CUT_FLOOR 1e-6

/*
 * Returns pixel (x, y), whose bytes are those of a render without the
 * cut-off whatever opts->cutoff allows; t->cut is the thread's, set up by
 * cut_init() (NULL: no cut-off). The rays the cut-off leaves out
 * could have added at most cut->skipped / n to each channel of the mean
 * (each is weight x colour, the colour within the bound trace_cut_init()
 * proves, or weight x E x lit for a shadow ray); leaving them out, or
 * adding them in later, also changes the rounding of the sums that would
 * have held them, by less than eta (a term k levels down carries some 2k
 * ulps of rounding, and the weights at one level add up to at most 1: under
 * 1.2 x 10^-10 of the bound after 1,000 levels, against eta = 10^-9 of it).
 * So the uncut colour lies in [x - eta, x + skipped / n + eta]; when that
 * whole interval quantises to one byte, that byte is the uncut render's.
 * Otherwise the rays left out are traced, with a smaller cut-off whose own
 * left-out rays hold the same argument, and in the end the pixel is traced
 * with every ray, which is the uncut render itself.
 */
RENDER_INLINE Colour render_pixel(const Tracer *t, const RenderOptions *opts,
                                  const SamplerGrid *g, const RenderRow *row, int x, int y)
{
    Cut *cut = t->cut;
    Colour c;
    double level = opts->cutoff, eta; /* this pass's cut-off */
    size_t done = 0;                  /* deferred rays traced so far */

    if (!cut)
        return render_samples(t, g, row, x, y);
    cut->cutoff = level;
    cut->skipped = 0;
    cut->deferred_count = 0;
    c = render_samples(t, g, row, x, y);
    if (cut->deferred_count == 0) /* nothing left out */
        return c;
    eta = 1e-9 * cut_bound(cut, opts->max_depth);
    for (;;) {
        double slack = cut->skipped / g->n;
        size_t end = cut->deferred_count;

        if (render_same_byte(c.r, slack, eta) && render_same_byte(c.g, slack, eta) &&
            render_same_byte(c.b, slack, eta)) {
            t->counts->cut += end - done; /* left out for good */
            return c;
        }
        if (done == 0) /* the first pass */
            t->counts->refined++;
        level /= RENDER_REFINE;
        if (level < RENDER_CUT_FLOOR) {
            Tracer every = *t;
            every.cut = NULL;
            return render_samples(&every, g, row, x, y);
        }
        /* What this pass left out, traced; what that leaves out is the
         * next pass's. */
        cut->cutoff = level;
        cut->skipped = 0;
        for (; done < end; done++)
            c = colour_add(c, colour_scale(trace_deferred(t, cut->deferred[done]), 1.0 / g->n));
    }
}

/* The image is cut into square tiles of RENDER_TILE pixels a side (those
 * on the right and bottom edges smaller), handed to threads one at a time:
 * a tile's neighbouring rays visit the same tree nodes and shapes, which a
 * row's far ends do not (32: the 100,000-sphere field's cache misses fell
 * by half, docs/log.md). */
enum { RENDER_TILE = 32 };

/* Returns the greatest common divisor of a and b (> 0). */
static long long render_gcd(long long a, long long b)
{
    while (b) {
        long long r = a % b;
        a = b;
        b = r;
    }
    return a;
}

/* Returns the number of tiles that cover n pixels in a line. */
static int render_tiles_over(int n)
{
    return (n + RENDER_TILE - 1) / RENDER_TILE;
}

/* Returns the picture's row of the image's row y: the image's own, or a
 * tile's (tile.h). */
static int render_picture_row(const RenderOptions *opts, int y)
{
    return opts->row_step > 0 ? opts->row_first + y * opts->row_step : y;
}

/* Says whether no primary ray of the image's pixels [x0, x1) x [y0, y1)
 * can meet an object (camera_frustum(), visibility_frustum_clear()): every
 * sample of theirs lies within its pixel; else stores in *skip the
 * spheres none can meet, as that function does. */
static int render_tile_clear(const Tracer *t, const RenderOptions *opts, int x0, int y0, int x1,
                             int y1, uint64_t *skip)
{
    Frustum f;
    int top = render_picture_row(opts, y0), bottom = render_picture_row(opts, y1 - 1) + 1;

    *skip = 0;
    return camera_frustum(&t->scene->camera, x0, top, x1, bottom, &f) == 0 &&
           visibility_frustum_clear(t->scene, &f, skip);
}

/* Returns the tracer of the tile [x0, x1) x [y0, y1): t, or *own, t's
 * copy told what the tile's primary rays are proven to miss
 * (render_tile_clear()): everything, and they take the miss colour
 * untraced, or some spheres, which they leave untested. */
static const Tracer *render_tile_tracer(const Tracer *t, const RenderOptions *opts, int x0,
                                        int y0, int x1, int y1, Tracer *own)
{
    uint64_t skip;
    int clear = render_tile_clear(t, opts, x0, y0, x1, y1, &skip);

    if (!clear && skip == 0)
        return t;
    *own = *t;
    own->primary_misses = clear;
    own->primary_skip = skip;
    return own;
}

/* Renders tile k of the image (numbered left to right, then top to
 * bottom) with tracer t and the pixels' sample grid g (columns as in
 * RenderRow). */
static void render_tile(const Tracer *t, const RenderOptions *opts, const SamplerGrid *g,
                        Image *img, int k, const CameraStep *columns)
{
    int across = render_tiles_over(img->width);
    int x0 = k % across * RENDER_TILE, y0 = k / across * RENDER_TILE;
    int x1 = img->width - x0 < RENDER_TILE ? img->width : x0 + RENDER_TILE;
    int y1 = img->height - y0 < RENDER_TILE ? img->height : y0 + RENDER_TILE;
    NoiseScale scale = noise_scale_of(img);
    Tracer own;

    t = render_tile_tracer(t, opts, x0, y0, x1, y1, &own);
    /* When every ray misses and the miss colour is the same for every
     * ray, so is every pixel's (made alike from the same samples): the
     * first pixel's is made, and copied. */
    if (t->primary_misses && opts->noise.level == 0 && t->model->miss_uniform(t)) {
        int py = render_picture_row(opts, y0);
        RenderRow row = {columns, camera_row(&t->scene->camera, py + 0.5)};

        image_fill(img, x0, y0, x1, y1, render_pixel(t, opts, g, &row, x0, py));
        t->counts->primary += ((unsigned long long)(x1 - x0) * (y1 - y0) - 1) * g->n;
        return;
    }
    for (int y = y0; y < y1; y++) {
        int py = render_picture_row(opts, y);
        RenderRow row = {columns, camera_row(&t->scene->camera, py + 0.5)};

        for (int x = x0; x < x1; x++) {
            size_t i = (size_t)y * (size_t)img->width + (size_t)x;
            unsigned spp;
            float error;

            if (opts->noise.level > 0) {
                image_set(img, x, y, render_adaptive(t, opts, g, scale, x, py, &spp, &error));
                if (opts->spp)
                    opts->spp[i] = spp;
                if (opts->error)
                    opts->error[i] = error;
            } else {
                image_set(img, x, y, render_pixel(t, opts, g, &row, x, py));
            }
        }
    }
}

/* Returns the tile rendered k-th of `tiles`: under --noise, tiles spread
 * over the picture (a stride coprime with their number), so that those
 * done are a fair sample of the work and the progress bar's share of
 * tiles done that of the work; else k. */
static int render_tile_order(int k, int tiles, int noise)
{
    long long stride;

    if (!noise || tiles < 3)
        return k;
    stride = (long long)(tiles * 0.618) | 1;
    while (render_gcd(stride, tiles) != 1)
        stride += 2;
    return (int)(k * stride % tiles);
}

/* Returns the grid of the `rays` indirect rays (occlusion or gathering,
 * 0: none) a point casts for each of a pixel's samples laid out by g. */
static SamplerGrid render_rays_grid(const SamplerGrid *g, int rays)
{
    return g->progressive ? *g : sampler_grid(g->n * (unsigned)(rays ? rays : 1));
}

int render(const Scene *scene, const RenderOptions *opts, Image *img, RayCounts *counts)
{
    int done = 0, used = 1;
    int tiles = render_tiles_over(img->width) * render_tiles_over(img->height);
    Cut proto = {0};
    /* Under global illumination a ray's colour has no bound the cut-off
     * could use, nor under the MPL ray tracer's rules: it is off; its proof of the
     * bytes is for linear ones. */
    int noise = opts->noise.level > 0;
    int cutting = opts->cutoff > 0 && opts->max_depth > 0 && opts->indirect.gi_samples == 0 &&
                  !img->encode && model_of(scene)->may_cut && !noise;
    SamplerGrid g = noise ? sampler_progressive() : sampler_grid((unsigned)opts->samples);
    /* One sample a pixel: the columns' part of the primary rays, made once
     * (without the room, each pixel makes its own). */
    CameraStep *columns = g.n == 1 && !noise ? malloc((size_t)img->width * sizeof *columns) : NULL;
    double depth_scale = opts->pass == TRACE_PASS_DEPTH ? pass_depth_scale(scene) : 0;

    if (cutting)
        cut_init(&proto, scene, opts->cutoff);
    for (int x = 0; columns && x < img->width; x++)
        columns[x] = camera_column(&scene->camera, x + 0.5);

#ifdef _OPENMP
#pragma omp parallel num_threads(opts->threads)
#endif
    {
        RayCounts mine = {0};
        Cut cut = proto; /* the thread's own: it keeps the rays left out */
        TraceSample sample = {0, 0, 0, g.n, NULL};
        uint32_t occluders[TRACE_OCCLUDERS];
        Tracer t = model_tracer(scene, opts->max_depth, &mine);

        t.cut = cutting ? &cut : NULL;
        t.indirect = opts->indirect;
        t.sample = &sample;
        t.ao_grid = render_rays_grid(&g, opts->indirect.ao_samples);
        if (t.indirect.gi_cache) /* only the points no record covers gather */
            t.indirect.gi_samples = gicache_fallback_rays(t.indirect.gi_samples);
        t.gi_grid = render_rays_grid(&g, t.indirect.gi_samples);
        t.path_grid = g;
        t.occluders = occluders;
        t.no_shadows = opts->no_shadows;
        t.gicache = opts->indirect.gi_cache ? opts->gicache : NULL;
        t.footprint_scale = render_footprint_scale(noise ? noise_most(&opts->noise) : g.n);
        t.pass = opts->pass;
        t.depth_scale = depth_scale;

        for (int k = 0; k < TRACE_OCCLUDERS; k++)
            occluders[k] = BVH_NO_SLOT;
#ifdef _OPENMP
#pragma omp single
        used = omp_get_num_threads();
        /* Tiles are handed out one at a time: their costs differ widely. */
#pragma omp for schedule(dynamic, 1)
#endif
        for (int k = 0; k < tiles; k++) {
            render_tile(&t, opts, &g, img, render_tile_order(k, tiles, noise), columns);
            if (opts->progress) {
#ifdef _OPENMP
#pragma omp critical(render_progress)
#endif
                opts->progress(opts->progress_ctx, ++done, tiles);
            }
        }
        if (counts) {
#ifdef _OPENMP
#pragma omp critical(render_counts)
#endif
            ray_counts_add(counts, &mine);
        }
        if (cutting)
            cut_free(&cut);
    }
    free(columns);
    return used;
}
