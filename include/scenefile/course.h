/*
 * course.h: reading the course's scene format into a Scene.
 *
 * The format is described in docs/scene-format.md. The parser never prints
 * and never exits: on a fault it fills an Error with the file, line and
 * column of the fault and a message saying what was expected and what was
 * found, and returns -1. Numbers are read in the C locale's format whatever
 * the program's locale (raytrace never calls setlocale()).
 */
#ifndef RAYTRACE_COURSE_H
#define RAYTRACE_COURSE_H

#include <stddef.h>

#include "base/error.h"
#include "scene/scene.h"
#include "scenefile/source.h"

/* Reads the len bytes at text (NUL bytes included), named `name` in errors
 * and for relative texture and mesh paths, into *scene, which this call
 * initialises with memory_limit (scene.h), ready to render (a tiny scene is
 * enlarged exactly by scene_fit_scale()), and its mesh lines into *source,
 * which it initialises too; returns 0, or -1 with *err filled and both
 * empty. load.h reads files, in either format. */
int course_parse_text(const char *name, const char *text, size_t len, size_t memory_limit,
                      Scene *scene, SceneSource *source, Error *err);

#endif
