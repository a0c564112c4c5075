/*
 * course_records.h: the course format's bonus records (course_records.c),
 * private to its reader: planes, triangles, cubes, squares, cylinders,
 * cones, meshes, textures, further lights, the ambient light, samples and
 * the lens.
 */
#ifndef RAYTRACE_COURSE_RECORDS_H
#define RAYTRACE_COURSE_RECORDS_H

#include "course_fields.h"

/* Reads rec, the record of a shape of kind (not a sphere):
 *   shape -> 'KIND:' geometry r g b reflection [transparency index]
 * with the geometry scenefile/shapes.h names (plane: px py pz nx ny nz;
 * triangle: three corners; cube: cx cy cz half-edge; square: cx cy cz nx
 * ny nz half-edge; cylinder: x y z radius; cone: x y z radius height);
 * returns 0, or -1 with the fault recorded. */
int course_shape_record(CourseParser *P, const Record *rec, Scene *scene, ShapeKind kind);

/* Each reads rec, a record of its kind, into the scene;
 * 0, or -1 with the fault recorded. */
int course_mesh_record(CourseParser *P, const Record *rec, Scene *scene);
int course_texture_record(CourseParser *P, const Record *rec, Scene *scene);
int course_extra_light_record(CourseParser *P, const Record *rec, Scene *scene);
int course_ambient_record(CourseParser *P, const Record *rec, Scene *scene);
int course_samples_record(CourseParser *P, const Record *rec, Scene *scene);
int course_lens_record(CourseParser *P, const Record *rec, Scene *scene);

#endif
