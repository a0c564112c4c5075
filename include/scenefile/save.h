/*
 * save.h: writing a scene back in the format it was read from: the OCaml course project's
 * keyword format (its Q.1.3) or the MPL ray tracer's MPL format.
 *
 * The file has the camera and the settings the scene set (background or
 * sky, ambient light, samples), every material (in definition order,
 * unused ones too), every light, then every object in the scene's order
 * (which decides exact ties), a keyword mesh as its mesh line. Every number
 * is written with the fewest digits that read back as the same double (at
 * most 17; the MPL format's 0-to-1 colours are the ones whose 255-fold is
 * the scene's), so loading the saved file gives the same scene, bit for
 * bit, and the same picture. Comments and spacing are not kept.
 */
#ifndef RAYTRACE_SAVE_H
#define RAYTRACE_SAVE_H

#include <stdio.h>

#include "base/error.h"
#include "scene/scene.h"
#include "scenefile/source.h"

/* Writes scene, read with source (its mesh and camera lines) from the file
 * named scene_name, to fp as the file
 * named out_name ("-": standard output; mesh paths are written so that they
 * resolve from its directory), in its own format; returns 0, or -1 with
 * *err filled: a course scene, whose screen corners and shading rule
 * neither other format expresses, or a write error. */
int save_scene(FILE *fp, const Scene *scene, const SceneSource *source, const char *scene_name,
               const char *out_name, Error *err);

#endif
