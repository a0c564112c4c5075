/*
 * parse.c: the course scene format (see parse.h, docs/scene-format.md).
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
 *   mesh       -> 'mesh:' path material           (a Wavefront OBJ file)
 *   material   -> r g b reflection [transparency index]
 *   light      -> 'light:' x y z r g b            (a further light)
 *   ambient    -> 'ambient:' r g b                (at most once)
 *   samples    -> 'samples:' digits               (at most once)
 *   lens       -> 'lens:' aperture focus          (at most once)
 *   texture    -> 'texture:' path [filter] number* (for the object before)
 *
 * Fields are separated by spaces or tabs; a line may end in CRLF.
 */
#include "scenefile/parse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenefile/lex.h"
#include "math/number.h"
#include "scenefile/mesh.h"
#include "scenefile/obj.h"
#include "scene/scale.h"
#include "scenefile/texture_file.h"
#include "base/threads.h"

/* The parser's state: a cursor over the input. */
typedef struct {
    Lexer lex;         /* the cursor over the input */
    int ambient_line;  /* line of the ambient: record, 0 before it */
    int samples_line;  /* line of the samples: record, 0 before it */
    int lens_line;     /* line of the lens: record, 0 before it */
    int has_last;      /* an object has been read */
    int last_kind;     /* which shape the last object is (a PARSE_SHAPE_*) */
    size_t last_index; /* its index among the scene's shapes of that kind (a
                          mesh: its first triangle's) */
} Parser;

/* Records a fault at column of line. */
#define parse_fail(P, line, column, ...) lex_fail(&(P)->lex, line, column, __VA_ARGS__)

/* The shapes a texture: record may follow. */
enum { PARSE_SHAPE_SPHERE, PARSE_SHAPE_PLANE, PARSE_SHAPE_TRIANGLE, PARSE_SHAPE_MESH };

static const char *const parse_xyz_names[] = {"x", "y", "z"};
static const FieldKind parse_xyz_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD};
static const char *const parse_rgb_names[] = {"red", "green", "blue"};
static const FieldKind parse_rgb_kinds[] = {FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};
static const char *const parse_light_names[] = {"x", "y", "z", "red", "green", "blue"};
static const FieldKind parse_light_kinds[] = {FIELD_COORD,  FIELD_COORD,  FIELD_COORD,
                                              FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};
static const char *const parse_sphere_names[] = {
    "centre x", "centre y", "centre z",   "radius",          "red",
    "green",    "blue",     "reflection", "transparency", "refractive index"};
static const FieldKind parse_sphere_kinds[] = {
    FIELD_COORD,  FIELD_COORD,  FIELD_COORD,    FIELD_POSITIVE, FIELD_COLOUR,
    FIELD_COLOUR, FIELD_COLOUR, FIELD_FRACTION, FIELD_FRACTION, FIELD_POSITIVE};
static const char *const parse_plane_names[] = {
    "point x", "point y", "point z", "normal x",   "normal y",     "normal z",
    "red",     "green",   "blue",    "reflection", "transparency", "refractive index"};
static const FieldKind parse_plane_kinds[] = {
    FIELD_COORD,  FIELD_COORD,  FIELD_COORD,  FIELD_COORD,    FIELD_COORD,    FIELD_COORD,
    FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR, FIELD_FRACTION, FIELD_FRACTION, FIELD_POSITIVE};
static const char *const parse_triangle_names[] = {
    "x0",  "y0",    "z0",   "x1",         "y1",           "z1",
    "x2",  "y2",    "z2",   "red",        "green",        "blue",
    "reflection", "transparency", "refractive index"};
static const FieldKind parse_triangle_kinds[] = {
    FIELD_COORD,  FIELD_COORD,  FIELD_COORD,    FIELD_COORD,    FIELD_COORD,
    FIELD_COORD,  FIELD_COORD,  FIELD_COORD,    FIELD_COORD,    FIELD_COLOUR,
    FIELD_COLOUR, FIELD_COLOUR, FIELD_FRACTION, FIELD_FRACTION, FIELD_POSITIVE};
static const char *const parse_lens_names[] = {"aperture", "focal distance"};
static const FieldKind parse_lens_kinds[] = {FIELD_NONNEGATIVE, FIELD_POSITIVE};
static const char *const parse_tile_names[] = {"tile size"};
static const FieldKind parse_tile_kinds[] = {FIELD_POSITIVE};
static const char *const parse_uv_names[] = {"u0", "v0", "u1", "v1", "u2", "v2"};
static const FieldKind parse_uv_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                           FIELD_COORD, FIELD_COORD, FIELD_COORD};

static const RecordSpec parse_camera = {"the camera position", NULL, 3, 0, 0, parse_xyz_names,
                                        parse_xyz_kinds};
static const RecordSpec parse_top_left = {"the screen's top-left corner", NULL, 3, 0, 0,
                                          parse_xyz_names, parse_xyz_kinds};
static const RecordSpec parse_top_right = {"the screen's top-right corner", NULL, 3, 0, 0,
                                           parse_xyz_names, parse_xyz_kinds};
static const RecordSpec parse_bottom_left = {"the screen's bottom-left corner", NULL, 3, 0, 0,
                                             parse_xyz_names, parse_xyz_kinds};
static const RecordSpec parse_background = {"the background colour", NULL, 3, 0, 0,
                                            parse_rgb_names, parse_rgb_kinds};
static const RecordSpec parse_light = {"the light", "x y z r g b", 6, 0, 0, parse_light_names,
                                       parse_light_kinds};
static const RecordSpec parse_sphere = {"the sphere",
                                        "cx cy cz radius r g b reflection"
                                        " [transparency index]",
                                        8, 2, 0, parse_sphere_names, parse_sphere_kinds};
static const RecordSpec parse_plane = {"the plane",
                                       "px py pz nx ny nz r g b reflection"
                                       " [transparency index]",
                                       10, 2, 0, parse_plane_names, parse_plane_kinds};
static const RecordSpec parse_triangle = {"the triangle",
                                          "x0 y0 z0 x1 y1 z1 x2 y2 z2 r g b reflection"
                                          " [transparency index]",
                                          13, 2, 0, parse_triangle_names, parse_triangle_kinds};
static const RecordSpec parse_ambient = {"the ambient light", "r g b", 3, 0, 0, parse_rgb_names,
                                         parse_rgb_kinds};
static const RecordSpec parse_lens = {"the lens", "aperture focal_distance", 2, 0, 0,
                                      parse_lens_names, parse_lens_kinds};
static const RecordSpec parse_sphere_texture = {"the sphere's texture", "path [filter]", 0, 0, 0,
                                                NULL, NULL};
static const RecordSpec parse_plane_texture = {"the plane's texture", "path [filter] [tile_size]",
                                               0, 1, 0, parse_tile_names, parse_tile_kinds};
static const RecordSpec parse_mesh = {"the mesh", "path r g b reflection [transparency index]",
                                      4, 2, 0, parse_sphere_names + 4, parse_sphere_kinds + 4};
static const RecordSpec parse_mesh_texture = {"the mesh's texture", "path [filter]", 0, 0, 0, NULL,
                                              NULL};
static const RecordSpec parse_triangle_texture = {"the triangle's texture",
                                                  "path [filter] [u0 v0 u1 v1 u2 v2]", 0, 6, 0,
                                                  parse_uv_names, parse_uv_kinds};

/* Reads the next record, which must be the header record spec, in which a
 * keyword is out of place; returns 0, or -1 with the fault recorded. */
static int parse_header_record(Parser *P, const RecordSpec *spec, const char *syntax,
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
        parse_fail(P, &rec->line, t->column,
                   "expected %s, found the record %s: the 7 header records (camera, three "
                   "screen corners, resolution, background, light) come first",
                   spec->what, lex_quote(q, sizeof q, t));
        return -1;
    }
    return 0;
}

/* Reads a header record of spec's numbers into values. */
static int parse_header_numbers(Parser *P, const RecordSpec *spec, Record *rec, double *values)
{
    const char *syntax = spec->syntax ? spec->syntax : spec->count == 3 ? "3 numbers" : NULL;

    if (parse_header_record(P, spec, syntax, rec) != 0)
        return -1;
    return lex_numbers(&P->lex, rec, 0, spec, values) < 0 ? -1 : 0;
}

/* point -> x y z */
static int parse_point(Parser *P, const RecordSpec *spec, Record *rec, Vec3 *out)
{
    double v[3];

    if (parse_header_numbers(P, spec, rec, v) != 0)
        return -1;
    *out = vec3(v[0], v[1], v[2]);
    return 0;
}

/* resolution -> digits, 1..CAMERA_MAX_SIZE */
static int parse_resolution(Parser *P, Record *rec, int *width)
{
    static const RecordSpec spec = {"the horizontal resolution", NULL, 1, 0, 0, NULL, NULL};

    if (parse_header_record(P, &spec, "a whole number of pixels", rec) != 0)
        return -1;
    if (rec->count > 1) {
        parse_fail(P, &rec->line, rec->tok[1].column,
                   "expected 1 number for the horizontal resolution, found %d", rec->count);
        return -1;
    }
    return lex_whole_number(&P->lex, rec, 0, "the horizontal resolution", "pixels",
                              CAMERA_MAX_SIZE, width);
}

/* colour -> r g b, each 0..255 */
static int parse_colour(Parser *P, const RecordSpec *spec, Record *rec, Colour *out)
{
    double v[3];

    if (parse_header_numbers(P, spec, rec, v) != 0)
        return -1;
    *out = colour(v[0], v[1], v[2]);
    return 0;
}

/* Records that rec's element could not be stored, scene_add_*() having
 * returned rc; returns -1. */
static int parse_fail_memory(Parser *P, const Record *rec, const Scene *scene, long rc)
{
    return lex_fail_memory(&P->lex, rec, rc == SCENE_OVER_LIMIT, scene->memory_limit);
}

/* Appends the light of values v (x y z r g b), the record rec, to the scene. */
static int parse_add_light(Parser *P, const Record *rec, const double *v, Scene *scene)
{
    Light light = light_point(vec3(v[0], v[1], v[2]), colour(v[3], v[4], v[5]));
    int rc = scene_add_light(scene, &light);

    return rc != 0 ? parse_fail_memory(P, rec, scene, rc) : 0;
}

/* light -> x y z r g b */
static int parse_light_record(Parser *P, Record *rec, Scene *scene)
{
    double v[6];

    if (parse_header_numbers(P, &parse_light, rec, v) != 0)
        return -1;
    return parse_add_light(P, rec, v, scene);
}

/* Checks the screen spanned by the corner records tl, tr and bl. */
static int parse_check_screen(Parser *P, Camera *cam, Vec3 tr, Vec3 bl, const Record *tr_rec,
                              const Record *bl_rec)
{
    cam->u = vec3_sub(tr, cam->top_left);
    cam->v = vec3_sub(bl, cam->top_left);
    switch (camera_check_screen(cam->u, cam->v)) {
    case CAMERA_SCREEN_OK:
        return 0;
    case CAMERA_SCREEN_NO_WIDTH:
        parse_fail(P, &tr_rec->line, tr_rec->tok[0].column,
                   "the screen's top-right corner is its top-left corner: the screen has no "
                   "width");
        return -1;
    case CAMERA_SCREEN_NO_HEIGHT:
        parse_fail(P, &bl_rec->line, bl_rec->tok[0].column,
                   "the screen's bottom-left corner is its top-left corner: the screen has no "
                   "height");
        return -1;
    case CAMERA_SCREEN_PARALLEL:
        parse_fail(P, &bl_rec->line, bl_rec->tok[0].column,
                   "the screen's top and left edges are parallel: its three corners lie on "
                   "one line");
        return -1;
    }
    return -1;
}

/* header -> camera top-left top-right bottom-left resolution background light */
static int parse_header(Parser *P, Scene *scene)
{
    Camera *cam = &scene->camera;
    Record rec, tr_rec;
    Vec3 tr, bl;
    double height;

    if (parse_point(P, &parse_camera, &rec, &cam->eye) != 0 ||
        parse_point(P, &parse_top_left, &rec, &cam->top_left) != 0 ||
        parse_point(P, &parse_top_right, &tr_rec, &tr) != 0 ||
        parse_point(P, &parse_bottom_left, &rec, &bl) != 0 ||
        parse_check_screen(P, cam, tr, bl, &tr_rec, &rec) != 0 ||
        parse_resolution(P, &rec, &cam->width) != 0)
        return -1;
    height = camera_height(cam->u, cam->v, cam->width);
    if (height > CAMERA_MAX_SIZE) {
        parse_fail(P, &rec.line, rec.tok[0].column,
                   "the image would be %d x %.0f pixels: its height, set by the screen's "
                   "proportions, must be at most %d",
                   cam->width, height, CAMERA_MAX_SIZE);
        return -1;
    }
    cam->height = (int)height;
    if (parse_colour(P, &parse_background, &rec, &scene->background) != 0 ||
        parse_light_record(P, &rec, scene) != 0)
        return -1;
    return 0;
}

/* material -> r g b reflection [transparency index]: the numbers of spec
 * from values[first] on, read by parse_expect_numbers() (n of them in all)
 * from rec's tokens, the first number being token tok0; checks R + T <= 1. */
static int parse_material(Parser *P, const Record *rec, const RecordSpec *spec, int tok0,
                          int first, const double *values, int n, Material *m)
{
    const double *v = values + first;

    *m = material_plain(colour(v[0], v[1], v[2]), v[3]);
    if (n == spec->count + spec->optional) {
        /* A little slack, so that 0.1 + 0.9 passes whatever the rounding. */
        if (v[3] + v[4] > 1 + 1e-12) {
            const Token *t = &rec->tok[tok0 + first + 4];
            parse_fail(P, &rec->line, t->column,
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
static void parse_note_object(Parser *P, int kind, size_t index)
{
    P->has_last = 1;
    P->last_kind = kind;
    P->last_index = index;
}

/* Returns the material of the last object read (there must be one). */
static Material *parse_last_material(Parser *P, Scene *scene)
{
    switch (P->last_kind) {
    case PARSE_SHAPE_PLANE:
        return &scene->planes[P->last_index].material;
    case PARSE_SHAPE_TRIANGLE:
    case PARSE_SHAPE_MESH: /* a mesh's triangles share it */
        return scene_material_of(scene, &scene->triangles[P->last_index]);
    default:
        return &scene->spheres[P->last_index].material;
    }
}


/* sphere -> 'sphere:' cx cy cz radius r g b reflection [transparency index]:
 * reads rec, a sphere: record, into *s (its order aside). */
static int parse_sphere_fields(Parser *P, const Record *rec, Sphere *s)
{
    double v[10];
    int n = lex_numbers(&P->lex, rec, 1, &parse_sphere, v);

    if (n < 0 || parse_material(P, rec, &parse_sphere, 1, 4, v, n, &s->material) != 0)
        return -1;
    s->centre = vec3(v[0], v[1], v[2]);
    s->radius = v[3];
    return 0;
}

/* sphere -> 'sphere:' ... (parse_sphere_fields()), appended to the scene */
static int parse_sphere_record(Parser *P, const Record *rec, Scene *scene)
{
    Sphere s;
    int rc;

    if (parse_sphere_fields(P, rec, &s) != 0)
        return -1;
    rc = scene_add_sphere(scene, &s);
    if (rc != 0)
        return parse_fail_memory(P, rec, scene, rc);
    parse_note_object(P, PARSE_SHAPE_SPHERE, scene->sphere_count - 1);
    return 0;
}

/* plane -> 'plane:' px py pz nx ny nz r g b reflection [transparency index] */
static int parse_plane_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[12];
    int n = lex_numbers(&P->lex, rec, 1, &parse_plane, v), rc;
    Material m;
    Plane pl;

    if (n < 0 || parse_material(P, rec, &parse_plane, 1, 6, v, n, &m) != 0)
        return -1;
    if (plane_make(&pl, vec3(v[0], v[1], v[2]), vec3(v[3], v[4], v[5]), 1, m) != 0) {
        parse_fail(P, &rec->line, rec->tok[4].column,
                   "the plane's normal is the zero vector: it must give a direction");
        return -1;
    }
    rc = scene_add_plane(scene, &pl);
    if (rc != 0)
        return parse_fail_memory(P, rec, scene, rc);
    parse_note_object(P, PARSE_SHAPE_PLANE, scene->plane_count - 1);
    return 0;
}

/* triangle -> 'triangle:' x0 y0 z0 x1 y1 z1 x2 y2 z2 r g b reflection
 *             [transparency index] */
static int parse_triangle_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[15];
    int n = lex_numbers(&P->lex, rec, 1, &parse_triangle, v), rc;
    Material m;
    Triangle tri;

    if (n < 0 || parse_material(P, rec, &parse_triangle, 1, 9, v, n, &m) != 0)
        return -1;
    if (triangle_make(&tri, vec3(v[0], v[1], v[2]), vec3(v[3], v[4], v[5]),
                      vec3(v[6], v[7], v[8])) != 0) {
        parse_fail(P, &rec->line, rec->tok[0].column,
                   "the triangle's three vertices lie on one line: it has no area");
        return -1;
    }
    rc = scene_add_triangle(scene, &tri, &m);
    if (rc != 0)
        return parse_fail_memory(P, rec, scene, rc);
    parse_note_object(P, PARSE_SHAPE_TRIANGLE, scene->triangle_count - 1);
    return 0;
}

/* light -> 'light:' x y z r g b */
static int parse_extra_light_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[6];

    if (lex_numbers(&P->lex, rec, 1, &parse_light, v) < 0)
        return -1;
    return parse_add_light(P, rec, v, scene);
}

/* Checks that the record keyword of rec, which may appear once, has not
 * appeared before (on line *seen, 0 if not); then notes its line. */
static int parse_once(Parser *P, const Record *rec, int *seen, const char *what)
{
    if (*seen) {
        parse_fail(P, &rec->line, rec->tok[0].column, "%s is already set, on line %d", what,
                   *seen);
        return -1;
    }
    *seen = rec->line.number;
    return 0;
}

/* ambient -> 'ambient:' r g b */
static int parse_ambient_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[3];

    if (parse_once(P, rec, &P->ambient_line, "the ambient light") != 0 ||
        lex_numbers(&P->lex, rec, 1, &parse_ambient, v) < 0)
        return -1;
    scene->ambient = colour(v[0], v[1], v[2]);
    scene->has_ambient = 1;
    return 0;
}

/* samples -> 'samples:' digits, 1..CAMERA_MAX_SAMPLES */
static int parse_samples_record(Parser *P, const Record *rec, Scene *scene)
{
    if (parse_once(P, rec, &P->samples_line, "the number of samples per pixel") != 0)
        return -1;
    if (rec->count != 2) {
        parse_fail(P, &rec->line, rec->count < 2 ? rec->end_column : rec->tok[2].column,
                   "expected 1 number for the samples per pixel, found %d", rec->count - 1);
        return -1;
    }
    return lex_whole_number(&P->lex, rec, 1, "the number of samples per pixel", "samples",
                              CAMERA_MAX_SAMPLES, &scene->samples);
}

/* lens -> 'lens:' aperture focal_distance */
static int parse_lens_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[2];

    if (parse_once(P, rec, &P->lens_line, "the lens") != 0 ||
        lex_numbers(&P->lex, rec, 1, &parse_lens, v) < 0)
        return -1;
    if (v[0] > 0 && camera_set_lens(&scene->camera, v[0], v[1]) != 0) {
        parse_fail(P, &rec->line, rec->tok[0].column,
                   "the camera lies in the plane of its screen: a lens needs the screen in "
                   "front of the camera");
        return -1;
    }
    return 0;
}

/* Loads the texture file named by token t (relative to the scene file's
 * directory) into the scene, or finds it there already; returns its index,
 * or -1 with the fault recorded at t. */
static int parse_load_texture(Parser *P, const Record *rec, const Token *t, Scene *scene)
{
    char *path = lex_path(&P->lex, t);
    Texture tex;
    Error inner;
    int index;

    if (!path)
        return -1;
    for (size_t i = 0; i < scene->texture_count; i++) {
        if (strcmp(scene->textures[i].path, path) == 0) {
            free(path);
            return (int)i;
        }
    }
    if (texture_file_load(&tex, path, &inner) != 0) {
        lex_fail_file(&P->lex, rec, t, "texture", &inner);
        free(path);
        return -1;
    }
    free(path);
    index = scene_add_texture(scene, &tex);
    if (index < 0)
        parse_fail_memory(P, rec, scene, index);
    return index < 0 ? -1 : index;
}

/* mesh -> 'mesh:' path r g b reflection [transparency index] */
static int parse_mesh_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[6];
    Material mat;
    ObjMesh mesh;
    Error inner;
    char *path, q[64];
    long added;
    int n;

    if (rec->count < 2) {
        parse_fail(P, &rec->line, rec->end_column,
                   "expected the path of an OBJ file for the mesh (%s), found the end of the "
                   "line",
                   parse_mesh.syntax);
        return -1;
    }
    n = lex_numbers(&P->lex, rec, 2, &parse_mesh, v);
    if (n < 0 || parse_material(P, rec, &parse_mesh, 2, 0, v, n, &mat) != 0)
        return -1;
    path = lex_path(&P->lex, &rec->tok[1]);
    if (!path)
        return -1;
    if (obj_load(path, scene_obj_budget(scene), &mesh, &inner) != 0) {
        lex_fail_file(&P->lex, rec, &rec->tok[1], "mesh", &inner);
        free(path);
        return -1;
    }
    free(path);
    added = mesh_add(scene, &mesh, &mat);
    obj_free(&mesh);
    if (added < 0)
        return parse_fail_memory(P, rec, scene, added);
    if (added == 0) {
        parse_fail(P, &rec->line, rec->tok[1].column,
                   "the mesh %s has no faces with an area: nothing to draw",
                   lex_quote(q, sizeof q, &rec->tok[1]));
        return -1;
    }
    parse_note_object(P, PARSE_SHAPE_MESH, scene->triangle_count - (size_t)added);
    return 0;
}

/* texture -> 'texture:' path [nearest | bilinear] number*, for the object
 * just before: none for a sphere, [tile_size] for a plane, [u0 v0 u1 v1 u2
 * v2] for a triangle. */
static int parse_texture_record(Parser *P, const Record *rec, Scene *scene)
{
    static const RecordSpec *const specs[] = {&parse_sphere_texture, &parse_plane_texture,
                                              &parse_triangle_texture, &parse_mesh_texture};
    const RecordSpec *spec;
    int first = 2, n, index;
    double v[6];
    TextureFilter filter = TEXTURE_BILINEAR;
    Material *m;

    if (!P->has_last) {
        parse_fail(P, &rec->line, rec->tok[0].column,
                   "a texture: record must follow the object it covers, and no object comes "
                   "before it");
        return -1;
    }
    spec = specs[P->last_kind];
    m = parse_last_material(P, scene);
    if (m->texture >= 0) {
        parse_fail(P, &rec->line, rec->tok[0].column,
                   "%s is already set: an object takes one texture: record", spec->what);
        return -1;
    }
    if (rec->count < 2) {
        parse_fail(P, &rec->line, rec->end_column,
                   "expected the path of a PPM file for %s (%s), found the end of the line",
                   spec->what, spec->syntax);
        return -1;
    }
    if (rec->count > 2 && lex_token_is(&rec->tok[2], "nearest")) {
        filter = TEXTURE_NEAREST;
        first = 3;
    } else if (rec->count > 2 && lex_token_is(&rec->tok[2], "bilinear")) {
        first = 3;
    } else if (rec->count > 2 &&
               number_parse(rec->tok[2].text, rec->tok[2].len, &v[0]) == NUMBER_SYNTAX) {
        char q[64];
        parse_fail(P, &rec->line, rec->tok[2].column,
                   "unknown texture filter %s (expected 'nearest' or 'bilinear')",
                   lex_quote(q, sizeof q, &rec->tok[2]));
        return -1;
    }
    if (spec->optional == 0 && rec->count > first)
        return lex_fail_extra(&P->lex, rec, first, spec->what);
    n = lex_numbers(&P->lex, rec, first, spec, v);
    if (n < 0)
        return -1;
    index = parse_load_texture(P, rec, &rec->tok[1], scene);
    if (index < 0)
        return -1;
    m = parse_last_material(P, scene);
    m->texture = index;
    m->filter = filter;
    if (P->last_kind == PARSE_SHAPE_PLANE && n == 1)
        scene->planes[P->last_index].tile = v[0];
    if (P->last_kind == PARSE_SHAPE_TRIANGLE && n == 6) {
        TriangleShading sh = triangle_plain_shading(&scene->triangles[P->last_index]);
        int rc;
        for (int k = 0; k < 3; k++) {
            sh.uv[k][0] = v[2 * k];
            sh.uv[k][1] = v[2 * k + 1];
        }
        rc = scene_shade_triangle(scene, P->last_index, &sh);
        if (rc != 0)
            return parse_fail_memory(P, rec, scene, rc);
    }
    return 0;
}

/* A record that may follow the header, and what reads it. */
typedef struct {
    const char *keyword; /* with its colon */
    int (*parse)(Parser *P, const Record *rec, Scene *scene);
} RecordKind;

static const RecordKind parse_records[] = {
    {"sphere:", parse_sphere_record},   {"plane:", parse_plane_record},
    {"triangle:", parse_triangle_record}, {"light:", parse_extra_light_record},
    {"ambient:", parse_ambient_record}, {"samples:", parse_samples_record},
    {"lens:", parse_lens_record},       {"texture:", parse_texture_record},
    {"mesh:", parse_mesh_record},
};

enum { PARSE_RECORD_KINDS = sizeof parse_records / sizeof parse_records[0] };

#define PARSE_KEYWORD_LIST                                                                    \
    "'sphere:', 'plane:', 'triangle:', 'mesh:', 'light:', 'ambient:', 'samples:', 'lens:' "   \
    "or 'texture:'"

/* Records why the first token of rec is not a known record keyword. */
static void parse_fail_keyword(Parser *P, const Record *rec)
{
    const Token *t = &rec->tok[0];
    char q[64];
    double ignored;

    lex_quote(q, sizeof q, t);
    for (int k = 0; k < PARSE_RECORD_KINDS; k++) {
        const char *kw = parse_records[k].keyword;
        size_t n = strlen(kw);
        char bare[16];

        memcpy(bare, kw, n - 1);
        bare[n - 1] = '\0';
        if (number_word_is(t->text, t->len, kw)) {
            parse_fail(P, &rec->line, t->column,
                       "unknown record %s: keywords are lower case ('%s')", q, kw);
            return;
        }
        if (t->len == n - 1 && number_word_is(t->text, t->len, bare)) {
            parse_fail(P, &rec->line, t->column,
                       "expected '%s' with its colon attached, found %s", kw, q);
            return;
        }
    }
    if (number_parse(t->text, t->len, &ignored) != NUMBER_SYNTAX)
        parse_fail(P, &rec->line, t->column,
                   "expected a record such as 'sphere:', found the number %s: the 7 header "
                   "records are complete",
                   q);
    else
        parse_fail(P, &rec->line, t->column, "unknown record %s (expected " PARSE_KEYWORD_LIST
                   ")", q);
}

enum {
    PARSE_PARALLEL_MIN = 1 << 20, /* fewer bytes of records are read on one thread */
    PARSE_PARTS_MAX = 64
};

/* A part of the records, whole lines, for one thread to read. */
typedef struct {
    const char *start, *end;
    size_t spheres; /* its records, every one a sphere: record if right */
    int lines;
    int others;     /* some record is not a sphere: record */
} ParsePart;

/* Counts part's lines and records (lines with a token before any '#'), and
 * notes whether a record does not start with 'sphere:'. */
static void parse_count_part(ParsePart *part)
{
    const char *p = part->start, *end = part->end;

    part->spheres = 0;
    part->lines = 0;
    part->others = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p)), *q = p;
        if (!eol)
            eol = end;
        while (q < eol && (*q == ' ' || *q == '\t'))
            q++;
        if (q < eol && *q != '#' && !(*q == '\r' && q + 1 == eol)) {
            part->spheres++;
            part->others |= (size_t)(eol - q) < 7 || memcmp(q, "sphere:", 7) != 0;
        }
        part->lines++;
        p = eol < end ? eol + 1 : end;
    }
}

/* Reads part's records into room, each a sphere: record, with P's
 * rules; returns 0, or -1 at anything else (a fault, another record). */
static int parse_sphere_part(const Parser *P, const ParsePart *part, Sphere *room)
{
    Parser Q = *P;
    Error ignored; /* the serial reading says what is wrong */
    Record rec;
    size_t k = 0;
    int rc;

    Q.lex.start = Q.lex.next = part->start;
    Q.lex.end = part->end;
    Q.lex.err = &ignored;
    while ((rc = lex_next_record(&Q.lex, &rec)) == 1) {
        if (k == part->spheres || !lex_token_is(&rec.tok[0], "sphere:") ||
            parse_sphere_fields(&Q, &rec, &room[k]) != 0)
            return -1;
        k++;
    }
    return rc == 0 && k == part->spheres ? 0 : -1;
}

/* What the parts' threads share. */
typedef struct {
    const Parser *P;
    const ParsePart *parts;
    int n;
} ParseParts;

/* Reads every part into its place in room (scene_add_spheres()'s fill). */
static int parse_fill_spheres(Sphere *room, void *ctx)
{
    const ParseParts *pp = ctx;
    int failed = 0;

#ifdef _OPENMP
#pragma omp parallel for num_threads(pp->n) schedule(static, 1) reduction(| : failed)
#endif
    for (int k = 0; k < pp->n; k++) {
        size_t at = 0; /* part k's spheres go after those of the parts before it */
        for (int j = 0; j < k; j++)
            at += pp->parts[j].spheres;
        failed |= parse_sphere_part(pp->P, &pp->parts[k], room + at) != 0;
    }
    return failed ? -1 : 0;
}

/* Reads the rest of the input on every thread when it is large and holds
 * sphere: records alone (the benchmark's fields), into the same scene as
 * the serial reading; returns 1 when it did, 0 when the serial reading
 * must (then also when something is wrong: it says what, as it would
 * have). */
static int parse_spheres_parallel(Parser *P, Scene *scene)
{
    ParsePart parts[PARSE_PARTS_MAX];
    const char *cut[PARSE_PARTS_MAX + 1];
    size_t len = (size_t)(P->lex.end - P->lex.next), spheres = 0;
    int threads = threads_count(), n = threads < PARSE_PARTS_MAX ? threads : PARSE_PARTS_MAX;
    int lines = 0, others = 0;
    ParseParts pp = {P, parts, n};

    if (n < 2 || len < PARSE_PARALLEL_MIN)
        return 0;
    lex_split(P->lex.next, len, n, cut);
#ifdef _OPENMP
#pragma omp parallel for num_threads(n) schedule(static, 1)
#endif
    for (int k = 0; k < n; k++) {
        parts[k].start = cut[k];
        parts[k].end = cut[k + 1];
        parse_count_part(&parts[k]);
    }
    for (int k = 0; k < n; k++) {
        spheres += parts[k].spheres;
        lines += parts[k].lines;
        others |= parts[k].others;
    }
    if (others || spheres == 0 || scene_add_spheres(scene, spheres, parse_fill_spheres, &pp) != 0)
        return 0;
    P->lex.next = P->lex.end;
    P->lex.lineno += lines;
    parse_note_object(P, PARSE_SHAPE_SPHERE, scene->sphere_count - 1);
    return 1;
}

/* objects -> record* */
static int parse_objects(Parser *P, Scene *scene)
{
    Record rec;
    int rc;

    if (parse_spheres_parallel(P, scene))
        return 0;
    while ((rc = lex_next_record(&P->lex, &rec)) == 1) {
        int k = 0;
        while (k < PARSE_RECORD_KINDS && !lex_token_is(&rec.tok[0], parse_records[k].keyword))
            k++;
        if (k == PARSE_RECORD_KINDS) {
            parse_fail_keyword(P, &rec);
            return -1;
        }
        if (parse_records[k].parse(P, &rec, scene) != 0)
            return -1;
    }
    return rc;
}

int parse_scene_text(const char *name, const char *text, size_t len, size_t memory_limit,
                     Scene *scene, Error *err)
{
    Parser P;

    scene_init(scene);
    scene->memory_limit = memory_limit;
    lex_init(&P.lex, name, text, len, err);
    P.ambient_line = P.samples_line = P.lens_line = 0;
    P.has_last = 0;
    P.last_kind = PARSE_SHAPE_SPHERE;
    P.last_index = 0;
    if (parse_header(&P, scene) != 0 || parse_objects(&P, scene) != 0) {
        scene_free(scene);
        return -1;
    }
    scene_fit_scale(scene);
    return 0;
}
