/* texture_file.c: textures from image files (see texture_file.h). */
#include "scenefile/texture_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/path.h"
#include "image/decode.h"

int texture_file_load(Texture *tex, const char *path, size_t max_bytes, Error *err)
{
    size_t n = strlen(path);
    Decoded d;

    memset(tex, 0, sizeof *tex);
    tex->path = malloc(n + 1);
    if (!tex->path) {
        error_set(err, path, "out of memory");
        return -1;
    }
    memcpy(tex->path, path, n + 1);
    if (decoded_read(path, max_bytes, &d, err) != 0) {
        texture_free(tex);
        return -1;
    }
    if (d.linear) {
        error_set(err, file_display_name(path),
                  "a PFM image holds linear colours, which a texture does not take: save it "
                  "as PPM, PNG, JPEG or BMP");
        decoded_free(&d);
        texture_free(tex);
        return -1;
    }
    snprintf(tex->warning, sizeof tex->warning, "%s", d.warning);
    tex->width = d.width;
    tex->height = d.height;
    tex->texels = d.samples; /* the texture takes them over */
    tex->scale = 255.0 / d.maxval;
    return 0;
}

int texture_file_add(Scene *scene, const char *path, Error *err)
{
    Texture tex;

    for (size_t i = 0; i < scene->texture_count; i++)
        if (strcmp(scene->textures[i].path, path) == 0)
            return (int)i;
    if (texture_file_load(&tex, path, scene_obj_budget(scene), err) != 0)
        return TEXTURE_FILE_FAULT;
    return scene_add_texture(scene, &tex);
}

char *texture_file_find(const char *scene_name, const char *name, size_t len,
                        const char *const *folders, size_t nfolders)
{
    char *first = path_beside(scene_name, "", name, len);

    if (!first)
        return NULL;
    for (size_t i = 0; i <= nfolders; i++) {
        char *path = i == 0 ? first : path_beside(scene_name, folders[i - 1], name, len);
        FILE *f;
        if (!path) {
            free(first);
            return NULL;
        }
        errno = 0;
        f = file_open(path, "rb");
        if (f || (errno != ENOENT && errno != ENOTDIR)) {
            /* There, or there but unreadable: loading it says why. */
            if (f)
                fclose(f);
            if (path != first)
                free(first);
            return path;
        }
        if (path != first)
            free(path);
        if (path_is_absolute(name, len))
            break;
    }
    return first;
}

