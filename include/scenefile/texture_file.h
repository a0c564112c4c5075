/*
 * texture_file.h: reading a texture (scene/texture.h) from an image file.
 *
 * Read, told apart by their first bytes: JPEG (jpeg.h), PNG (png.h), BMP
 * (bmp.h) and PPM (P6 or P3, any maxval).
 */
#ifndef RAYTRACE_TEXTURE_FILE_H
#define RAYTRACE_TEXTURE_FILE_H

#include "base/error.h"
#include "scene/scene.h"
#include "scene/texture.h"

/* Reads the image file at path into *tex, keeping a copy of path, a
 * JPEG's decoding within max_bytes (0: no limit); returns 0, or -1 with
 * *err describing the fault in the file (*tex then owns nothing). */
int texture_file_load(Texture *tex, const char *path, size_t max_bytes, Error *err);

/* Returns, newly allocated, where the texture file name (len bytes, not
 * NUL-terminated) named by the scene file scene_name is: beside the scene
 * file, else in the first of its nfolders folders (relative to the scene
 * file's folder, each ending in '/') that has it; the search stops at a
 * file that opens, or that fails to open for another reason than not
 * being there (ENOENT, ENOTDIR), so that loading it reports that reason.
 * When none has it: the path beside the scene. An absolute name is taken
 * as it is. NULL when memory runs out. */
char *texture_file_find(const char *scene_name, const char *name, size_t len,
                        const char *const *folders, size_t nfolders);

/* What texture_file_add() returns when the file cannot be used. */
#define TEXTURE_FILE_FAULT (-3)

/* Returns the index of the texture read from path among the scene's
 * textures, reading it and adding it to the scene unless a texture of that
 * path is there already; or TEXTURE_FILE_FAULT with *err describing the
 * fault in the file, or what scene_add_texture() returned (-1,
 * SCENE_OVER_LIMIT). */
int texture_file_add(Scene *scene, const char *path, Error *err);

#endif
