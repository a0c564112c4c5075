/*
 * load.h: reading a scene file in any of the three formats: the course's
 * (course.h), the keyword format of the OCaml course project (keyword.h) or the MPL ray tracer's MPL
 * format (mpl.h), told apart by content unless the caller names one.
 *
 * The rule: the first token of the first line that is neither blank nor a
 * comment (after a UTF-8 byte order mark) decides. A course scene opens with
 * the camera's coordinates, a number; a keyword scene with a keyword; an
 * MPL scene with one of its line letters. So a token that is one of the
 * letters m, p, l or c means the MPL format (no keyword is one letter); one
 * that starts with another ASCII letter and is not a number word ("nan",
 * "inf") means the keyword format; anything else the course format, whose
 * parser then explains what it expected. A file without any such token
 * is refused as an empty scene.
 */
#ifndef RAYTRACE_LOAD_H
#define RAYTRACE_LOAD_H

#include <stddef.h>

#include "base/error.h"
#include "scene/scene.h"
#include "scenefile/source.h"

/* Returns the format of the len bytes at text by the rule above, or
 * SCENE_AUTO when they hold no element (an empty scene, which
 * load_scene_text() refuses as such). */
SceneFormat load_detect(const char *text, size_t len);

/* Reads the scene file at path ("-": standard input) in the given format
 * (SCENE_AUTO: detected) into *scene, which this call initialises with
 * memory_limit (bytes, 0 for none: scene.h), and, unless source is NULL,
 * what --save writes back into *source (source.h), initialised too;
 * strict: lines of the MPL ray tracer's format its program read leniently are
 * errors, not warnings in the scene's list (mpl.h). Returns 0, or -1 with
 * *err filled and both empty. */
int load_scene_file(const char *path, SceneFormat format, size_t memory_limit, int strict,
                    Scene *scene, SceneSource *source, Error *err);

/* Same as load_scene_file() for the len bytes at text, named `name`. */
int load_scene_text(const char *name, const char *text, size_t len, SceneFormat format,
                    size_t memory_limit, int strict, Scene *scene, SceneSource *source,
                    Error *err);

#endif
