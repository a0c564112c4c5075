/*
 * render.h: turning a scene into an image, rows shared among threads.
 *
 * Each pixel is traced on its own from its own primary ray, so the bytes do
 * not depend on the number of threads or on how rows are scheduled.
 */
#ifndef RAYTRACE_RENDER_H
#define RAYTRACE_RENDER_H

#include "image.h"
#include "scene.h"

typedef struct {
    int max_depth; /* deepest reflected ray traced, 0..TRACE_MAX_DEPTH_LIMIT */
    int threads;   /* worker threads, >= 1; 1 without OpenMP */
} RenderOptions;

/* Renders scene into img, which must already be sized to the scene's
 * camera width and height; cannot fail. Returns the number of threads used. */
int render(const Scene *scene, const RenderOptions *opts, Image *img);

/* Returns the number of threads render() can use by default: the number of
 * processors when built with OpenMP, else 1. */
int render_default_threads(void);

#endif
