/* model.c: the lighting models' table (see model.h). */
#include "render/model.h"

#include "render/mpl_light.h"
#include "render/trace.h"

/* The MPL model darkens its own ambient term, which every scene has. */
static int model_mpl_light_occludes(const Scene *scene)
{
    (void)scene;
    return 1;
}

static const Model model_table[] = {
    {
        .id = SCENE_MODEL_PHYSICAL,
        .name = "physical",
        .trace = trace_ray_diff,
        .miss = trace_miss,
        .miss_uniform = trace_miss_uniform,
        .max_depth = 10,
        .may_cut = 1,
        .occludes = trace_has_ambient, /* the tracer's own ambient rule */
    },
    {
        .id = SCENE_MODEL_MPL,
        .name = "mpl",
        .trace = mpl_light_trace_diff,
        .miss = mpl_light_miss,
        .miss_uniform = mpl_light_miss_uniform,
        .max_depth = MPL_LIGHT_MAX_DEPTH,
        .ao_rays = MPL_LIGHT_AO_RAYS,
        .gi_rays = MPL_LIGHT_GI_RAYS,
        .ao_distance = MPL_LIGHT_AO_DISTANCE,
        .gamma = MPL_LIGHT_GAMMA,
        .verbose = "the MPL model: its program's light, occlusion and gathering",
        .bounces_note = "the MPL model gathers the colours its rays meet, one bounce "
                        "(--model physical gathers light)",
        .cache_note = "the MPL model keeps its own gathering, every point's rays (--model "
                      "physical gathers through the cache)",
        .occludes = model_mpl_light_occludes,
    },
};

const Model *model_of(const Scene *scene)
{
    for (size_t k = 0; k < sizeof model_table / sizeof model_table[0]; k++)
        if (model_table[k].id == scene->model)
            return &model_table[k];
    return &model_table[0];
}

int model_choosable(const Scene *scene)
{
    return scene->format == SCENE_MPL;
}

Tracer model_tracer(const Scene *scene, int max_depth, RayCounts *counts)
{
    Tracer t = {0};

    t.scene = scene;
    t.model = model_of(scene);
    t.named = scene->named_count > 0;
    t.max_depth = max_depth;
    t.counts = counts;
    return t;
}
