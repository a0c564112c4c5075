/*
 * shapes.h: the shapes every scene format describes, made from the numbers
 * their records give, checked the same way whatever the format.
 *
 * A kind's record (its word, shape_list.h, then its numbers, shape.h, then
 * the format's material) is read by each format with the spec
 * shapes_spec() makes of the kind's record and the format's material.
 */
#ifndef RAYTRACE_SHAPES_H
#define RAYTRACE_SHAPES_H

#include "scene/scene.h"
#include "scenefile/lex.h"

/* What shapes_add() returns when the numbers make no shape (a zero normal,
 * three vertices on a line, a cone of height 0). */
#define SHAPES_INVALID (-3)

enum { SHAPES_MORE_MAX = 6 }; /* the most numbers a format adds (a material) */

/* The spec of a kind's record in one format, and what it points to. */
typedef struct {
    RecordSpec spec;
    char what[40];    /* "the cone" */
    char syntax[160]; /* "x y z radius height r g b reflection ..." */
    const char *names[SHAPE_NUMBERS_MAX + SHAPES_MORE_MAX];
    FieldKind kinds[SHAPE_NUMBERS_MAX + SHAPES_MORE_MAX];
} ShapesSpec;

/* Makes *s the spec of a record of kind: the kind's numbers, then `more`
 * (at most SHAPES_MORE_MAX) of the format's own, of names and kinds, the
 * last `optional` of which may be left out together; tail ends the syntax
 * ("r g b reflection [transparency index]", "material"). */
void shapes_spec(ShapesSpec *s, ShapeKind kind, const char *tail, int more, int optional,
                 const char *const *names, const FieldKind *kinds);

/* Finds the kind whose word is the len bytes at text less suffix (":" in
 * the course format, "" in the keyword format); returns 1 with *kind, or
 * 0. */
int shapes_kind_of(const char *text, size_t len, const char *suffix, ShapeKind *kind);

/* Adds the shape of kind made from the numbers v (its record's) and
 * material m to scene; returns 0, -1 or SCENE_OVER_LIMIT as scene_add_*()
 * does, or SHAPES_INVALID with *fault saying why and *field the number at
 * fault (-1: the whole record). */
int shapes_add(Scene *scene, ShapeKind kind, const double *v, const Material *m,
               const char **fault, int *field);

/* Stores in v the numbers that make shape index of kind in scene, as its
 * record gave them (lengths divided back by 2^length_exponent, exactly;
 * normals as given); returns how many. */
int shapes_numbers(const Scene *scene, ShapeKind kind, size_t index, double *v);

#endif
