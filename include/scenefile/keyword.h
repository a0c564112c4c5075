/*
 * keyword.h: reading the OCaml course project's keyword scene format into a Scene.
 *
 * One element per line, each starting with its keyword: camera, material,
 * sphere, plane, triangle, mesh, light, and our ambient and background
 * (docs/scene-format.md, "The keyword format"). Like course.h, the reader
 * never prints: a fault fills an Error with the file, line and column and
 * a message saying what was expected and what was found.
 */
#ifndef RAYTRACE_KEYWORD_H
#define RAYTRACE_KEYWORD_H

#include <stddef.h>

#include "base/error.h"
#include "scene/scene.h"
#include "scenefile/source.h"

/* Reads the len bytes at text (NUL bytes included), named `name` in errors
 * and for relative mesh paths, into *scene, which this call initialises
 * with memory_limit (scene.h), and what --save writes back into *source,
 * which it initialises too; returns 0, or -1 with *err filled and both
 * empty. */
int keyword_parse_text(const char *name, const char *text, size_t len, size_t memory_limit,
                       Scene *scene, SceneSource *source, Error *err);

#endif
