/*
 * course_records.h: the course format's bonus records (course_records.c),
 * private to its reader: planes, triangles, cubes, squares, cylinders,
 * cones, meshes, textures, further lights, the ambient light, samples and
 * the lens.
 */
#ifndef RAYTRACE_COURSE_RECORDS_H
#define RAYTRACE_COURSE_RECORDS_H

#include "course_fields.h"

/* Each reads rec, a record of its kind, into the scene;
 * 0, or -1 with the fault recorded. */
int course_plane_record(CourseParser *P, const Record *rec, Scene *scene);
int course_triangle_record(CourseParser *P, const Record *rec, Scene *scene);
int course_cube_record(CourseParser *P, const Record *rec, Scene *scene);
int course_square_record(CourseParser *P, const Record *rec, Scene *scene);
int course_cylinder_record(CourseParser *P, const Record *rec, Scene *scene);
int course_cone_record(CourseParser *P, const Record *rec, Scene *scene);
int course_mesh_record(CourseParser *P, const Record *rec, Scene *scene);
int course_texture_record(CourseParser *P, const Record *rec, Scene *scene);
int course_extra_light_record(CourseParser *P, const Record *rec, Scene *scene);
int course_ambient_record(CourseParser *P, const Record *rec, Scene *scene);
int course_samples_record(CourseParser *P, const Record *rec, Scene *scene);
int course_lens_record(CourseParser *P, const Record *rec, Scene *scene);

#endif
