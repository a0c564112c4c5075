/*
 * course_fields.h: the course format's reader state and what every record
 * is read with (course_fields.c): materials, lights, spheres' fields;
 * private to the course reader (course.c, course_records.c, course_bulk.c).
 */
#ifndef RAYTRACE_COURSE_FIELDS_H
#define RAYTRACE_COURSE_FIELDS_H

#include <stddef.h>

#include "scene/scene.h"
#include "scenefile/lex.h"
#include "scenefile/source.h"

/* The parser's state: a cursor over the input. */
typedef struct {
    Lexer lex;         /* the cursor over the input */
    SceneSource *source; /* where its mesh lines are kept */
    int ambient_line;  /* line of the ambient: record, 0 before it */
    int samples_line;  /* line of the samples: record, 0 before it */
    int lens_line;     /* line of the lens: record, 0 before it */
    int has_last;      /* an object has been read */
    int last_kind;     /* which shape the last object is (a ShapeKind,
                          COURSE_MESH or COURSE_MESH_OWN) */
    size_t last_index; /* its index among the scene's shapes of that kind (a
                          mesh: its first triangle's) */
} CourseParser;

/* Records a fault at column of line. */
#define course_fail(P, line, column, ...) lex_fail(&(P)->lex, line, column, __VA_ARGS__)

/* last_kind after a mesh: record: its triangles of the one material it
 * gives, or of its file's own (which a texture: record cannot change). */
#define COURSE_MESH SHAPE_KINDS
#define COURSE_MESH_OWN (SHAPE_KINDS + 1)

/* light -> x y z r g b: the header's light and a light: record's numbers. */
extern const RecordSpec course_light_spec;

/* sphere -> cx cy cz radius r g b reflection [transparency index]: a
 * sphere: record's numbers. */
extern const RecordSpec course_sphere_spec;

/* Records that rec's element could not be stored, scene_add_*() having
 * returned rc; returns -1. */
int course_fail_memory(CourseParser *P, const Record *rec, const Scene *scene, long rc);

/* Appends the light of values v (x y z r g b), the record rec, to the scene. */
int course_add_light(CourseParser *P, const Record *rec, const double *v, Scene *scene);

/* material -> r g b reflection [transparency index]: the numbers of spec
 * from values[first] on (n numbers read in all), the first number being
 * rec's token tok0, into *m; checks R + T <= 1. */
int course_material(CourseParser *P, const Record *rec, const RecordSpec *spec, int tok0,
                    int first, const double *values, int n, Material *m);

/* Remembers the object just added (a ShapeKind, or COURSE_MESH, and its
 * index), for a
 * texture: record after it. */
void course_note_object(CourseParser *P, int kind, size_t index);

/* Reads rec, a sphere: record, into *centre, *radius and *m. */
int course_sphere_fields(CourseParser *P, const Record *rec, Vec3 *centre, real *radius,
                         Material *m);

#endif
