/*
 * shapes.h: the shapes every scene format describes, made from the numbers
 * their records give, checked the same way whatever the format.
 *
 * A record gives a shape's geometry as numbers, in this order:
 *   sphere    cx cy cz radius
 *   plane     px py pz nx ny nz          (a point and a normal, any length)
 *   triangle  x0 y0 z0 x1 y1 z1 x2 y2 z2
 *   cube      cx cy cz half              (the edge is 2 half)
 *   square    cx cy cz nx ny nz half     (the edge is 2 half)
 *   cylinder  cx cy cz radius            (infinite, along y)
 *   cone      x y z radius height        (cone.h)
 * shapes_names and shapes_kinds give each number's name and kind (lex.h)
 * for the readers' messages and checks.
 */
#ifndef RAYTRACE_SHAPES_H
#define RAYTRACE_SHAPES_H

#include "scene/scene.h"
#include "scenefile/lex.h"

enum { SHAPES_NUMBERS_MAX = 9 }; /* the most numbers a shape takes */

/* What shapes_add() returns when the numbers make no shape (a zero normal,
 * three vertices on a line, a cone of height 0). */
#define SHAPES_INVALID (-3)

/* The numbers each kind takes, their names and kinds. */
extern const int shapes_count[SHAPE_KINDS];
extern const char *const *const shapes_names[SHAPE_KINDS];
extern const FieldKind *const shapes_kinds[SHAPE_KINDS];

/* The names and kinds of some shapes' numbers, for the readers' own
 * record specs (lex.h): cylinders take the sphere's, cubes the sphere's
 * kinds. */
extern const char *const shapes_sphere_names[];
extern const FieldKind shapes_sphere_kinds[];
extern const char *const shapes_cube_names[];
extern const char *const shapes_square_names[];
extern const FieldKind shapes_square_kinds[];
extern const char *const shapes_cone_names[];
extern const FieldKind shapes_cone_kinds[];

/* The name of each kind, for messages ("sphere", "cone", ...). */
extern const char *const shapes_word[SHAPE_KINDS];

/* Adds the shape of kind made from the numbers v (as above) and material m
 * to scene (a plane's texture tiles every unit); returns 0, -1 or
 * SCENE_OVER_LIMIT as scene_add_*() does, or SHAPES_INVALID with *fault
 * saying why and *field the number at fault. */
int shapes_add(Scene *scene, ShapeKind kind, const double *v, const Material *m,
               const char **fault, int *field);

/* Stores in v the numbers that make shape index of kind in scene, as its
 * record gave them (lengths divided back by 2^length_exponent, exactly;
 * normals as given); returns how many. */
int shapes_numbers(const Scene *scene, ShapeKind kind, size_t index, double *v);

#endif
