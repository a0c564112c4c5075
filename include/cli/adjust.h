/*
 * adjust.h: what the command line changes in a scene and its render: the
 * model and size, the depth, samples, --noise, occlusion and gathering
 * (the command line first, then the scene, then the model's defaults),
 * with one note on standard error for each option that can change nothing
 * here; and the fingerprint that keeps tiles of different renders apart.
 */
#ifndef RAYTRACE_ADJUST_H
#define RAYTRACE_ADJUST_H

#include <stdint.h>

#include "cli/options.h"
#include "render/render.h"
#include "scene/scene.h"

/* Applies opts' choices about the picture to scene (its model and size)
 * and sets ropts' depth, samples, adaptive sampling and indirect light. */
void adjust_render(const Options *opts, Scene *scene, RenderOptions *ropts);

/* Returns the fingerprint of a render of scene with ropts: what it was
 * read from and every option that changes its pixels. */
uint64_t adjust_fingerprint(const Scene *scene, const RenderOptions *ropts);

#endif
