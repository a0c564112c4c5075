/*
 * mpl.h: reading the MPL ray tracer's scene format, the MPL format, into a Scene.
 *
 * One element per line, its kind the line's first letter: `m` a material,
 * `p` a primitive, `l` a light, and our `c` settings (camera, background,
 * sky, ambient light, samples); numbers may be written as C float
 * literals (`1.f`, `0.5f`) and followed by stray commas
 * (docs/scene-format.md, "The MPL format"). Like course.h, the reader never
 * prints: a fault fills an Error with the file, line and column and a
 * message saying what was expected and what was found.
 */
#ifndef RAYTRACE_MPL_H
#define RAYTRACE_MPL_H

#include <stddef.h>

#include "base/error.h"
#include "scene/scene.h"
#include "scenefile/source.h"

/* The defaults of a scene without a camera line: the MPL ray tracer's camera and
 * image size, and of one without c Samples: its program's samples. */
#define MPL_DEFAULT_FOV 90.0 /* vertical field of view, degrees */
enum { MPL_DEFAULT_SIZE = 500 };  /* width and height, pixels */
enum { MPL_DEFAULT_SAMPLES = 4 }; /* samples per pixel */

/* Reads the len bytes at text (NUL bytes included), named `name` in errors
 * and for relative texture paths, into *scene, which this call initialises
 * with memory_limit (scene.h), and what --save writes back into *source,
 * which it initialises too; returns 0, or -1 with *err filled and both
 * empty. Lines the MPL ray tracer read, though they break the
 * format, are read as it read them, each with a warning in the scene's
 * list (a number up to its first letter, words after a primitive's
 * material and numbers after a light's ignored, an unknown material read
 * as the first, a second material of a name ignored), unless strict:
 * then they are errors. */
int mpl_parse_text(const char *name, const char *text, size_t len, size_t memory_limit, int strict,
                   Scene *scene, SceneSource *source, Error *err);

#endif
