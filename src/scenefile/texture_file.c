/* texture_file.c: textures from image files (see texture_file.h). */
#include "scenefile/texture_file.h"

#include <stdlib.h>
#include <string.h>

#include "image/ppm.h"

int texture_file_load(Texture *tex, const char *path, Error *err)
{
    size_t n = strlen(path);
    PpmImage im;

    memset(tex, 0, sizeof *tex);
    tex->path = malloc(n + 1);
    if (!tex->path) {
        error_set(err, path, "out of memory");
        return -1;
    }
    memcpy(tex->path, path, n + 1);
    if (ppm_read(path, &im, err) != 0) {
        texture_free(tex);
        return -1;
    }
    tex->width = im.width;
    tex->height = im.height;
    tex->texels = im.samples; /* the texture takes them over */
    tex->scale = 255.0 / im.maxval;
    return 0;
}

int texture_file_add(Scene *scene, const char *path, Error *err)
{
    Texture tex;

    for (size_t i = 0; i < scene->texture_count; i++)
        if (strcmp(scene->textures[i].path, path) == 0)
            return (int)i;
    if (texture_file_load(&tex, path, err) != 0)
        return TEXTURE_FILE_FAULT;
    return scene_add_texture(scene, &tex);
}
