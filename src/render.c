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
                           int x, int y)
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
        sum = colour_add(sum, trace_ray(scene, &ray, 0, opts->max_depth));
    }
    return colour(sum.r / g->n, sum.g / g->n, sum.b / g->n);
}

/* Renders row y of the image. */
static void render_row(const Scene *scene, const RenderOptions *opts, Image *img, int y)
{
    SamplerGrid g = sampler_grid((unsigned)opts->samples);

    if (g.n > 1) {
        for (int x = 0; x < img->width; x++)
            image_set(img, x, y, render_pixel(scene, opts, &g, x, y));
        return;
    }
    /* One sample: the pixel's centre, through the lens's centre. */
    for (int x = 0; x < img->width; x++) {
        Ray ray = camera_ray(&scene->camera, x + 0.5, y + 0.5);
        image_set(img, x, y, trace_ray(scene, &ray, 0, opts->max_depth));
    }
}

int render(const Scene *scene, const RenderOptions *opts, Image *img)
{
#ifdef _OPENMP
    /* Rows are handed out one at a time: their costs differ widely. */
#pragma omp parallel for schedule(dynamic, 1) num_threads(opts->threads)
#endif
    for (int y = 0; y < img->height; y++)
        render_row(scene, opts, img, y);
#ifdef _OPENMP
    return opts->threads;
#else
    return 1;
#endif
}

int render_default_threads(void)
{
#ifdef _OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}
