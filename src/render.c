/* render.c: the pixel loop (see render.h). */
#include "render.h"

#include "camera.h"
#include "trace.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* Renders row y of the image. */
static void render_row(const Scene *scene, const RenderOptions *opts, Image *img, int y)
{
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
