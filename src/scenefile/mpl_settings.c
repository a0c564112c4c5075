/* mpl_settings.c: the MPL reader's 'c' lines, the scene's settings (see
 * mpl_read.h, docs/scene-format.md). */
#include <stdio.h>
#include <string.h>

#include "math/angle.h"
#include "math/number.h"
#include "mpl_read.h"

static const char *const mpl_rgb_names[] = {"red", "green", "blue"};
static const FieldKind mpl_rgb_kinds[] = {FIELD_FRACTION, FIELD_FRACTION, FIELD_FRACTION};
static const char *const mpl_camera_names[] = {"x",  "y",  "z",  "target x",
                                               "target y", "target z", "field of view"};
static const FieldKind mpl_camera_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                             FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                             FIELD_POSITIVE};
static const char *const mpl_sky_names[] = {"zenith red", "zenith green", "zenith blue",
                                            "nadir red",  "nadir green",  "nadir blue"};
static const FieldKind mpl_sky_kinds[] = {FIELD_FRACTION, FIELD_FRACTION, FIELD_FRACTION,
                                          FIELD_FRACTION, FIELD_FRACTION, FIELD_FRACTION};
static const char *const mpl_ao_names[] = {"distance"};
static const FieldKind mpl_ao_kinds[] = {FIELD_POSITIVE};
static const RecordSpec mpl_ao_distance = {"the ambient occlusion", NULL, 1, 0, 0, mpl_ao_names,
                                           mpl_ao_kinds};
static const char *const mpl_noise_names[] = {"level"};
static const FieldKind mpl_noise_kinds[] = {FIELD_POSITIVE};
static const RecordSpec mpl_noise = {"the noise", NULL, 1, 0, 0, mpl_noise_names, mpl_noise_kinds};
static const char *const mpl_gicache_names[] = {"error"};
static const RecordSpec mpl_gicache = {"the irradiance cache", NULL, 1, 0, 0, mpl_gicache_names,
                                       mpl_noise_kinds};
static const RecordSpec mpl_camera = {"the camera", "x y z tx ty tz fov width height", 7, 0, 0,
                                      mpl_camera_names, mpl_camera_kinds};
static const RecordSpec mpl_background = {"the background", "r g b", 3, 0, 0, mpl_rgb_names,
                                          mpl_rgb_kinds};
static const RecordSpec mpl_ambient = {"the ambient light", "r g b", 3, 0, 0, mpl_rgb_names,
                                       mpl_rgb_kinds};
static const RecordSpec mpl_sky = {"the sky", "r g b r g b", 6, 0, 0, mpl_sky_names,
                                   mpl_sky_kinds};


/* camera -> 'c' Camera px py pz tx ty tz fov width height */
static int mpl_camera_record(Mpl *M, const Record *rec, Scene *scene)
{
    double v[7], half;
    int width, height;
    char q[64];

    if (lex_once(&M->lex, rec, &M->camera_line, "the camera") != 0 ||
        mpl_need(M, rec, 10, "the camera's numbers", mpl_camera.syntax) != 0)
        return -1;
    for (int k = 0; k < 7; k++)
        if (lex_number(&M->lex, rec, 2 + k, &mpl_camera, k, &v[k]) != 0)
            return -1;
    if (lex_whole_number(&M->lex, rec, 9, "the image width", "pixels", CAMERA_MAX_SIZE, &width) !=
            0 ||
        lex_whole_number(&M->lex, rec, 10, "the image height", "pixels", CAMERA_MAX_SIZE,
                         &height) != 0)
        return -1;
    if (rec->count > 11)
        return lex_fail_extra(&M->lex, rec, 11, "the image height");
    if (!(v[6] < 180)) {
        mpl_fail(M, &rec->line, rec->tok[8].column,
                 "the camera's field of view must be less than 180 degrees, found %s",
                 lex_quote(q, sizeof q, &rec->tok[8]));
        return -1;
    }
    M->source->camera_line = 1;
    M->source->look_from = vec3(v[0], v[1], v[2]);
    M->source->look_at = vec3(v[3], v[4], v[5]);
    M->source->fov = v[6];
    /* The MPL ray tracer's field of view is vertical; the camera's, horizontal. */
    half = angle_atan2(angle_tan(v[6] * ANGLE_PI / 360) * width, height);
    switch (camera_look_at(&scene->camera, M->source->look_from, M->source->look_at, 2 * half,
                           width, height)) {
    case CAMERA_VIEW_OK:
        return 0;
    case CAMERA_VIEW_NO_DIRECTION:
        mpl_fail(M, &rec->line, rec->tok[5].column,
                 "the camera looks at its own position: its target must be elsewhere");
        return -1;
    default:
        mpl_fail(M, &rec->line, rec->tok[8].column,
                 "the camera's field of view %s is too narrow: the screen has no size in double "
                 "precision",
                 lex_quote(q, sizeof q, &rec->tok[8]));
        return -1;
    }
}

/* AO -> 'c' AO n [distance] | GI -> 'c' GI n [bounces]: ambient occlusion
 * and global illumination rays (the MPL ray tracer's section IV, trace.h, mpl_light.h);
 * 0 for none. */
static int mpl_indirect_record(Mpl *M, const Record *rec, Scene *scene, int gi)
{
    const char *what = gi ? "the global illumination" : "the ambient occlusion";

    if (lex_once(&M->lex, rec, gi ? &M->gi_line : &M->ao_line, what) != 0 ||
        mpl_need(M, rec, 2, gi ? "the number of global illumination rays"
                               : "the number of ambient occlusion rays",
                 gi ? "c GI n [bounces]" : "c AO n [distance]") != 0 ||
        lex_whole_number_in(&M->lex, rec, 2, gi ? "the number of global illumination rays"
                                                : "the number of ambient occlusion rays",
                            "rays", 0, SCENE_MAX_INDIRECT,
                            gi ? &scene->gi_samples : &scene->ao_samples) != 0)
        return -1;
    if (rec->count > 4)
        return lex_fail_extra(&M->lex, rec, 4, gi ? "the number of bounces" : "the distance");
    if (rec->count == 4)
        return gi ? lex_whole_number(&M->lex, rec, 3, "the number of bounces", "bounces",
                                     SCENE_MAX_BOUNCES, &scene->gi_bounces)
                  : lex_number(&M->lex, rec, 3, &mpl_ao_distance, 0, &scene->ao_distance);
    return 0;
}

/* noise -> 'c' Noise level [min [max]]: adaptive sampling, each pixel
 * until its estimated error is at most level levels (0..255), between min
 * and max samples (render/noise.h). */
static int mpl_noise_record(Mpl *M, const Record *rec, Scene *scene)
{
    const char *syntax = "c Noise level [min-spp [max-spp]]";

    if (lex_once(&M->lex, rec, &M->noise_line, "the noise") != 0 ||
        mpl_need(M, rec, 2, "the noise level", syntax) != 0 ||
        lex_number(&M->lex, rec, 2, &mpl_noise, 0, &scene->noise) != 0)
        return -1;
    if (scene->noise > 255) {
        mpl_fail(M, &rec->line, rec->tok[2].column,
                 "the noise level must be at most 255 levels (an error the size of the whole "
                 "range)");
        return -1;
    }
    if (rec->count > 5)
        return lex_fail_extra(&M->lex, rec, 5, "the noise");
    if ((rec->count > 3 &&
         lex_whole_number_in(&M->lex, rec, 3, "the least samples a pixel", "samples", 1,
                             SCENE_MAX_SPP, &scene->noise_min_spp) != 0) ||
        (rec->count > 4 &&
         lex_whole_number_in(&M->lex, rec, 4, "the most samples a pixel", "samples", 1,
                             SCENE_MAX_SPP, &scene->noise_max_spp) != 0))
        return -1;
    if (rec->count > 4 && scene->noise_max_spp < scene->noise_min_spp) {
        mpl_fail(M, &rec->line, rec->tok[4].column,
                 "the most samples a pixel (%d) is fewer than the least (%d)",
                 scene->noise_max_spp, scene->noise_min_spp);
        return -1;
    }
    return 0;
}

/* gicache -> 'c' GICache [error]: global illumination's light through the
 * irradiance cache (render/irradiance.h), of accuracy error. */
static int mpl_gicache_record(Mpl *M, const Record *rec, Scene *scene)
{
    if (lex_once(&M->lex, rec, &M->gicache_line, "the irradiance cache") != 0)
        return -1;
    scene->gi_cache = 1;
    if (rec->count > 3)
        return lex_fail_extra(&M->lex, rec, 3, "the irradiance cache's error");
    if (rec->count == 3 &&
        lex_number(&M->lex, rec, 2, &mpl_gicache, 0, &scene->gi_cache_error) != 0)
        return -1;
    if (rec->count == 3 && !(scene->gi_cache_error >= SCENE_GI_CACHE_MIN_ERROR &&
                             scene->gi_cache_error <= SCENE_GI_CACHE_MAX_ERROR)) {
        mpl_fail(M, &rec->line, rec->tok[2].column,
                 "the irradiance cache's error must be from %g to %g (smaller: more records)",
                 SCENE_GI_CACHE_MIN_ERROR, SCENE_GI_CACHE_MAX_ERROR);
        return -1;
    }
    return 0;
}

/* model -> 'c' Model mpl | 'c' Model physical: the rules the picture
 * is made by (scene.h). */
static int mpl_model_record(Mpl *M, const Record *rec, Scene *scene)
{
    char q[64];

    if (lex_once(&M->lex, rec, &M->model_line, "the model") != 0 ||
        mpl_need(M, rec, 2, "the model", "c Model mpl or c Model physical") != 0)
        return -1;
    /* "seed001" is the old spelling of "mpl", still taken. */
    if (mpl_word_is(&rec->tok[2], "mpl") || mpl_word_is(&rec->tok[2], "seed001")) {
        scene->model = SCENE_MODEL_MPL;
    } else if (mpl_word_is(&rec->tok[2], "physical")) {
        scene->model = SCENE_MODEL_PHYSICAL;
    } else {
        mpl_fail(M, &rec->line, rec->tok[2].column,
                 "unknown model %s (expected mpl, the MPL ray tracer's rules, or physical)",
                 lex_quote(q, sizeof q, &rec->tok[2]));
        return -1;
    }
    return rec->count > 3 ? lex_fail_extra(&M->lex, rec, 3, "the model") : 0;
}

int mpl_setting_record(Mpl *M, const Record *rec, Scene *scene)
{
    double v[6];
    char q[64];

    if (mpl_need(M, rec, 1, "the setting",
                 "Camera, Background, Sky, Ambient, Samples, AO, GI, GICache, Model or Noise") != 0)
        return -1;
    if (mpl_word_is(&rec->tok[1], "Model"))
        return mpl_model_record(M, rec, scene);
    if (mpl_word_is(&rec->tok[1], "Noise"))
        return mpl_noise_record(M, rec, scene);
    if (mpl_word_is(&rec->tok[1], "GICache"))
        return mpl_gicache_record(M, rec, scene);
    if (mpl_word_is(&rec->tok[1], "AO") || mpl_word_is(&rec->tok[1], "GI"))
        return mpl_indirect_record(M, rec, scene, mpl_word_is(&rec->tok[1], "GI"));
    if (mpl_word_is(&rec->tok[1], "Camera"))
        return mpl_camera_record(M, rec, scene);
    if (mpl_word_is(&rec->tok[1], "Background") || mpl_word_is(&rec->tok[1], "Sky")) {
        int sky = mpl_word_is(&rec->tok[1], "Sky");
        if (lex_once(&M->lex, rec, &M->background_line, "the background") != 0 ||
            lex_numbers(&M->lex, rec, 2, sky ? &mpl_sky : &mpl_background, v) < 0)
            return -1;
        scene->has_sky = sky;
        scene->sky = sky ? colour(v[0] * 255, v[1] * 255, v[2] * 255) : colour(0, 0, 0);
        scene->background = sky ? colour(v[3] * 255, v[4] * 255, v[5] * 255)
                                : colour(v[0] * 255, v[1] * 255, v[2] * 255);
        return 0;
    }
    if (mpl_word_is(&rec->tok[1], "Ambient")) {
        if (lex_once(&M->lex, rec, &M->ambient_line, "the ambient light") != 0 ||
            lex_numbers(&M->lex, rec, 2, &mpl_ambient, v) < 0)
            return -1;
        scene->ambient = colour(v[0] * 255, v[1] * 255, v[2] * 255);
        scene->has_ambient = 1;
        return 0;
    }
    if (mpl_word_is(&rec->tok[1], "Samples")) {
        if (lex_once(&M->lex, rec, &M->samples_line, "the number of samples per pixel") != 0 ||
            mpl_need(M, rec, 2, "the number of samples per pixel", "c Samples n") != 0)
            return -1;
        if (rec->count > 3)
            return lex_fail_extra(&M->lex, rec, 3, "the number of samples per pixel");
        return lex_whole_number(&M->lex, rec, 2, "the number of samples per pixel", "samples",
                                CAMERA_MAX_SAMPLES, &scene->samples);
    }
    mpl_fail(M, &rec->line, rec->tok[1].column,
             "unknown setting %s (expected Camera, Background, Sky, Ambient, Samples, AO, GI, "
             "GICache, Model or Noise)",
             lex_quote(q, sizeof q, &rec->tok[1]));
    return -1;
}
