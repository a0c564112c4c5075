/* course_fields.c: what every record of the course format is read with
 * (see course_fields.h). */
#include "course_fields.h"

static const char *const course_light_names[] = {"x", "y", "z", "red", "green", "blue"};
static const FieldKind course_light_kinds[] = {FIELD_COORD,  FIELD_COORD,  FIELD_COORD,
                                              FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};
static const char *const course_sphere_names[] = {
    "centre x", "centre y", "centre z",   "radius",          "red",
    "green",    "blue",     "reflection", "transparency", "refractive index"};
static const FieldKind course_sphere_kinds[] = {
    FIELD_COORD,  FIELD_COORD,  FIELD_COORD,    FIELD_POSITIVE, FIELD_COLOUR,
    FIELD_COLOUR, FIELD_COLOUR, FIELD_FRACTION, FIELD_FRACTION, FIELD_POSITIVE};

const RecordSpec course_light_spec = {"the light", "x y z r g b", 6, 0, 0, course_light_names,
                                       course_light_kinds};
const RecordSpec course_sphere_spec = {"the sphere",
                                        "cx cy cz radius r g b reflection"
                                        " [transparency index]",
                                        8, 2, 0, course_sphere_names, course_sphere_kinds};

/* Records that rec's element could not be stored, scene_add_*() having
 * returned rc; returns -1. */
int course_fail_memory(CourseParser *P, const Record *rec, const Scene *scene, long rc)
{
    return lex_fail_memory(&P->lex, rec, rc == SCENE_OVER_LIMIT, scene->memory_limit);
}

/* Appends the light of values v (x y z r g b), the record rec, to the scene. */
int course_add_light(CourseParser *P, const Record *rec, const double *v, Scene *scene)
{
    Light light = light_point(vec3(v[0], v[1], v[2]), colour(v[3], v[4], v[5]));
    int rc = scene_add_light(scene, &light);

    return rc != 0 ? course_fail_memory(P, rec, scene, rc) : 0;
}

/* material -> r g b reflection [transparency index]: the numbers of spec
 * from values[first] on, read by course_expect_numbers() (n of them in all)
 * from rec's tokens, the first number being token tok0; checks R + T <= 1. */
int course_material(CourseParser *P, const Record *rec, const RecordSpec *spec, int tok0,
                          int first, const double *values, int n, Material *m)
{
    const double *v = values + first;

    *m = material_plain(colour(v[0], v[1], v[2]), v[3]);
    if (n == spec->count + spec->optional) {
        /* A little slack, so that 0.1 + 0.9 passes whatever the rounding. */
        if (v[3] + v[4] > 1 + 1e-12) {
            const Token *t = &rec->tok[tok0 + first + 4];
            course_fail(P, &rec->line, t->column,
                       "%s's reflection plus transparency must be at most 1, found %g + %g",
                       spec->what, v[3], v[4]);
            return -1;
        }
        m->transparency = v[4];
        m->ior = v[5];
    }
    return 0;
}

/* Remembers the object just added, for a texture: record after it. */
void course_note_object(CourseParser *P, int kind, size_t index)
{
    P->has_last = 1;
    P->last_kind = kind;
    P->last_index = index;
}

/* sphere -> 'sphere:' cx cy cz radius r g b reflection [transparency index]:
 * reads rec, a sphere: record, into *centre, *radius and *m. */
int course_sphere_fields(CourseParser *P, const Record *rec, Vec3 *centre, real *radius,
                         Material *m)
{
    double v[10];
    int n = lex_numbers(&P->lex, rec, 1, &course_sphere_spec, v);

    if (n < 0 || course_material(P, rec, &course_sphere_spec, 1, 4, v, n, m) != 0)
        return -1;
    *centre = vec3(v[0], v[1], v[2]);
    *radius = v[3];
    return 0;
}

