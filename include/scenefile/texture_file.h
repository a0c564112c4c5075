/*
 * texture_file.h: reading a texture (scene/texture.h) from an image file.
 *
 * Read: PPM (P6 or P3, any maxval).
 */
#ifndef RAYTRACE_TEXTURE_FILE_H
#define RAYTRACE_TEXTURE_FILE_H

#include "base/error.h"
#include "scene/texture.h"

/* Reads the image file at path into *tex, keeping a copy of path; returns
 * 0, or -1 with *err describing the fault in the file (*tex then owns
 * nothing). */
int texture_file_load(Texture *tex, const char *path, Error *err);

#endif
