/* adjust.c: the command line's choices applied to a scene and its render
 * (see adjust.h). */
#include "cli/adjust.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/hash.h"
#include "render/gicache.h"
#include "render/noise.h"
#include "render/model.h"
#include "scene/camera.h"
#include "scene/scene_filter.h"

/* Sets *in from the command line, else from the scene, else from its
 * model's defaults: the rays, the occlusion distance (the scene file's
 * units, as the scene may have been enlarged; by default a tenth of the
 * scene's size, the MPL ray tracer's 2) and the bounces. */
static void adjust_indirect(const Options *opts, const Scene *scene, Indirect *in)
{
    const Model *model = model_of(scene);
    double d = opts->ao_distance > 0 ? opts->ao_distance : scene->ao_distance;

    if (!(d > 0))
        d = model->ao_distance;
    in->ao_samples = opts->ao >= 0 ? opts->ao : scene->ao_samples >= 0 ? scene->ao_samples
                                                                        : model->ao_rays;
    /* The scene's size, a pass over every shape, only for occlusion rays. */
    in->ao_distance = d > 0             ? ldexp(d, scene->length_exponent)
                      : in->ao_samples > 0 ? scene_size(scene) / 10
                                           : 0;
    in->gi_cache = opts->gi_cache || scene->gi_cache;
    /* The cache asked for without a count of rays: its own default. */
    in->gi_samples = opts->gi >= 0                       ? opts->gi
                     : scene->gi_samples >= 0            ? scene->gi_samples
                     : in->gi_cache && !model->cache_note ? GICACHE_DEFAULT_RAYS
                                                          : model->gi_rays;
    in->gi_bounces = opts->gi_bounces > 0 ? opts->gi_bounces
                     : scene->gi_bounces > 0 ? scene->gi_bounces
                                             : 1;
    in->gi_cache_error = opts->gi_cache_error > 0   ? opts->gi_cache_error
                         : scene->gi_cache_error > 0 ? scene->gi_cache_error
                                                     : GICACHE_DEFAULT_ERROR;
}

/* Prints "raytrace: note: WHAT" on standard error, the one place that
 * says an option changes nothing here. */
static void adjust_note(const Options *opts, const char *what)
{
    if (!opts->quiet)
        fprintf(stderr, "raytrace: note: %s\n", what);
}

/* Prints "raytrace: note: OPTION changes nothing here: WHY". */
static void adjust_note_why(const Options *opts, const char *option, const char *why)
{
    if (!opts->quiet)
        fprintf(stderr, "raytrace: note: %s changes nothing here: %s\n", option, why);
}

/* Turns the irradiance cache off where it can change nothing, saying so
 * of the options given: no gathering rays, or a model that keeps its own
 * gathering; and of --gi-cache-error and --gi-cache-map without it. */
static void adjust_gi_cache(const Options *opts, const Model *model, Indirect *in)
{
    const char *option = opts->gi_cache ? "--gi-cache" : NULL;

    if (in->gi_cache && in->gi_samples == 0) {
        if (option)
            adjust_note_why(opts, option, "no global illumination rays are cast (--gi 0)");
        in->gi_cache = 0;
    } else if (in->gi_cache && model->cache_note) {
        if (option)
            adjust_note_why(opts, option, model->cache_note);
        in->gi_cache = 0;
    }
    if (!in->gi_cache && (opts->gi_cache_error > 0 || opts->gi_cache_map) && !option)
        adjust_note(opts, "--gi-cache-error and --gi-cache-map change nothing without the "
                          "irradiance cache (--gi-cache)");
}

/* Sets ropts' adaptive sampling from the command line, else the scene
 * (noise.h); says when an option of it, or -s under it, changes nothing. */
static void adjust_noise(const Options *opts, const Scene *scene, RenderOptions *ropts)
{
    NoiseOptions *n = &ropts->noise;
    int most = opts->max_spp ? opts->max_spp : scene->noise_max_spp;
    int least = opts->min_spp ? opts->min_spp : scene->noise_min_spp;

    n->level = opts->noise >= 0 ? opts->noise : scene->noise;
    n->max_spp = most ? (unsigned)most : NOISE_MAX_SPP;
    n->min_spp = least ? (unsigned)least : noise_default_min(n->level);
    /* A bound given alone moves the other's default out of its way. */
    if (n->min_spp > n->max_spp) {
        if (least)
            n->max_spp = n->min_spp;
        else
            n->min_spp = n->max_spp;
    }
    if (n->level > 0 && opts->samples)
        adjust_note(opts, "--spp changes nothing here: --noise takes as many samples a pixel as "
                        "its error needs (bounded by --min-spp and --max-spp)");
    if (n->level > 0)
        return;
    if (opts->min_spp || opts->max_spp)
        adjust_note(opts, "--min-spp and --max-spp change nothing without --noise: every pixel "
                        "takes the samples -s asks for");
    if (opts->spp_map)
        adjust_note(opts, "--spp-map writes nothing without --noise: every pixel takes the "
                        "samples -s asks for");
}

/* Applies the command line's choices about the picture to scene (its
 * model and size) and sets ropts' depth, samples and indirect light from
 * them; says once, on standard error, of each option given that can
 * change nothing in this scene. */
/* Says whether some object of scene has a texture or stripes. */
static int adjust_has_patterns(const Scene *scene)
{
    SceneWalk w;
    ShapeKind kind;
    size_t index;

    scene_walk_start(&w);
    while (scene_walk_next(scene, &w, &kind, &index)) {
        Material m = scene_material(scene, kind, index);
        if (m.texture >= 0 || m.stripes)
            return 1;
    }
    return 0;
}

void adjust_render(const Options *opts, Scene *scene, RenderOptions *ropts)
{
    const Model *model;

    if (opts->model >= 0 && !model_choosable(scene))
        adjust_note(opts, "--model changes nothing here: it chooses how MPL scenes are lit; the "
                        "course and keyword formats have one model");
    else if (opts->model >= 0)
        scene->model = (SceneModel)opts->model;
    model = model_of(scene);
    if (opts->width > 0)
        camera_resize(&scene->camera, opts->width, opts->height);
    if (opts->texture_filter >= 0 && !adjust_has_patterns(scene))
        adjust_note(opts, "--texture-filter changes nothing here: no object has a texture or "
                          "stripes");
    else if (opts->texture_filter >= 0)
        scene_set_texture_filter(scene, (TextureFilter)opts->texture_filter);
    ropts->max_depth = opts->max_depth >= 0 ? opts->max_depth : model->max_depth;
    ropts->samples = opts->samples ? opts->samples : scene->samples ? scene->samples : 1;
    ropts->no_shadows = opts->no_shadows;
    adjust_noise(opts, scene, ropts);
    adjust_indirect(opts, scene, &ropts->indirect);
    adjust_gi_cache(opts, model, &ropts->indirect);
    if (opts->ao > 0 && !model->occludes(scene))
        adjust_note(opts, "--ao changes nothing here: ambient occlusion darkens the ambient "
                        "light, and this scene has none (add one: the course's ambient:, the "
                        "MPL format's c Ambient)");
    if (opts->ao_distance > 0 && ropts->indirect.ao_samples == 0)
        adjust_note(opts, "--ao-distance changes nothing here: no ambient occlusion rays are cast "
                        "(--ao N)");
    ropts->pass = (TracePass)opts->pass;
    if (ropts->pass == TRACE_PASS_INDIRECT && ropts->indirect.gi_samples == 0)
        adjust_note(opts, "--pass indirect is black here: no light is gathered (--gi N)");
    if (ropts->pass == TRACE_PASS_AO && ropts->indirect.ao_samples == 0)
        adjust_note(opts, "--pass ao is white here: no occlusion rays are cast (--ao N)");
    if (opts->gi_bounces > 0 && model->bounces_note && ropts->indirect.gi_samples > 0)
        adjust_note_why(opts, "--gi-bounces", model->bounces_note);
    else if (opts->gi_bounces > 0 && ropts->indirect.gi_samples == 0)
        adjust_note(opts, "--gi-bounces changes nothing here: no global illumination rays are "
                        "cast (--gi N)");
}

/* Returns the fingerprint of a render of scene with ropts: what it was read
 * from and every option that changes its pixels, so that tiles of
 * different renders are never merged. */
uint64_t adjust_fingerprint(const Scene *scene, const RenderOptions *ropts)
{
    uint64_t h = hash_u64(HASH_START, scene->source_hash), distance;
    double d = ropts->indirect.ao_distance;

    memcpy(&distance, &d, sizeof distance);
    h = hash_u64(h, (uint64_t)ropts->max_depth);
    h = hash_u64(h, (uint64_t)ropts->samples);
    h = hash_u64(h, (uint64_t)ropts->indirect.ao_samples);
    h = hash_u64(h, ropts->indirect.ao_samples ? distance : 0);
    h = hash_u64(h, (uint64_t)ropts->indirect.gi_samples);
    h = hash_u64(h, (uint64_t)ropts->indirect.gi_bounces);
    h = hash_u64(h, (uint64_t)scene->model);
    h = hash_u64(h, (uint64_t)ropts->no_shadows);
    if (scene->filter_override >= 0) /* else the hash of earlier versions */
        h = hash_u64(h, 0x100 + (uint64_t)scene->filter_override);
    if (ropts->noise.level > 0) { /* else the hash of earlier versions */
        double level = ropts->noise.level;
        uint64_t bits;
        memcpy(&bits, &level, sizeof bits);
        h = hash_u64(h, bits);
        h = hash_u64(h, (uint64_t)ropts->noise.min_spp << 32 | ropts->noise.max_spp);
    }
    if (ropts->indirect.gi_cache) { /* else the hash of earlier versions */
        double a = ropts->indirect.gi_cache_error;
        uint64_t bits;
        memcpy(&bits, &a, sizeof bits);
        h = hash_u64(hash_u64(h, 0x6763), bits);
    }
    if (ropts->pass != TRACE_PASS_FULL) /* else the hash of earlier versions */
        h = hash_u64(hash_u64(h, 0x7061), (uint64_t)ropts->pass);
    h = hash_u64(h, (uint64_t)scene->camera.width << 32 | (uint64_t)scene->camera.height);
    return hash_u64(h, sizeof(real)); /* a float build's pixels differ */
}

