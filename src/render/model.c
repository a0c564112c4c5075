/* model.c: the lighting models' table (see model.h). */
#include "render/model.h"

#include "render/seed001.h"
#include "render/trace.h"

/* Seed 001's model darkens its own ambient term, which every scene has. */
static int model_seed001_occludes(const Scene *scene)
{
    (void)scene;
    return 1;
}

static const Model model_table[] = {
    {SCENE_MODEL_PHYSICAL, "physical", trace_ray_diff, trace_miss, trace_miss_uniform, 10, 0, 0, 0,
     0, 1, NULL, NULL, NULL, trace_has_ambient}, /* the tracer's own ambient rule */
    {SCENE_MODEL_SEED001, "seed001", seed001_trace_diff, seed001_miss, seed001_miss_uniform,
     SEED001_MAX_DEPTH, SEED001_AO_RAYS, SEED001_GI_RAYS, SEED001_AO_DISTANCE, SEED001_GAMMA, 0,
     "seed 001's model: its program's light, occlusion and gathering",
     "seed 001's model gathers the colours its rays meet, one bounce (--model physical gathers "
     "light)",
     "seed 001's model keeps its own gathering, every point's rays (--model physical gathers "
     "through the cache)",
     model_seed001_occludes},
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
