/* texture_file.c: textures from image files (see texture_file.h). */
#include "scenefile/texture_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/path.h"
#include "image/bmp.h"
#include "image/jpeg.h"
#include "image/png.h"
#include "image/ppm.h"

/* Makes tex's texels the 8-bit RGB image rgb of width x height; returns
 * 0, or -1 with *err set when memory runs out. */
static int texture_file_bytes(Texture *tex, const char *name, int width, int height,
                              const unsigned char *rgb, Error *err)
{
    size_t n = 3 * (size_t)width * (size_t)height;

    tex->texels = malloc(n * sizeof *tex->texels);
    if (!tex->texels) {
        error_set(err, name, "out of memory for a %d x %d texture", width, height);
        return -1;
    }
    for (size_t k = 0; k < n; k++)
        tex->texels[k] = rgb[k];
    tex->width = width;
    tex->height = height;
    tex->scale = 1;
    return 0;
}

/* Decodes the len bytes at data, the file name, into tex by their first
 * bytes: JPEG, PNG, BMP or PPM; JPEG's buffers within max_bytes. */
static int texture_file_decode(Texture *tex, const char *name, const char *data, size_t len,
                               size_t max_bytes, Error *err)
{
    const unsigned char *head = (const unsigned char *)data;
    int rc;

    if (jpeg_is(head, len)) {
        JpegImage jpg;
        if (jpeg_parse(name, head, len, max_bytes, &jpg, err) != 0)
            return -1;
        snprintf(tex->warning, sizeof tex->warning, "%s", jpg.warning);
        rc = texture_file_bytes(tex, name, jpg.width, jpg.height, jpg.rgb, err);
        jpeg_free(&jpg);
        return rc;
    }
    if (len >= 8 && head[0] == 0x89 && memcmp(head + 1, "PNG", 3) == 0) {
        PngImage png;
        if (png_parse(name, head, len, &png, err) != 0)
            return -1;
        rc = texture_file_bytes(tex, name, png.width, png.height, png.rgb, err);
        png_free(&png);
        return rc;
    }
    if (bmp_is(head, len)) {
        BmpImage bmp;
        if (bmp_parse(name, head, len, &bmp, err) != 0)
            return -1;
        rc = texture_file_bytes(tex, name, bmp.width, bmp.height, bmp.rgb, err);
        bmp_free(&bmp);
        return rc;
    }
    {
        PpmImage im;
        if (ppm_parse(name, data, len, &im, err) != 0)
            return -1;
        tex->width = im.width;
        tex->height = im.height;
        tex->texels = im.samples; /* the texture takes them over */
        tex->scale = 255.0 / im.maxval;
    }
    return 0;
}

int texture_file_load(Texture *tex, const char *path, size_t max_bytes, Error *err)
{
    size_t n = strlen(path), len;
    char *data;
    int rc;

    memset(tex, 0, sizeof *tex);
    tex->path = malloc(n + 1);
    if (!tex->path) {
        error_set(err, path, "out of memory");
        return -1;
    }
    memcpy(tex->path, path, n + 1);
    if (file_read_all(path, &data, &len, err) != 0) {
        texture_free(tex);
        return -1;
    }
    rc = texture_file_decode(tex, file_display_name(path), data, len, max_bytes, err);
    free(data);
    if (rc != 0)
        texture_free(tex);
    return rc;
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

