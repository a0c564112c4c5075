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
    {SCENE_MODEL_PHYSICAL, "physical", trace_ray_diff, trace_miss, trace_miss_uniform, 10, 0, 0, 0,
     0, 1, NULL, NULL, NULL, trace_has_ambient}, /* the tracer's own ambient rule */
    {SCENE_MODEL_MPL, "mpl", mpl_light_trace_diff, mpl_light_miss, mpl_light_miss_uniform,
     MPL_LIGHT_MAX_DEPTH, MPL_LIGHT_AO_RAYS, MPL_LIGHT_GI_RAYS, MPL_LIGHT_AO_DISTANCE, MPL_LIGHT_GAMMA, 0,
     "the MPL model: its program's light, occlusion and gathering",
     "the MPL model gathers the colours its rays meet, one bounce (--model physical gathers "
     "light)",
     "the MPL model keeps its own gathering, every point's rays (--model physical gathers "
     "through the cache)",
     model_mpl_light_occludes},
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
