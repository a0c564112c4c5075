/*
 * course.c: the course scene format (see course.h, docs/scene-format.md):
 * its header and sphere: records here, the bonus records in
 * course_records.c, large fields of spheres in course_bulk.c.
 *
 * The input is split into lines; a '#' starts a comment, blank lines are
 * skipped, and each remaining line is one record:
 *
 *   scene      -> camera top-left top-right bottom-left resolution
 *                 background light sphere*
 *   camera     -> x y z                      (likewise the three corners)
 *   resolution -> digits                     (1..32768)
 *   background -> r g b                      (0..255 each)
 *   light      -> x y z r g b
 *   record     -> sphere | plane | triangle | light | ambient | samples
 *                 | lens | texture                 (any order, any number)
 *   sphere     -> 'sphere:' cx cy cz radius material
 *   plane      -> 'plane:' px py pz nx ny nz material
 *   triangle   -> 'triangle:' x0 y0 z0 x1 y1 z1 x2 y2 z2 material
 *   mesh       -> 'mesh:' path [material]  (an OBJ, PLY or STL file;
 *                                          without a material, its own)
 *   material   -> r g b reflection [transparency index]
 *   light      -> 'light:' x y z r g b            (a further light)
 *   ambient    -> 'ambient:' r g b                (at most once)
 *   samples    -> 'samples:' digits               (at most once)
 *   lens       -> 'lens:' aperture focus          (at most once)
 *   texture    -> 'texture:' path [filter] number* (for the object before)
 *
 * Fields are separated by spaces or tabs; a line may end in CRLF.
 */
#include "scenefile/course.h"

#include <stdio.h>
#include <string.h>

#include "course_bulk.h"
#include "course_fields.h"
#include "course_records.h"
#include "math/number.h"
#include "scene/scale.h"
#include "scenefile/shapes.h"

static const char *const course_xyz_names[] = {"x", "y", "z"};
static const FieldKind course_xyz_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD};
static const char *const course_rgb_names[] = {"red", "green", "blue"};
static const FieldKind course_rgb_kinds[] = {FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};

static const RecordSpec course_camera_spec = {"the camera position", NULL, 3, 0, 0, course_xyz_names,
                                        course_xyz_kinds};
static const RecordSpec course_top_left_spec = {"the screen's top-left corner", NULL, 3, 0, 0,
                                          course_xyz_names, course_xyz_kinds};
static const RecordSpec course_top_right_spec = {"the screen's top-right corner", NULL, 3, 0, 0,
                                           course_xyz_names, course_xyz_kinds};
static const RecordSpec course_bottom_left_spec = {"the screen's bottom-left corner", NULL, 3, 0, 0,
                                             course_xyz_names, course_xyz_kinds};
static const RecordSpec course_background_spec = {"the background colour", NULL, 3, 0, 0,
                                            course_rgb_names, course_rgb_kinds};

/* Reads the next record, which must be the header record spec, in which a
 * keyword is out of place; returns 0, or -1 with the fault recorded. */
static int course_header_record(CourseParser *P, const RecordSpec *spec, const char *syntax,
                               Record *rec)
{
    int rc = lex_next_record(&P->lex, rec);
    const Token *t = &rec->tok[0];
    char q[64];

    if (rc < 0)
        return -1;
    if (rc == 0) {
        lex_fail_eof(&P->lex, spec->what, syntax);
        return -1;
    }
    if (t->len > 0 && t->text[t->len - 1] == ':') {
        course_fail(P, &rec->line, t->column,
                   "expected %s, found the record %s: the 7 header records (camera, three "
                   "screen corners, resolution, background, light) come first",
                   spec->what, lex_quote(q, sizeof q, t));
        return -1;
    }
    return 0;
}

/* Reads a header record of spec's numbers into values. */
static int course_header_numbers(CourseParser *P, const RecordSpec *spec, Record *rec, double *values)
{
    const char *syntax = spec->syntax ? spec->syntax : spec->count == 3 ? "3 numbers" : NULL;

    if (course_header_record(P, spec, syntax, rec) != 0)
        return -1;
    return lex_numbers(&P->lex, rec, 0, spec, values) < 0 ? -1 : 0;
}

/* point -> x y z */
static int course_point(CourseParser *P, const RecordSpec *spec, Record *rec, Vec3 *out)
{
    double v[3];

    if (course_header_numbers(P, spec, rec, v) != 0)
        return -1;
    *out = vec3(v[0], v[1], v[2]);
    return 0;
}

/* resolution -> digits, 1..CAMERA_MAX_SIZE */
static int course_resolution(CourseParser *P, Record *rec, int *width)
{
    static const RecordSpec spec = {"the horizontal resolution", NULL, 1, 0, 0, NULL, NULL};

    if (course_header_record(P, &spec, "a whole number of pixels", rec) != 0)
        return -1;
    if (rec->count > 1) {
        course_fail(P, &rec->line, rec->tok[1].column,
                   "expected 1 number for the horizontal resolution, found %d", rec->count);
        return -1;
    }
    return lex_whole_number(&P->lex, rec, 0, "the horizontal resolution", "pixels",
                              CAMERA_MAX_SIZE, width);
}

/* colour -> r g b, each 0..255 */
static int course_colour(CourseParser *P, const RecordSpec *spec, Record *rec, Colour *out)
{
    double v[3];

    if (course_header_numbers(P, spec, rec, v) != 0)
        return -1;
    *out = colour(v[0], v[1], v[2]);
    return 0;
}

/* light -> x y z r g b */
static int course_light_record(CourseParser *P, Record *rec, Scene *scene)
{
    double v[6];

    if (course_header_numbers(P, &course_light_spec, rec, v) != 0)
        return -1;
    return course_add_light(P, rec, v, scene);
}

/* Checks the screen spanned by the corner records tl, tr and bl. */
static int course_check_screen(CourseParser *P, Camera *cam, Vec3 tr, Vec3 bl, const Record *tr_rec,
                              const Record *bl_rec)
{
    cam->u = vec3_sub(tr, cam->top_left);
    cam->v = vec3_sub(bl, cam->top_left);
    switch (camera_check_screen(cam->u, cam->v)) {
    case CAMERA_SCREEN_OK:
        return 0;
    case CAMERA_SCREEN_NO_WIDTH:
        course_fail(P, &tr_rec->line, tr_rec->tok[0].column,
                   "the screen's top-right corner is its top-left corner: the screen has no "
                   "width");
        return -1;
    case CAMERA_SCREEN_NO_HEIGHT:
        course_fail(P, &bl_rec->line, bl_rec->tok[0].column,
                   "the screen's bottom-left corner is its top-left corner: the screen has no "
                   "height");
        return -1;
    case CAMERA_SCREEN_PARALLEL:
        course_fail(P, &bl_rec->line, bl_rec->tok[0].column,
                   "the screen's top and left edges are parallel: its three corners lie on "
                   "one line");
        return -1;
    }
    return -1;
}

/* header -> camera top-left top-right bottom-left resolution background light */
static int course_header(CourseParser *P, Scene *scene)
{
    Camera *cam = &scene->camera;
    Record rec, tr_rec;
    Vec3 tr, bl;
    double height;

    if (course_point(P, &course_camera_spec, &rec, &cam->eye) != 0 ||
        course_point(P, &course_top_left_spec, &rec, &cam->top_left) != 0 ||
        course_point(P, &course_top_right_spec, &tr_rec, &tr) != 0 ||
        course_point(P, &course_bottom_left_spec, &rec, &bl) != 0 ||
        course_check_screen(P, cam, tr, bl, &tr_rec, &rec) != 0 ||
        course_resolution(P, &rec, &cam->width) != 0)
        return -1;
    height = camera_height(cam->u, cam->v, cam->width);
    if (height > CAMERA_MAX_SIZE) {
        course_fail(P, &rec.line, rec.tok[0].column,
                   "the image would be %d x %.0f pixels: its height, set by the screen's "
                   "proportions, must be at most %d",
                   cam->width, height, CAMERA_MAX_SIZE);
        return -1;
    }
    cam->height = (int)height;
    if (course_colour(P, &course_background_spec, &rec, &scene->background) != 0 ||
        course_light_record(P, &rec, scene) != 0)
        return -1;
    return 0;
}

/* sphere -> 'sphere:' ... (course_sphere_fields()), appended to the scene */
static int course_sphere_record(CourseParser *P, const Record *rec, Scene *scene)
{
    Vec3 centre;
    real radius;
    Material m;
    int rc;

    if (course_sphere_fields(P, rec, &centre, &radius, &m) != 0)
        return -1;
    rc = scene_add_sphere(scene, centre, radius, &m);
    if (rc != 0)
        return course_fail_memory(P, rec, scene, rc);
    course_note_object(P, SHAPE_SPHERE, scene_count_of(scene, SHAPE_SPHERE) - 1);
    return 0;
}
/* A record that may follow the header, other than a shape's (but the
 * sphere's, which the course reads its own way), and what reads it. */
typedef struct {
    const char *keyword; /* with its colon */
    int (*parse)(CourseParser *P, const Record *rec, Scene *scene);
} RecordKind;

static const RecordKind course_record_kinds[] = {
    {"sphere:", course_sphere_record},   {"light:", course_extra_light_record},
    {"ambient:", course_ambient_record}, {"samples:", course_samples_record},
    {"lens:", course_lens_record},       {"texture:", course_texture_record},
    {"mesh:", course_mesh_record},
};

enum { COURSE_RECORD_KINDS = sizeof course_record_kinds / sizeof course_record_kinds[0] };

#define COURSE_SHAPE_WORD(K, T, name, ...) "'" #name ":', "
#define COURSE_KEYWORD_LIST                                                                    \
    SHAPE_LIST(COURSE_SHAPE_WORD)                                                              \
    "'mesh:', 'light:', 'ambient:', 'samples:', 'lens:' or 'texture:'"

/* Records why t, the first token of rec, is not the record keyword kw (a
 * word and its colon) that it nearly is, and returns 1; or returns 0. */
static int course_near_keyword(CourseParser *P, const Record *rec, const char *kw)
{
    const Token *t = &rec->tok[0];
    size_t n = strlen(kw);
    char q[64], bare[16];

    lex_quote(q, sizeof q, t);
    memcpy(bare, kw, n - 1);
    bare[n - 1] = '\0';
    if (number_word_is(t->text, t->len, kw)) {
        course_fail(P, &rec->line, t->column, "unknown record %s: keywords are lower case ('%s')",
                    q, kw);
        return 1;
    }
    if (t->len == n - 1 && number_word_is(t->text, t->len, bare)) {
        course_fail(P, &rec->line, t->column, "expected '%s' with its colon attached, found %s",
                    kw, q);
        return 1;
    }
    return 0;
}

/* Records why the first token of rec is not a known record keyword. */
static void course_fail_keyword(CourseParser *P, const Record *rec)
{
    const Token *t = &rec->tok[0];
    char q[64], kw[16];
    double ignored;

    lex_quote(q, sizeof q, t);
    for (int k = 0; k < COURSE_RECORD_KINDS; k++)
        if (course_near_keyword(P, rec, course_record_kinds[k].keyword))
            return;
    for (int k = 0; k < SHAPE_KINDS; k++) {
        snprintf(kw, sizeof kw, "%s:", shape_words[k]);
        if (course_near_keyword(P, rec, kw))
            return;
    }
    if (number_parse(t->text, t->len, &ignored) != NUMBER_SYNTAX)
        course_fail(P, &rec->line, t->column,
                   "expected a record such as 'sphere:', found the number %s: the 7 header "
                   "records are complete",
                   q);
    else
        course_fail(P, &rec->line, t->column, "unknown record %s (expected " COURSE_KEYWORD_LIST
                   ")", q);
}

/* objects -> record* */
static int course_objects(CourseParser *P, Scene *scene)
{
    Record rec;
    int rc;

    if (course_spheres_parallel(P, scene))
        return 0;
    while ((rc = lex_next_record(&P->lex, &rec)) == 1) {
        int k = 0;
        ShapeKind kind;
        while (k < COURSE_RECORD_KINDS && !lex_token_is(&rec.tok[0], course_record_kinds[k].keyword))
            k++;
        if (k < COURSE_RECORD_KINDS) {
            if (course_record_kinds[k].parse(P, &rec, scene) != 0)
                return -1;
        } else if (shapes_kind_of(rec.tok[0].text, rec.tok[0].len, ":", &kind)) {
            if (course_shape_record(P, &rec, scene, kind) != 0)
                return -1;
        } else {
            course_fail_keyword(P, &rec);
            return -1;
        }
    }
    return rc;
}

int course_parse_text(const char *name, const char *text, size_t len, size_t memory_limit,
                      Scene *scene, SceneSource *source, Error *err)
{
    CourseParser P;

    scene_init(scene);
    source_init(source);
    scene->memory_limit = memory_limit;
    lex_init(&P.lex, name, text, len, err);
    P.ambient_line = P.samples_line = P.lens_line = 0;
    P.has_last = 0;
    P.last_kind = SHAPE_SPHERE;
    P.last_index = 0;
    P.source = source;
    if (course_header(&P, scene) != 0 || course_objects(&P, scene) != 0) {
        scene_free(scene);
        source_free(source);
        return -1;
    }
    scene_fit_scale(scene);
    return 0;
}

