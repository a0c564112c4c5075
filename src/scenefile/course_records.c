/* course_records.c: the course format's bonus records (see course_records.h,
 * docs/scene-format.md). */
#include "course_records.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "math/number.h"
#include "scenefile/mesh.h"
#include "scenefile/obj.h"
#include "scenefile/shapes.h"
#include "scenefile/texture_file.h"

static const char *const course_material_names[] = {"red",        "green",        "blue",
                                                     "reflection", "transparency", "refractive index"};
static const FieldKind course_material_kinds[] = {FIELD_COLOUR,   FIELD_COLOUR,   FIELD_COLOUR,
                                                  FIELD_FRACTION, FIELD_FRACTION, FIELD_POSITIVE};
static const char *const course_rgb_names[] = {"red", "green", "blue"};
static const FieldKind course_rgb_kinds[] = {FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};
static const char *const course_lens_names[] = {"aperture", "focal distance"};
static const FieldKind course_lens_kinds[] = {FIELD_NONNEGATIVE, FIELD_POSITIVE};
static const char *const course_tile_names[] = {"tile size"};
static const FieldKind course_tile_kinds[] = {FIELD_POSITIVE};
static const char *const course_uv_names[] = {"u0", "v0", "u1", "v1", "u2", "v2"};
static const FieldKind course_uv_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                           FIELD_COORD, FIELD_COORD, FIELD_COORD};
static const RecordSpec course_ambient_spec = {"the ambient light", "r g b", 3, 0, 0, course_rgb_names,
                                         course_rgb_kinds};
static const RecordSpec course_lens_spec = {"the lens", "aperture focal_distance", 2, 0, 0,
                                      course_lens_names, course_lens_kinds};
static const RecordSpec course_plane_texture_spec = {"the plane's texture", "path [filter] [tile_size]",
                                               0, 1, 0, course_tile_names, course_tile_kinds};
static const RecordSpec course_mesh_spec = {"the mesh", "path [r g b reflection [transparency index]]",
                                      4, 2, 0, course_material_names, course_material_kinds};
static const RecordSpec course_mesh_texture_spec = {"the mesh's texture", "path [filter]", 0, 0, 0, NULL,
                                              NULL};
static const RecordSpec course_triangle_texture_spec = {"the triangle's texture",
                                                  "path [filter] [u0 v0 u1 v1 u2 v2]", 0, 6, 0,
                                                  course_uv_names, course_uv_kinds};

/* Returns the kind of the last object read (there must be one): a mesh's
 * triangles share their material. */
static ShapeKind course_last_kind(const CourseParser *P)
{
    return P->last_kind >= COURSE_MESH ? SHAPE_TRIANGLE : (ShapeKind)P->last_kind;
}

int course_shape_record(CourseParser *P, const Record *rec, Scene *scene, ShapeKind kind)
{
    ShapesSpec shape;
    const RecordSpec *spec = &shape.spec;
    double v[SHAPE_NUMBERS_MAX + SHAPES_MORE_MAX];
    int n, rc, field = 0;
    const char *fault = NULL;
    Material m;

    shapes_spec(&shape, kind, "r g b reflection [transparency index]", 6, 2,
                course_material_names, course_material_kinds);
    n = lex_numbers(&P->lex, rec, 1, spec, v);
    if (n < 0 || course_material(P, rec, spec, 1, shape_records[kind]->count, v, n, &m) != 0)
        return -1;
    rc = shapes_add(scene, kind, v, &m, &fault, &field);
    if (rc == SHAPES_INVALID) {
        course_fail(P, &rec->line, rec->tok[field < 0 ? 0 : 1 + field].column, "%s", fault);
        return -1;
    }
    if (rc != 0)
        return course_fail_memory(P, rec, scene, rc);
    course_note_object(P, kind, scene_count_of(scene, kind) - 1);
    return 0;
}

/* light -> 'light:' x y z r g b */
int course_extra_light_record(CourseParser *P, const Record *rec, Scene *scene)
{
    double v[6];

    if (lex_numbers(&P->lex, rec, 1, &course_light_spec, v) < 0)
        return -1;
    return course_add_light(P, rec, v, scene);
}

/* ambient -> 'ambient:' r g b */
int course_ambient_record(CourseParser *P, const Record *rec, Scene *scene)
{
    double v[3];

    if (lex_once(&P->lex, rec, &P->ambient_line, "the ambient light") != 0 ||
        lex_numbers(&P->lex, rec, 1, &course_ambient_spec, v) < 0)
        return -1;
    scene->ambient = colour(v[0], v[1], v[2]);
    scene->has_ambient = 1;
    return 0;
}

/* samples -> 'samples:' digits, 1..CAMERA_MAX_SAMPLES */
int course_samples_record(CourseParser *P, const Record *rec, Scene *scene)
{
    if (lex_once(&P->lex, rec, &P->samples_line, "the number of samples per pixel") != 0)
        return -1;
    if (rec->count != 2) {
        course_fail(P, &rec->line, rec->count < 2 ? rec->end_column : rec->tok[2].column,
                   "expected 1 number for the samples per pixel, found %d", rec->count - 1);
        return -1;
    }
    return lex_whole_number(&P->lex, rec, 1, "the number of samples per pixel", "samples",
                              CAMERA_MAX_SAMPLES, &scene->samples);
}

/* lens -> 'lens:' aperture focal_distance */
int course_lens_record(CourseParser *P, const Record *rec, Scene *scene)
{
    double v[2];

    if (lex_once(&P->lex, rec, &P->lens_line, "the lens") != 0 ||
        lex_numbers(&P->lex, rec, 1, &course_lens_spec, v) < 0)
        return -1;
    if (v[0] > 0 && camera_set_lens(&scene->camera, v[0], v[1]) != 0) {
        course_fail(P, &rec->line, rec->tok[0].column,
                   "the camera lies in the plane of its screen: a lens needs the screen in "
                   "front of the camera");
        return -1;
    }
    return 0;
}

/* Loads the texture file named by token t (relative to the scene file's
 * directory) into the scene, or finds it there already; returns its index,
 * or -1 with the fault recorded at t. */
static int course_load_texture(CourseParser *P, const Record *rec, const Token *t, Scene *scene)
{
    char *path = lex_path(&P->lex, t);
    Error inner;
    int index;

    if (!path)
        return -1;
    index = texture_file_add(scene, path, &inner);
    free(path);
    if (index == TEXTURE_FILE_FAULT)
        lex_fail_file(&P->lex, rec, t, "texture", &inner);
    else if (index < 0)
        course_fail_memory(P, rec, scene, index);
    return index < 0 ? -1 : index;
}

/* mesh -> 'mesh:' path [r g b reflection [transparency index]]: without
 * a material, the mesh file's own */
int course_mesh_record(CourseParser *P, const Record *rec, Scene *scene)
{
    double v[6];
    Material mat;
    char q[64];
    long added;
    int n, own = rec->count == 2;

    if (rec->count < 2) {
        course_fail(P, &rec->line, rec->end_column,
                   "expected the path of an OBJ file for the mesh (%s), found the end of the "
                   "line",
                   course_mesh_spec.syntax);
        return -1;
    }
    if (!own && ((n = lex_numbers(&P->lex, rec, 2, &course_mesh_spec, v)) < 0 ||
                 course_material(P, rec, &course_mesh_spec, 2, 0, v, n, &mat) != 0))
        return -1;
    added = mesh_load(&P->lex, rec, &rec->tok[1], own ? NULL : &mat, scene, P->source);
    if (added == MESH_FAULT)
        return -1;
    if (added < 0)
        return course_fail_memory(P, rec, scene, (int)added);
    if (added == 0) {
        course_fail(P, &rec->line, rec->tok[1].column,
                   "the mesh %s has no faces with an area: nothing to draw",
                   lex_quote(q, sizeof q, &rec->tok[1]));
        return -1;
    }
    course_note_object(P, own ? COURSE_MESH_OWN : COURSE_MESH,
                       scene_count_of(scene, SHAPE_TRIANGLE) - (size_t)added);
    return 0;
}

/* texture -> 'texture:' path [nearest | bilinear] number*, for the object
 * just before: [tile_size] for a plane, [u0 v0 u1 v1 u2 v2] for a
 * triangle, none for the others. */
int course_texture_record(CourseParser *P, const Record *rec, Scene *scene)
{
    RecordSpec any = {NULL, "path [filter]", 0, 0, 0, NULL, NULL};
    char what[48];
    const RecordSpec *spec;
    int first = 2, n, index, rc = 0;
    double v[6];
    TextureFilter filter = TEXTURE_BILINEAR;
    Material *m;

    if (!P->has_last) {
        course_fail(P, &rec->line, rec->tok[0].column,
                   "a texture: record must follow the object it covers, and no object comes "
                   "before it");
        return -1;
    }
    if (P->last_kind == COURSE_MESH_OWN) {
        course_fail(P, &rec->line, rec->tok[0].column,
                    "the mesh before is drawn in its file's own materials, whose textures its "
                    "MTL file names (map_Kd): a texture: record may follow a mesh: record that "
                    "gives a material");
        return -1;
    }
    if (P->last_kind == COURSE_MESH) {
        spec = &course_mesh_texture_spec;
    } else if (P->last_kind == SHAPE_PLANE) {
        spec = &course_plane_texture_spec;
    } else if (P->last_kind == SHAPE_TRIANGLE) {
        spec = &course_triangle_texture_spec;
    } else {
        snprintf(what, sizeof what, "the %s's texture", shape_words[P->last_kind]);
        any.what = what;
        spec = &any;
    }
    if (scene_material(scene, course_last_kind(P), P->last_index).texture >= 0) {
        course_fail(P, &rec->line, rec->tok[0].column,
                   "%s is already set: an object takes one texture: record", spec->what);
        return -1;
    }
    if (rec->count < 2) {
        course_fail(P, &rec->line, rec->end_column,
                   "expected the path of a PPM file for %s (%s), found the end of the line",
                   spec->what, spec->syntax);
        return -1;
    }
    if (rec->count > 2 && lex_filter_word(&rec->tok[2], &filter)) {
        first = 3;
    } else if (rec->count > 2 &&
               number_parse(rec->tok[2].text, rec->tok[2].len, &v[0]) == NUMBER_SYNTAX) {
        char q[64];
        course_fail(P, &rec->line, rec->tok[2].column,
                   "unknown texture filter %s (expected 'nearest', 'bilinear', 'trilinear' or "
                   "'ewa')",
                   lex_quote(q, sizeof q, &rec->tok[2]));
        return -1;
    }
    if (spec->optional == 0 && rec->count > first)
        return lex_fail_extra(&P->lex, rec, first, spec->what);
    n = lex_numbers(&P->lex, rec, first, spec, v);
    if (n < 0)
        return -1;
    index = course_load_texture(P, rec, &rec->tok[1], scene);
    if (index < 0)
        return -1;
    m = scene_material_edit(scene, course_last_kind(P), P->last_index, &rc);
    if (!m)
        return course_fail_memory(P, rec, scene, rc);
    m->texture = index;
    m->filter = filter;
    if (P->last_kind == SHAPE_PLANE && n == 1)
        scene_planes(scene)[P->last_index].tile = v[0];
    if (P->last_kind == SHAPE_TRIANGLE && n == 6) {
        TriangleShading sh = triangle_plain_shading(&scene_triangles(scene)[P->last_index]);
        int rc;
        for (int k = 0; k < 3; k++) {
            sh.uv[k][0] = v[2 * k];
            sh.uv[k][1] = v[2 * k + 1];
        }
        rc = scene_shade_triangle(scene, P->last_index, &sh);
        if (rc != 0)
            return course_fail_memory(P, rec, scene, rc);
    }
    return 0;
}

