/* render.c: the pixel loop (see render.h). */
#include "render.h"

#include "camera.h"
#include "sampler.h"
#include "trace.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* Returns the mean colour of the grid's samples of pixel (x, y). */
static Colour render_pixel(const Scene *scene, const RenderOptions *opts, const SamplerGrid *g,
                           int x, int y, RayCounts *counts)
{
    const Camera *cam = &scene->camera;
    Colour sum = colour(0, 0, 0);

    for (unsigned k = 0; k < g->n; k++) {
        double p[2], l[2], disk[2] = {0, 0};
        Ray ray;

        sampler_sample(g, x, y, k, SAMPLER_DIM_PIXEL, p);
        if (cam->aperture > 0) {
            sampler_sample(g, x, y, k, SAMPLER_DIM_LENS, l);
            sampler_disk(l, disk);
        }
        ray = camera_lens_ray(cam, x + p[0], y + p[1], disk);
        sum = colour_add(sum, trace_ray(scene, &ray, 0, opts->max_depth, counts));
    }
    counts->primary += g->n;
    return colour(sum.r / g->n, sum.g / g->n, sum.b / g->n);
}

/* Renders row y of the image. */
static void render_row(const Scene *scene, const RenderOptions *opts, Image *img, int y,
                       RayCounts *counts)
{
    SamplerGrid g = sampler_grid((unsigned)opts->samples);

    if (g.n > 1) {
        for (int x = 0; x < img->width; x++)
            image_set(img, x, y, render_pixel(scene, opts, &g, x, y, counts));
        return;
    }
    /* One sample: the pixel's centre, through the lens's centre. */
    for (int x = 0; x < img->width; x++) {
        Ray ray = camera_ray(&scene->camera, x + 0.5, y + 0.5);
        image_set(img, x, y, trace_ray(scene, &ray, 0, opts->max_depth, counts));
    }
    counts->primary += (unsigned long long)img->width;
}

/* Adds the counts of b to a. */
static void render_add_counts(RayCounts *a, const RayCounts *b)
{
    a->primary += b->primary;
    a->shadow += b->shadow;
    a->reflection += b->reflection;
    a->refraction += b->refraction;
}

int render(const Scene *scene, const RenderOptions *opts, Image *img, RayCounts *counts)
{
    int done = 0, used = 1;

#ifdef _OPENMP
#pragma omp parallel num_threads(opts->threads)
#endif
    {
        RayCounts mine = {0, 0, 0, 0};

#ifdef _OPENMP
#pragma omp single
        used = omp_get_num_threads();
        /* Rows are handed out one at a time: their costs differ widely. */
#pragma omp for schedule(dynamic, 1)
#endif
        for (int y = 0; y < img->height; y++) {
            render_row(scene, opts, img, y, &mine);
            if (opts->progress) {
#ifdef _OPENMP
#pragma omp critical(render_progress)
#endif
                opts->progress(opts->progress_ctx, ++done, img->height);
            }
        }
        if (counts) {
#ifdef _OPENMP
#pragma omp critical(render_counts)
#endif
            render_add_counts(counts, &mine);
        }
    }
    return used;
}

int render_default_threads(void)
{
#ifdef _OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}
