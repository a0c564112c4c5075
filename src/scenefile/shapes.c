/* shapes.c: shapes from their records' numbers (see shapes.h). */
#include "scenefile/shapes.h"

#include <stdio.h>
#include <string.h>

void shapes_spec(ShapesSpec *s, ShapeKind kind, const char *tail, int more, int optional,
                 const char *const *names, const FieldKind *kinds)
{
    const ShapeRecord *r = shape_records[kind];

    for (int i = 0; i < r->count; i++) {
        s->names[i] = r->names[i];
        s->kinds[i] = r->kinds[i] == SHAPE_LENGTH ? FIELD_POSITIVE : FIELD_COORD;
    }
    for (int i = 0; i < more; i++) {
        s->names[r->count + i] = names[i];
        s->kinds[r->count + i] = kinds[i];
    }
    snprintf(s->what, sizeof s->what, "the %s", shape_words[kind]);
    snprintf(s->syntax, sizeof s->syntax, "%s %s", r->syntax, tail);
    s->spec.what = s->what;
    s->spec.syntax = s->syntax;
    s->spec.count = r->count + more - optional;
    s->spec.optional = optional;
    s->spec.partial = 0;
    s->spec.names = s->names;
    s->spec.kinds = s->kinds;
}

int shapes_kind_of(const char *text, size_t len, const char *suffix, ShapeKind *kind)
{
    size_t tail = strlen(suffix);

    if (len < tail || memcmp(text + len - tail, suffix, tail) != 0)
        return 0;
    for (int k = 0; k < SHAPE_KINDS; k++)
        if (strlen(shape_words[k]) == len - tail && memcmp(shape_words[k], text, len - tail) == 0) {
            *kind = (ShapeKind)k;
            return 1;
        }
    return 0;
}

int shapes_numbers(const Scene *scene, ShapeKind kind, size_t i, double *v)
{
    const ShapeRecord *r = shape_records[kind];

    r->numbers((const char *)scene_items(scene, kind) + i * shape_size(kind),
               scene->length_exponent, v);
    return r->count;
}

int shapes_add(Scene *scene, ShapeKind kind, const double *v, const Material *m,
               const char **fault, int *field)
{
    ShapeAny shape;

    memset(&shape, 0, sizeof shape);
    *fault = shape_records[kind]->make(&shape, v, m, field);
    if (*fault)
        return SHAPES_INVALID;
    return scene_add_any(scene, kind, &shape, m);
}
