/*
 * fuzz_scene.h: the body shared by the scene fuzz targets: parse the input
 * as a scene of one format and, when it is accepted and small, build its
 * hierarchy and render it, so the tracer meets every value a parser lets
 * through. Included by fuzz_course.c, fuzz_keyword.c and fuzz_mpl.c only.
 */
#include <stddef.h>
#include <stdint.h>

#include "render/render.h"
#include "scene/scene_accel.h"
#include "scenefile/load.h"

static int fuzz_scene(const uint8_t *data, size_t size, SceneFormat format)
{
    Scene scene;
    Error err;
    Image img;
    RayCounts counts = {0};
    RenderOptions opts = {.max_depth = 4, .samples = 1, .cutoff = 0.001, .threads = 1};

    scene_init(&scene);
    if (load_scene_text("fuzz", (const char *)data, size, format, 0, 0, &scene, NULL, &err) == 0 &&
        (long)scene.camera.width * scene.camera.height <= 32 * 32 &&
        (scene.samples == 0 || scene.samples <= 4)) {
        opts.samples = scene.samples ? scene.samples : 1;
        scene_build_accel(&scene, 1);
        if (image_init(&img, scene.camera.width, scene.camera.height) == 0) {
            render(&scene, &opts, &img, &counts);
            image_free(&img);
        }
    }
    scene_free(&scene);
    return 0;
}
