/* summary.c: what raytrace tells the user of a render (see summary.h). */
#include "cli/summary.h"

#include <stdio.h>

#include "accel/bvh.h"
#include "accel/light_buffer.h"
#include "base/process.h"
#include "math/number.h"
#include "render/model.h"

/* Prints, for -v, light buffer lb (light_buffer.h), around `what`. */
static void summary_buffer(const char *what, const LightBuffer *lb)
{
    char b[NUMBER_FORMAT_MAX];

    fprintf(stderr, "raytrace: light buffer of %s: 6 x %d x %d cells, %zu entries, %s\n", what,
            lb->res, lb->res, lb->entry_count, number_bytes(b, light_buffer_memory(lb)));
}

/* Prints, for -v, the light buffers the scene was given, built in seconds. */
static void summary_buffers(const Scene *scene, double seconds)
{
    char what[32];
    int any = scene->eye_buffer != NULL;

    for (size_t i = 0; scene->light_buffers && i < scene->light_count; i++)
        any |= scene->light_buffers[i].first != NULL;
    if (any)
        fprintf(stderr, "raytrace: light buffers built in %.3f s\n", seconds);
    if (scene->eye_buffer)
        summary_buffer("the eye", scene->eye_buffer);
    for (size_t i = 0; scene->light_buffers && i < scene->light_count; i++)
        if (scene->light_buffers[i].first) {
            snprintf(what, sizeof what, "light %zu", i + 1);
            summary_buffer(what, &scene->light_buffers[i]);
        }
}

/* Returns how ropts samples pixels, for a summary: "4 samples per pixel",
 * or under --noise its level and bounds (the text is overwritten by the
 * next call). */
const char *summary_samples_text(const RenderOptions *ropts)
{
    static char text[96];

    if (ropts->noise.level > 0)
        snprintf(text, sizeof text, "--noise %g (%u to %u samples a pixel)", ropts->noise.level,
                 ropts->noise.min_spp, ropts->noise.max_spp);
    else
        snprintf(text, sizeof text, "%d sample%s per pixel", ropts->samples,
                 ropts->samples == 1 ? "" : "s");
    return text;
}

/* Prints the -v summary: size, threads, rays by kind, the model when it
 * is the MPL ray tracer's, time, speed, peak memory. */
static void summary_statistics(const Image *img, const RenderOptions *ropts, const Model *model,
                            int threads, const RayCounts *c, const SummaryTimes *times)
{
    unsigned long long all = c->primary + c->shadow + c->reflection + c->refraction +
                             c->occlusion + c->gather;
    char indirect[96] = "";

    fprintf(stderr, "raytrace: %d x %d pixels, %s, %d thread%s\n", img->width, img->height,
            summary_samples_text(ropts), threads, threads == 1 ? "" : "s");
    if (ropts->indirect.ao_samples > 0 || ropts->indirect.gi_samples > 0)
        snprintf(indirect, sizeof indirect, "%llu occlusion, %llu gathering, ", c->occlusion,
                 c->gather);
    fprintf(stderr,
            "raytrace: rays: %llu primary, %llu shadow, %llu reflection, %llu refraction, "
            "%s%llu in all\n",
            c->primary, c->shadow, c->reflection, c->refraction, indirect, all);
    if (model->verbose && model->gamma > 0)
        fprintf(stderr, "raytrace: %s; gamma %g\n", model->verbose, model->gamma);
    else if (model->verbose)
        fprintf(stderr, "raytrace: %s\n", model->verbose);
    if (ropts->indirect.ao_samples > 0)
        fprintf(stderr, "raytrace: ambient occlusion: %d rays a point, distance %g\n",
                ropts->indirect.ao_samples, ropts->indirect.ao_distance);
    if (ropts->indirect.gi_samples > 0)
        fprintf(stderr, "raytrace: global illumination: %d rays a point, %d bounce%s\n",
                ropts->indirect.gi_samples, ropts->indirect.gi_bounces,
                ropts->indirect.gi_bounces == 1 ? "" : "s");
    if (ropts->cutoff > 0)
        fprintf(stderr,
                "raytrace: cut-off %g levels: %llu rays left out, %llu pixels refined\n",
                ropts->cutoff, c->cut, c->refined);
    /* The rays counted include the cache's pre-pass's: the rate is over
     * its time too. */
    if (times->cache > 0)
        fprintf(stderr, "raytrace: rendered in %.3f s, after the cache's %.3f s: %.2f Mrays/s "
                        "over both\n",
                times->render, times->cache, all / (times->render + times->cache) / 1e6);
    else
        fprintf(stderr, "raytrace: rendered in %.3f s: %.2f Mrays/s\n", times->render,
                times->render > 0 ? all / times->render / 1e6 : 0.0);
    fprintf(stderr, "raytrace: peak memory: %.1f MB\n", process_peak_memory() / 1e6);
}

/* Prints, for -v, the samples n pixels took under --noise and the errors
 * they reached. */
static void summary_noise(const RenderOptions *ropts, size_t n, const char *spp_map)
{
    NoiseSummary s;
    size_t short_of = 0;

    noise_summarise(ropts->spp, ropts->error, n, &s);
    for (size_t i = 0; i < n; i++)
        short_of += ropts->error[i] > ropts->noise.level;
    fprintf(stderr,
            "raytrace: --noise %g: samples a pixel %u to %u: mean %.1f, most %u; pixels by "
            "samples:",
            ropts->noise.level, ropts->noise.min_spp, ropts->noise.max_spp, s.mean_spp,
            s.max_spp);
    for (int b = 0; b < NOISE_BINS; b++)
        if (s.bins[b])
            fprintf(stderr, " %s%u %.1f%%", b == NOISE_BINS - 1 ? ">" : "<=",
                    b == NOISE_BINS - 1 ? 2u << b : 4u << b, 100.0 * s.bins[b] / n);
    fprintf(stderr, "\nraytrace: estimated error (one standard error, 68%% confidence): mean "
                    "%.3f, worst %.3f levels; %zu pixel%s short of %g at --max-spp\n",
            s.mean_error, s.worst_error, short_of, short_of == 1 ? "" : "s", ropts->noise.level);
    if (ropts->indirect.gi_cache)
        fprintf(stderr, "raytrace: under --gi-cache the estimate sees only the spread of the "
                        "camera's samples: the cache's error is the same in every sample\n");
    if (spp_map)
        fprintf(stderr, "raytrace: map of samples: %s (black %u or fewer, white %u, log scale)\n",
                spp_map, ropts->noise.min_spp, ropts->noise.max_spp);
}

void summary_read(double seconds, const SceneSource *source)
{
    fprintf(stderr, "raytrace: read the scene in %.3f s\n", seconds);
    for (size_t i = 0; i < source->mesh_count; i++) {
        const SceneMesh *m = &source->meshes[i];
        fprintf(stderr, "raytrace: mesh %s (%s): %zu triangle%s, ", m->path, m->format, m->count,
                m->count == 1 ? "" : "s");
        if (m->own_materials)
            fprintf(stderr, "%zu material%s of its own, %zu texture%s", m->materials,
                    m->materials == 1 ? "" : "s", m->textures, m->textures == 1 ? "" : "s");
        else
            fputs("the scene's material", stderr);
        if (m->polygons > 0)
            fprintf(stderr, "; %zu face%s of more than 3 corners: %zu cut around %s notches, %zu "
                            "not simple",
                    m->polygons, m->polygons == 1 ? "" : "s", m->polygons_cut,
                    m->polygons_cut == 1 ? "its" : "their", m->polygons_irregular);
        fputc('\n', stderr);
    }
}

void summary_verbose(const Scene *scene, const Image *img, const RenderOptions *ropts,
                     const char *spp_map, const SummaryTimes *times, int threads,
                     const RayCounts *counts)
{
    if (scene->accel)
        fprintf(stderr, "raytrace: bounding volume hierarchy: %zu nodes, depth %d, built in "
                        "%.3f s%s\n",
                scene->accel->node_count, scene->accel->depth, times->accel,
                scene->accel->avx2 ? ", box tests in AVX2 and FMA" : "");
    summary_buffers(scene, times->buffers);
    summary_statistics(img, ropts, model_of(scene), threads, counts, times);
    if (ropts->spp)
        summary_noise(ropts, (size_t)img->width * (size_t)img->height, spp_map);
    fprintf(stderr, "raytrace: wrote the image in %.3f s\n", times->write);
}

void summary_gi_cache(const GiCache *cache, const IrradianceStats *stats, const RayCounts *counts,
                      const char *map)
{
    fprintf(stderr,
            "raytrace: irradiance cache: error %g, %zu records (%zu where the camera's rays "
            "reach), %llu rays in its pre-pass, %.3f s\n",
            cache->a, stats->records, stats->seen, stats->rays, stats->seconds);
    fprintf(stderr, "raytrace: irradiance cache: %llu of %llu lookups served (%.1f%%), the rest "
                    "gathered\n",
            counts->served, counts->lookups,
            counts->lookups ? 100.0 * (double)counts->served / (double)counts->lookups : 100.0);
    if (map)
        fprintf(stderr, "raytrace: map of records: %s (red: a record the camera's rays reach)\n",
                map);
}

void summary_line(const char *output, const Scene *scene, const Image *img,
                  const RenderOptions *ropts, double seconds, int threads)
{
    size_t objects = scene_object_count(scene);

    fprintf(stderr, "raytrace: wrote %s: %d x %d pixels, %zu object%s, %s, %.2f s, %d thread%s\n",
            output, img->width, img->height, objects, objects == 1 ? "" : "s",
            summary_samples_text(ropts), seconds, threads, threads == 1 ? "" : "s");
}
