/*
 * keyword.c: the OCaml course project's keyword scene format (see keyword.h,
 * docs/scene-format.md). Lines, comments and numbers follow lex.h.
 *
 *   scene      -> element*            (exactly one camera, anywhere)
 *   camera     -> 'camera' x0 y0 z0 xA yA zA alpha width height
 *   material   -> 'material' name r g b ka kd ks alpha [rho [eta [tau]]]
 *   sphere     -> 'sphere' xC yC zC radius material
 *   plane      -> 'plane' px py pz nx ny nz material
 *   triangle   -> 'triangle' x0 y0 z0 x1 y1 z1 x2 y2 z2 material
 *   cube       -> 'cube' xC yC zC half material
 *   square     -> 'square' xC yC zC nx ny nz half material
 *   cylinder   -> 'cylinder' x y z radius material   (infinite, along y)
 *   cone       -> 'cone' x y z radius height material (infinite, cone.h)
 *   mesh       -> 'mesh' path [material]     (an OBJ, PLY or STL file;
 *                                             without a material, its own)
 *   light      -> 'light' x y z r g b i              (distant, any number)
 *   ambient    -> 'ambient' r g b                    (at most once)
 *   background -> 'background' r g b                 (at most once)
 *
 * A material is defined on a line before the objects that name it.
 */
#include "scenefile/keyword.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "math/angle.h"
#include "math/number.h"
#include "scene/scale.h"
#include "scenefile/lex.h"
#include "scenefile/mesh.h"
#include "scenefile/names.h"
#include "scenefile/obj.h"
#include "scenefile/shapes.h"

/* The reader's state. */
typedef struct {
    Lexer lex;              /* the cursor over the input */
    SceneSource *source;    /* its mesh lines and camera line, kept */
    int camera_line;        /* line of the camera, 0 before it */
    int ambient_line;       /* line of the ambient record, 0 before it */
    int gi_line, gicache_line; /* the gi and gicache records' */
    int background_line;    /* line of the background record, 0 before it */
    Names names;            /* the materials by name */
} Keyword;

static const char *const keyword_camera_names[] = {
    "x0", "y0", "z0", "xA", "yA", "zA", "field of view", "width", "height"};
static const FieldKind keyword_camera_kinds[] = {
    FIELD_COORD, FIELD_COORD, FIELD_COORD, FIELD_COORD,   FIELD_COORD,
    FIELD_COORD, FIELD_POSITIVE, FIELD_POSITIVE, FIELD_POSITIVE};
static const char *const keyword_material_names[] = {
    "red", "green", "blue", "ka", "kd", "ks", "alpha", "rho_r", "eta_r", "tau"};
static const FieldKind keyword_material_kinds[] = {
    FIELD_COLOUR,      FIELD_COLOUR,      FIELD_COLOUR,   FIELD_NONNEGATIVE, FIELD_NONNEGATIVE,
    FIELD_NONNEGATIVE, FIELD_NONNEGATIVE, FIELD_FRACTION, FIELD_POSITIVE,    FIELD_FRACTION};
static const char *const keyword_light_names[] = {"x", "y", "z", "red", "green", "blue",
                                                  "intensity"};
static const FieldKind keyword_light_kinds[] = {FIELD_COORD,  FIELD_COORD,  FIELD_COORD,
                                                FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR,
                                                FIELD_NONNEGATIVE};
static const char *const keyword_rgb_names[] = {"red", "green", "blue"};
static const FieldKind keyword_rgb_kinds[] = {FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};

static const RecordSpec keyword_camera = {
    "the camera", "x0 y0 z0 xA yA zA alpha width height", 9, 0, 0,
    keyword_camera_names, keyword_camera_kinds};
static const RecordSpec keyword_material = {
    "the material", "name r g b ka kd ks alpha [rho_r [eta_r [tau]]]", 7, 3, 1,
    keyword_material_names, keyword_material_kinds};
static const RecordSpec keyword_light = {"the light", "x y z r g b i", 7, 0, 0,
                                         keyword_light_names, keyword_light_kinds};
static const RecordSpec keyword_ambient = {"the ambient light", "r g b", 3, 0, 0,
                                           keyword_rgb_names, keyword_rgb_kinds};
static const RecordSpec keyword_background = {"the background", "r g b", 3, 0, 0,
                                              keyword_rgb_names, keyword_rgb_kinds};

static const char *const keyword_gicache_names[] = {"error"};
static const FieldKind keyword_gicache_kinds[] = {FIELD_POSITIVE};
static const RecordSpec keyword_gicache = {"the irradiance cache", "[error]", 1, 0, 0,
                                           keyword_gicache_names, keyword_gicache_kinds};

/* Records a fault at column of line. */
#define keyword_fail(K, line, column, ...) lex_fail(&(K)->lex, line, column, __VA_ARGS__)

/* Records that memory ran out; returns -1. */
static int keyword_fail_memory(Keyword *K)
{
    error_set(K->lex.err, K->lex.name, "out of memory");
    return -1;
}

/* Says whether token t reads as a number (valid or not: "1e400", "nan"). */
static int keyword_is_number(const Token *t)
{
    double ignored;

    return number_parse(t->text, t->len, &ignored) != NUMBER_SYNTAX;
}

/* Records that rec's element could not be stored, scene_add_*() having
 * returned rc; returns -1. */
static int keyword_fail_store(Keyword *K, const Record *rec, const Scene *scene, long rc)
{
    return lex_fail_memory(&K->lex, rec, rc == SCENE_OVER_LIMIT, scene->memory_limit);
}

/* camera -> 'camera' x0 y0 z0 xA yA zA alpha width height */
static int keyword_camera_record(Keyword *K, const Record *rec, Scene *scene)
{
    double v[9];
    int width, height;
    char q[64];

    if (lex_once(&K->lex, rec, &K->camera_line, "the camera") != 0 ||
        lex_numbers(&K->lex, rec, 1, &keyword_camera, v) < 0 ||
        lex_whole_number(&K->lex, rec, 8, "the image width", "pixels", CAMERA_MAX_SIZE,
                         &width) != 0 ||
        lex_whole_number(&K->lex, rec, 9, "the image height", "pixels", CAMERA_MAX_SIZE,
                         &height) != 0)
        return -1;
    if (!(v[6] < ANGLE_PI)) {
        keyword_fail(K, &rec->line, rec->tok[7].column,
                     "the camera's field of view must be less than pi radians, found %s "
                     "(it is in radians: 120 degrees is 2.0943951)",
                     lex_quote(q, sizeof q, &rec->tok[7]));
        return -1;
    }
    K->source->camera_line = 1;
    K->source->look_from = vec3(v[0], v[1], v[2]);
    K->source->look_at = vec3(v[3], v[4], v[5]);
    K->source->fov = v[6];
    switch (camera_look_at(&scene->camera, K->source->look_from, K->source->look_at, v[6], width,
                           height)) {
    case CAMERA_VIEW_OK:
        return 0;
    case CAMERA_VIEW_NO_DIRECTION:
        keyword_fail(K, &rec->line, rec->tok[4].column,
                     "the camera looks at its own position: the point it looks at must be "
                     "elsewhere");
        return -1;
    case CAMERA_VIEW_TOO_NARROW:
        keyword_fail(K, &rec->line, rec->tok[7].column,
                     "the camera's field of view %s is too narrow: the screen has no size in "
                     "double precision",
                     lex_quote(q, sizeof q, &rec->tok[7]));
        return -1;
    }
    return -1;
}

/* material -> 'material' name r g b ka kd ks alpha [rho [eta [tau]]] */
static int keyword_material_record(Keyword *K, const Record *rec, Scene *scene)
{
    double v[10];
    const Token *name = rec->count > 1 ? &rec->tok[1] : NULL;
    NamedMaterial pm;
    char q[64];
    int n, index;

    if (!name || keyword_is_number(name)) {
        keyword_fail(K, &rec->line, name ? name->column : rec->end_column,
                     "expected the material's name (%s), found %s%s", keyword_material.syntax,
                     name ? "the number " : "the end of the line",
                     name ? lex_quote(q, sizeof q, name) : "");
        return -1;
    }
    index = names_find(&K->names, scene, name);
    if (index >= 0) {
        keyword_fail(K, &rec->line, name->column, "the material %s is already defined, on line %d",
                     lex_quote(q, sizeof q, name), scene->named[index].line);
        return -1;
    }
    n = lex_numbers(&K->lex, rec, 2, &keyword_material, v);
    if (n < 0)
        return -1;
    memset(&pm, 0, sizeof pm);
    pm.base = material_plain(colour(v[0], v[1], v[2]), n > 7 ? v[7] : 0);
    pm.ka = v[3];
    pm.kd = v[4];
    pm.ks = v[5];
    pm.shininess = v[6];
    pm.line = rec->line.number;
    if (n > 8) {
        /* A refractive index makes the material transparent: tau is given,
         * or all the light it does not mirror. */
        double tau = n > 9 ? v[9] : 1 - v[7];
        if (v[7] + tau > 1 + 1e-12) {
            keyword_fail(K, &rec->line, rec->tok[11].column,
                         "the material's rho_r plus tau must be at most 1, found %g + %g", v[7],
                         tau);
            return -1;
        }
        pm.base.transparency = tau;
        pm.base.ior = v[8];
    }
    pm.name = malloc(name->len + 1);
    if (!pm.name)
        return keyword_fail_memory(K);
    memcpy(pm.name, name->text, name->len);
    pm.name[name->len] = '\0';
    index = scene_add_named(scene, &pm);
    if (index < 0)
        return keyword_fail_store(K, rec, scene, index);
    scene->named[index].base.named = index;
    return names_add(&K->names, scene, (size_t)index) != 0 ? keyword_fail_memory(K) : 0;
}

/* shape -> KEYWORD numbers material (sphere: xC yC zC radius; plane: px py
 * pz nx ny nz; triangle: three corners; cube: xC yC zC half; square: xC
 * yC zC nx ny nz half; cylinder: x y z radius; cone: x y z radius
 * height): reads rec, an element of a shape of kind, into the scene. */
static int keyword_shape_record(Keyword *K, const Record *rec, Scene *scene, ShapeKind kind)
{
    ShapesSpec shape;
    double v[SHAPE_NUMBERS_MAX];
    const char *fault = NULL;
    int rc, field = 0;
    Material m;

    shapes_spec(&shape, kind, "material", 0, 0, NULL, NULL);
    if (names_numbers_and_material(&K->lex, &K->names, rec, 1, &shape.spec, scene,
                                   "a material line", v, &m) != 0)
        return -1;
    rc = shapes_add(scene, kind, v, &m, &fault, &field);
    if (rc == SHAPES_INVALID) {
        keyword_fail(K, &rec->line, rec->tok[field < 0 ? 0 : 1 + field].column, "%s", fault);
        return -1;
    }
    return rc != 0 ? keyword_fail_store(K, rec, scene, rc) : 0;
}

/* mesh -> 'mesh' path [material]: without a material, the mesh file's
 * own */
static int keyword_mesh_record(Keyword *K, const Record *rec, Scene *scene)
{
    static const RecordSpec spec = {"the mesh", "path [material]", 0, 0, 0, NULL, NULL};
    const Token *path_tok = &rec->tok[1];
    Material m;
    char q[64];
    long added;

    if (rec->count < 2) {
        keyword_fail(K, &rec->line, rec->end_column,
                     "expected the path of a mesh file (OBJ, PLY or STL) for the mesh (path "
                     "[material]), found the end of the line");
        return -1;
    }
    if (rec->count > 2 && names_numbers_and_material(&K->lex, &K->names, rec, 2, &spec, scene,
                                                      "a material line", NULL, &m) != 0)
        return -1;
    added = mesh_load(&K->lex, rec, path_tok, rec->count > 2 ? &m : NULL, scene, K->source);
    if (added == MESH_FAULT)
        return -1;
    if (added < 0)
        return keyword_fail_store(K, rec, scene, (int)added);
    if (added == 0) {
        keyword_fail(K, &rec->line, path_tok->column,
                     "the mesh %s has no faces with an area: nothing to draw",
                     lex_quote(q, sizeof q, path_tok));
        return -1;
    }
    return 0;
}

/* light -> 'light' x y z r g b i */
static int keyword_light_record(Keyword *K, const Record *rec, Scene *scene)
{
    double v[7];
    Light light;

    if (lex_numbers(&K->lex, rec, 1, &keyword_light, v) < 0)
        return -1;
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) {
        keyword_fail(K, &rec->line, rec->tok[1].column,
                     "the light's direction is the zero vector: a distant light needs the "
                     "direction its light travels");
        return -1;
    }
    light = light_point(vec3(v[0], v[1], v[2]), colour(v[3], v[4], v[5]));
    light.distant = 1;
    light.intensity = v[6];
    light.to_light = vec3_neg(vec3_direction(light.position));
    {
        int rc = scene_add_light(scene, &light);
        if (rc != 0)
            return keyword_fail_store(K, rec, scene, rc);
    }
    return 0;
}

/* ambient -> 'ambient' r g b */
static int keyword_ambient_record(Keyword *K, const Record *rec, Scene *scene)
{
    double v[3];

    if (lex_once(&K->lex, rec, &K->ambient_line, "the ambient light") != 0 ||
        lex_numbers(&K->lex, rec, 1, &keyword_ambient, v) < 0)
        return -1;
    scene->ambient = colour(v[0], v[1], v[2]);
    scene->has_ambient = 1;
    return 0;
}

/* background -> 'background' r g b */
static int keyword_background_record(Keyword *K, const Record *rec, Scene *scene)
{
    double v[3];

    if (lex_once(&K->lex, rec, &K->background_line, "the background") != 0 ||
        lex_numbers(&K->lex, rec, 1, &keyword_background, v) < 0)
        return -1;
    scene->background = colour(v[0], v[1], v[2]);
    return 0;
}

/* gi -> 'gi' rays [bounces]: global illumination, as --gi and
 * --gi-bounces (docs/scene-format.md) */
static int keyword_gi_record(Keyword *K, const Record *rec, Scene *scene)
{
    if (lex_once(&K->lex, rec, &K->gi_line, "the global illumination") != 0)
        return -1;
    if (rec->count < 2) {
        keyword_fail(K, &rec->line, rec->tok[0].column + (int)rec->tok[0].len,
                     "missing the number of global illumination rays (expected gi rays "
                     "[bounces])");
        return -1;
    }
    if (rec->count > 3)
        return lex_fail_extra(&K->lex, rec, 3, "the number of bounces");
    if (lex_whole_number_in(&K->lex, rec, 1, "the number of global illumination rays", "rays", 0,
                            SCENE_MAX_INDIRECT, &scene->gi_samples) != 0)
        return -1;
    return rec->count == 3 ? lex_whole_number(&K->lex, rec, 2, "the number of bounces",
                                              "bounces", SCENE_MAX_BOUNCES, &scene->gi_bounces)
                           : 0;
}

/* gicache -> 'gicache' [error]: global illumination's light through the
 * irradiance cache, as --gi-cache and --gi-cache-error */
static int keyword_gicache_record(Keyword *K, const Record *rec, Scene *scene)
{
    if (lex_once(&K->lex, rec, &K->gicache_line, "the irradiance cache") != 0)
        return -1;
    scene->gi_cache = 1;
    if (rec->count > 2)
        return lex_fail_extra(&K->lex, rec, 2, "the irradiance cache's error");
    if (rec->count == 2 &&
        lex_number(&K->lex, rec, 1, &keyword_gicache, 0, &scene->gi_cache_error) != 0)
        return -1;
    if (rec->count == 2 && !(scene->gi_cache_error >= SCENE_GI_CACHE_MIN_ERROR &&
                             scene->gi_cache_error <= SCENE_GI_CACHE_MAX_ERROR)) {
        keyword_fail(K, &rec->line, rec->tok[1].column,
                     "the irradiance cache's error must be from %g to %g (smaller: more "
                     "records)",
                     SCENE_GI_CACHE_MIN_ERROR, SCENE_GI_CACHE_MAX_ERROR);
        return -1;
    }
    return 0;
}

/* An element other than a shape's, and what reads it. */
typedef struct {
    const char *keyword;
    int (*parse)(Keyword *K, const Record *rec, Scene *scene);
} KeywordKind;

static const KeywordKind keyword_kinds[] = {
    {"camera", keyword_camera_record},         {"material", keyword_material_record},
    {"mesh", keyword_mesh_record},             {"light", keyword_light_record},
    {"ambient", keyword_ambient_record},       {"background", keyword_background_record},
    {"gi", keyword_gi_record},                 {"gicache", keyword_gicache_record},
};

enum { KEYWORD_KINDS = sizeof keyword_kinds / sizeof keyword_kinds[0] };

#define KEYWORD_SHAPE_WORD(K, T, name, ...) "'" #name "', "
#define KEYWORD_LIST                                                                          \
    "'camera', 'material', " SHAPE_LIST(KEYWORD_SHAPE_WORD) "'mesh', 'light', 'ambient' or "    \
    "'background'"

/* Records why t, the first token of rec, is not the keyword kw that it
 * nearly is, and returns 1; or returns 0. */
static int keyword_near(Keyword *K, const Record *rec, const char *kw)
{
    const Token *t = &rec->tok[0];
    size_t n = strlen(kw);
    char q[64];

    lex_quote(q, sizeof q, t);
    if (number_word_is(t->text, t->len, kw)) {
        keyword_fail(K, &rec->line, t->column, "unknown element %s: keywords are lower case "
                                               "('%s')", q, kw);
        return 1;
    }
    if (t->len == n + 1 && t->text[n] == ':' && number_word_is(t->text, n, kw)) {
        keyword_fail(K, &rec->line, t->column,
                     "unknown element %s: this is a keyword-format scene (its first "
                     "element is a keyword), where keywords take no colon ('%s')",
                     q, kw);
        return 1;
    }
    return 0;
}

/* Records why the first token of rec is not a known keyword. */
static void keyword_fail_keyword(Keyword *K, const Record *rec)
{
    const Token *t = &rec->tok[0];
    char q[64];

    lex_quote(q, sizeof q, t);
    for (int k = 0; k < KEYWORD_KINDS; k++)
        if (keyword_near(K, rec, keyword_kinds[k].keyword))
            return;
    for (int k = 0; k < SHAPE_KINDS; k++)
        if (keyword_near(K, rec, shape_words[k]))
            return;
    if (keyword_is_number(t))
        keyword_fail(K, &rec->line, t->column,
                     "expected an element such as 'sphere', found the number %s: every line "
                     "of a keyword-format scene starts with its keyword",
                     q);
    else
        keyword_fail(K, &rec->line, t->column, "unknown element %s (expected " KEYWORD_LIST ")",
                     q);
}

/* scene -> element* */
static int keyword_elements(Keyword *K, Scene *scene)
{
    Record rec;
    int rc;

    while ((rc = lex_next_record(&K->lex, &rec)) == 1) {
        int k = 0;
        ShapeKind kind;
        while (k < KEYWORD_KINDS && !lex_token_is(&rec.tok[0], keyword_kinds[k].keyword))
            k++;
        if (k < KEYWORD_KINDS) {
            if (keyword_kinds[k].parse(K, &rec, scene) != 0)
                return -1;
        } else if (shapes_kind_of(rec.tok[0].text, rec.tok[0].len, "", &kind)) {
            if (keyword_shape_record(K, &rec, scene, kind) != 0)
                return -1;
        } else {
            keyword_fail_keyword(K, &rec);
            return -1;
        }
    }
    if (rc == 0 && !K->camera_line) {
        lex_fail_eof(&K->lex, "a camera line", "camera x0 y0 z0 xA yA zA alpha width height");
        return -1;
    }
    return rc;
}

int keyword_parse_text(const char *name, const char *text, size_t len, size_t memory_limit,
                       Scene *scene, SceneSource *source, Error *err)
{
    Keyword K;
    int rc;

    scene_init(scene);
    source_init(source);
    scene->memory_limit = memory_limit;
    scene->format = SCENE_KEYWORD;
    lex_init(&K.lex, name, text, len, err);
    K.camera_line = K.ambient_line = K.background_line = 0;
    K.gi_line = K.gicache_line = 0;
    K.source = source;
    names_init(&K.names);
    rc = keyword_elements(&K, scene);
    names_free(&K.names);
    if (rc != 0) {
        scene_free(scene);
        source_free(source);
        return -1;
    }
    if (!scene->has_ambient)
        /* Without an ambient line, each light also lights the scene
         * indirectly, with its colour times its intensity. */
        for (size_t i = 0; i < scene->light_count; i++) {
            const Light *l = &scene->lights[i];
            scene->ambient = colour_add(scene->ambient, colour_scale(l->colour, l->intensity));
        }
    scene_fit_scale(scene);
    return 0;
}
