/*
 * summary.h: what raytrace tells the user of a render it has written: -v's
 * statistics (times, the hierarchy and light buffers, rays by kind, the
 * model, occlusion and gathering, the cut-off, --noise's samples and
 * errors, speed, peak memory) and, on a terminal, the one-line summary.
 * Everything goes to standard error; nothing here fails.
 */
#ifndef RAYTRACE_SUMMARY_H
#define RAYTRACE_SUMMARY_H

#include "image/image.h"
#include "render/gicache.h"
#include "render/irradiance.h"
#include "render/render.h"
#include "scene/scene.h"
#include "scenefile/source.h"

/* Seconds each step of a render took (accel: the hierarchy; buffers: the
 * light buffers; cache: the irradiance cache's pre-pass, 0 without one). */
typedef struct {
    double read, accel, buffers, cache, render, write;
} SummaryTimes;

/* Returns how ropts samples pixels: "4 samples per pixel", or under
 * --noise its level and bounds (the text is overwritten by the next
 * call). */
const char *summary_samples_text(const RenderOptions *ropts);

/* Prints -v's first line, "raytrace: read the scene in T s", as soon as
 * the scene is read (a render's first sign of life, and a test's sign that
 * an interrupt will be caught, which it is from the program's start), then
 * a line for each mesh the scene read from source: its triangles,
 * materials and textures, and its faces of more than three corners. */
void summary_read(double seconds, const SceneSource *source);

/* Prints -v's statistics, after summary_read(), of the render of scene into img with ropts on
 * `threads` threads, which cast counts' rays (spp_map: --spp-map's file,
 * or NULL). */
void summary_verbose(const Scene *scene, const Image *img, const RenderOptions *ropts,
                     const char *spp_map, const SummaryTimes *times, int threads,
                     const RayCounts *counts);

/* Prints -v's lines of the irradiance cache: records made (of which the
 * camera's rays reach), rays its pre-pass spent and its time, the share
 * of lookups it served in the render (counts), and its map's file (map,
 * or NULL). */
void summary_gi_cache(const GiCache *cache, const IrradianceStats *stats, const RayCounts *counts,
                      const char *map);

/* Prints "raytrace: wrote OUTPUT: W x H pixels, N objects, SAMPLES, T s,
 * N threads". */
void summary_line(const char *output, const Scene *scene, const Image *img,
                  const RenderOptions *ropts, double seconds, int threads);

#endif
