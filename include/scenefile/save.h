/*
 * save.h: writing a scene back in seed 002's keyword format (its Q.1.3).
 *
 * The file has the camera, the background and ambient lines when the scene
 * set them, every material (in definition order, unused ones too), every
 * light, then every object in the scene's order (which decides exact ties),
 * a mesh as its mesh line. Every number is written with the fewest digits
 * that read back as the same double (at most 17), so loading the saved
 * file gives the same scene, bit for bit, and the same picture.
 */
#ifndef RAYTRACE_SAVE_H
#define RAYTRACE_SAVE_H

#include <stdio.h>

#include "base/error.h"
#include "scene/scene.h"

/* Writes scene, read from the file named scene_name, to fp as the file
 * named out_name ("-": standard output; mesh paths are written so that they
 * resolve from its directory); returns 0, or -1 with *err filled: a course
 * scene, which the keyword format cannot express, or a write error. */
int save_keyword(FILE *fp, const Scene *scene, const char *scene_name, const char *out_name,
                 Error *err);

#endif
