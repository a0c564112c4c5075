/*
 * course_bulk.h: large fields of sphere: records read on every thread
 * (course_bulk.c), private to the course reader.
 */
#ifndef RAYTRACE_COURSE_BULK_H
#define RAYTRACE_COURSE_BULK_H

#include "course_fields.h"

/* Reads the rest of the input on every thread when it is large and holds
 * sphere: records alone (the benchmark's fields), into the same scene as
 * the serial reading; returns 1 when it did, 0 when the
 * serial reading must (then also when something is wrong: it says what,
 * as it would have). */
int course_spheres_parallel(CourseParser *P, Scene *scene);

#endif
