/*
 * mpl.c: the MPL ray tracer's MPL scene format (see mpl.h, docs/scene-format.md).
 * Lines, comments and numbers follow lex.h, with C float literals and
 * stray commas allowed.
 *
 *   scene     -> line*                 (materials before the shapes that use them)
 *   material  -> 'm' name kind r g b stripes index glossiness texture
 *   kind      -> MATTE | PLASTIC | METALLIC | DIELECTRIC       (any case)
 *   primitive -> 'p' shape number* material
 *   shape     -> Sphere | Plane | Triangle | Tri | Cube | Square | Cylinder | Cone
 *   light     -> 'l' DirectionLight dx dy dz r g b i
 *              | 'l' PointLight x y z r g b i [range]
 *   setting   -> 'c' Camera px py pz tx ty tz fov width height    (at most once)
 *              | 'c' Background r g b | 'c' Sky r g b r g b        (one of them)
 *              | 'c' Ambient r g b | 'c' Samples n                 (each at most once)
 *              | 'c' AO n [distance] | 'c' GI n [bounces]          (each at most once)
 *              | 'c' Model mpl | 'c' Model physical          (at most once)
 *
 * Colours are 0 to 1 (scaled to the renderer's 0 to 255).
 */
#include "scenefile/mpl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "math/angle.h"
#include "math/number.h"
#include "scene/scale.h"
#include "scenefile/lex.h"
#include "scenefile/names.h"
#include "scenefile/shapes.h"
#include "scenefile/texture_file.h"
#include "mpl_read.h"

/* The MPL ray tracer's reader's order (its SceneReader and Material): the 7th field
 * is the refractive index ("indice"), the 8th the glossiness. */
static const char *const mpl_material_names[] = {"red",   "green",      "blue",
                                                 "stripes", "index", "glossiness"};
static const FieldKind mpl_material_kinds[] = {FIELD_FRACTION, FIELD_FRACTION,    FIELD_FRACTION,
                                               FIELD_COORD,    FIELD_NONNEGATIVE, FIELD_NONNEGATIVE};
static const char *const mpl_light_names[] = {"x",    "y",         "z",    "red",
                                              "green", "blue", "intensity", "range"};
static const FieldKind mpl_light_kinds[] = {FIELD_COORD,    FIELD_COORD,    FIELD_COORD,
                                            FIELD_FRACTION, FIELD_FRACTION, FIELD_FRACTION,
                                            FIELD_NONNEGATIVE, FIELD_NONNEGATIVE};
static const char *const mpl_tri_names[] = {"size", "x", "y", "z"};
static const FieldKind mpl_tri_kinds[] = {FIELD_POSITIVE, FIELD_COORD, FIELD_COORD, FIELD_COORD};

static const RecordSpec mpl_material = {
    "the material", "m name kind r g b stripes index glossiness texture", 6, 0, 0,
    mpl_material_names, mpl_material_kinds};
static const RecordSpec mpl_direction = {"the directional light", "dx dy dz r g b intensity", 7,
                                         0, 0, mpl_light_names, mpl_light_kinds};
static const RecordSpec mpl_point = {"the point light", "x y z r g b intensity [range]", 7, 1, 0,
                                     mpl_light_names, mpl_light_kinds};
/* The shapes a primitive line names, and the numbers each takes: the
 * kind's own (shape.h), but the Tri's. */
typedef struct {
    const char *word; /* as the MPL ray tracer writes it; any case */
    ShapeKind kind;
    const char *syntax; /* its numbers and material, for messages */
} MplShape;

static const MplShape mpl_shapes[] = {
    {"Sphere", SHAPE_SPHERE, "cx cy cz radius material"},
    {"Plane", SHAPE_PLANE, "px py pz nx ny nz material"},
    {"Triangle", SHAPE_TRIANGLE, "x1 y1 z1 x2 y2 z2 x3 y3 z3 material"},
    {"Tri", SHAPE_TRIANGLE, "size x y z material"},
    {"Cube", SHAPE_CUBE, "cx cy cz size material"},
    {"Square", SHAPE_SQUARE, "cx cy cz nx ny nz size material"},
    {"Cylinder", SHAPE_CYLINDER, "cx cy cz radius material"},
    {"Cone", SHAPE_CONE, "x y z radius height material"},
};

enum { MPL_SHAPES = sizeof mpl_shapes / sizeof mpl_shapes[0] };

static const char *const mpl_kinds[] = {"MATTE", "PLASTIC", "METALLIC", "DIELECTRIC"};

/* Returns the path of texture token t, as texture_file_find() finds it
 * from the scene's folder in the folders the MPL ray tracer looks in:
 * Textures beside the scene (or textures, the same on a system that
 * ignores case), and Textures beside the scene's folder (its repository
 * keeps Scene/ and Textures/ side by side); NULL with the fault recorded
 * when memory runs out. */
static char *mpl_texture_path(Mpl *M, const Token *t)
{
    static const char *const folders[] = {"Textures/", "textures/", "../Textures/"};
    char *path = texture_file_find(M->lex.name, t->text, t->len, folders, 3);

    if (!path)
        error_set(M->lex.err, M->lex.name, "out of memory");
    return path;
}

/* Sets what the material kind `model` shades with under the physical
 * model (docs/scene-format.md): the weights of the Blinn-Phong term, a
 * highlight wherever the glossiness is above 0 (the MPL ray tracer's rule), and the
 * index its glass and clear coat bend and reflect with. */
static void mpl_model(NamedMaterial *pm, ShadingModel model, double index, double glossiness)
{
    Material *b = &pm->base;
    int diffuse = model == MODEL_MATTE || model == MODEL_PLASTIC;
    double ior = model == MODEL_PLASTIC || model == MODEL_DIELECTRIC ? index : 1;
    double f0 = (ior - 1) / (ior + 1);

    pm->model = model;
    pm->ka = pm->kd = diffuse ? 1 : 0;
    pm->ks = glossiness > 0 ? 1 : 0;
    pm->shininess = glossiness;
    pm->index = index;
    b->ior = ior;
    /* Shadows through glass: what crosses one surface head on, 1 - F(0),
     * times the mean of its tint. */
    if (model == MODEL_DIELECTRIC)
        b->transparency = (1 - f0 * f0) * (b->colour.r + b->colour.g + b->colour.b) / (3 * 255);
}

/* Checks the fields of material record rec past its texture (the MPL ray tracer's
 * layout ends there, ours may add the filter its texture or stripes are
 * read with, stored in *filter); returns 0, or -1 with the fault recorded: a number
 * there is the layout raytrace's --save wrote before it followed the
 * MPL ray tracer's reader (a highlight weight 7th, the index 11th), which would be
 * misread. */
static int mpl_material_end(Mpl *M, const Record *rec, TextureFilter *filter)
{
    double ignored;
    char q[64];

    if (rec->count <= 10 || (rec->count == 11 && lex_filter_word(&rec->tok[10], filter)))
        return 0;
    if (rec->count == 11 &&
        number_parse(rec->tok[10].text, rec->tok[10].len, &ignored) == NUMBER_OK) {
        mpl_fail(M, &rec->line, rec->tok[10].column,
                 "the material has an 11th field, %s: the MPL ray tracer's layout ends with the texture "
                 "(m name kind r g b stripes index glossiness texture); raytrace 0.1's --save "
                 "wrote a highlight weight 7th and the index last: move the index to the 7th "
                 "field and drop this one",
                 lex_quote(q, sizeof q, &rec->tok[10]));
        return -1;
    }
    if (rec->count == 11) {
        mpl_fail(M, &rec->line, rec->tok[10].column,
                 "unknown texture filter %s after the material's texture (expected nearest, "
                 "bilinear, trilinear or ewa)",
                 lex_quote(q, sizeof q, &rec->tok[10]));
        return -1;
    }
    return lex_fail_extra(&M->lex, rec, 11, "the material's filter");
}

/* Reads texture token tex of material record rec into *pm: N (or n) for
 * none, else a file found as the MPL ray tracer found it; returns 0, or
 * -1 with the fault recorded. */
static int mpl_material_texture(Mpl *M, const Record *rec, Scene *scene, const Token *tex,
                                NamedMaterial *pm)
{
    char *path;
    Error inner;
    int t;

    if (tex->len == 1 && (tex->text[0] == 'N' || tex->text[0] == 'n'))
        return 0;
    path = mpl_texture_path(M, tex);
    if (!path)
        return -1;
    t = texture_file_add(scene, path, &inner);
    free(path);
    if (t == TEXTURE_FILE_FAULT) {
        lex_fail_file(&M->lex, rec, tex, "texture", &inner);
        return -1;
    }
    if (t < 0)
        return mpl_fail_memory(M, rec, scene, t);
    pm->base.texture = t;
    pm->texture = malloc(tex->len + 1);
    if (!pm->texture)
        return mpl_fail_memory(M, rec, scene, -1);
    memcpy(pm->texture, tex->text, tex->len);
    pm->texture[tex->len] = '\0';
    return 0;
}

/* material -> 'm' name kind r g b stripes index glossiness texture [filter] */
static int mpl_material_record(Mpl *M, const Record *line, Scene *scene)
{
    Record copy = *line, *rec = &copy;
    const char *syntax = mpl_material.syntax;
    double v[6] = {0, 0, 0, 0, 0, 0};
    const Token *name, *kind, *tex;
    NamedMaterial pm;
    char q[64];
    int model = -1, index;
    /* Ours: textures and stripes read over each pixel's footprint unless
     * the line says otherwise. */
    TextureFilter filter = TEXTURE_TRILINEAR;

    if (mpl_need(M, rec, 1, "the material's name", syntax) != 0)
        return -1;
    name = &rec->tok[1];
    if (names_find(&M->names, scene, name) >= 0) {
        int first = scene->named[names_find(&M->names, scene, name)].line;
        if (!M->strict)
            return mpl_warn(M, scene, rec, name->column,
                            "the material %s is already defined, on line %d: kept that one, "
                            "this line changes nothing",
                            lex_quote(q, sizeof q, name), first);
        mpl_fail(M, &rec->line, name->column, "the material %s is already defined, on line %d",
                 lex_quote(q, sizeof q, name), first);
        return -1;
    }
    if (mpl_need(M, rec, 2, "the material's kind", syntax) != 0)
        return -1;
    kind = &rec->tok[2];
    for (int k = 0; k < 4; k++)
        if (mpl_word_is(kind, mpl_kinds[k]))
            model = MODEL_MATTE + k;
    if (model < 0) {
        mpl_fail(M, &rec->line, kind->column,
                 "unknown material kind %s (expected MATTE, PLASTIC, METALLIC or DIELECTRIC)",
                 lex_quote(q, sizeof q, kind));
        return -1;
    }
    if (mpl_number_prefixes(M, scene, rec, 3, 6) != 0)
        return -1;
    for (int k = 0; k < 6; k++)
        if (mpl_need(M, rec, 3 + k, "a number for the material", syntax) != 0 ||
            lex_number(&M->lex, rec, 3 + k, &mpl_material, k, &v[k]) != 0)
            return -1;
    if (v[3] != 0 && v[3] != 1) {
        mpl_fail(M, &rec->line, rec->tok[6].column,
                 "the material's stripes must be 0 (a plain colour) or 1 (stripes), found %s",
                 lex_quote(q, sizeof q, &rec->tok[6]));
        return -1;
    }
    if ((model == MODEL_PLASTIC || model == MODEL_DIELECTRIC) && !(v[4] > 0)) {
        mpl_fail(M, &rec->line, rec->tok[7].column,
                 "the %s material's index must be positive (glass: about 1.5), found %s",
                 mpl_kinds[model - MODEL_MATTE], lex_quote(q, sizeof q, &rec->tok[7]));
        return -1;
    }
    if (mpl_need(M, rec, 9, "the material's texture, a file or N for none", syntax) != 0 ||
        mpl_material_end(M, rec, &filter) != 0)
        return -1;
    tex = &rec->tok[9];
    memset(&pm, 0, sizeof pm);
    pm.base = material_plain(colour(v[0] * 255, v[1] * 255, v[2] * 255), 0);
    pm.base.stripes = v[3] == 1;
    pm.base.filter = filter;
    pm.line = rec->line.number;
    mpl_model(&pm, (ShadingModel)model, v[4], v[5]);
    if (mpl_material_texture(M, rec, scene, tex, &pm) != 0)
        return -1;
    pm.name = malloc(name->len + 1);
    if (!pm.name) {
        free(pm.texture);
        return mpl_fail_memory(M, rec, scene, -1);
    }
    memcpy(pm.name, name->text, name->len);
    pm.name[name->len] = '\0';
    index = scene_add_named(scene, &pm);
    if (index < 0)
        return mpl_fail_memory(M, rec, scene, index);
    scene->named[index].base.named = index;
    return names_add(&M->names, scene, (size_t)index) != 0 ? mpl_fail_memory(M, rec, scene, -1)
                                                           : 0;
}

/* Reads the material name at token k of primitive rec as the MPL ray tracer's
 * program did (not when strict), each time with a warning: the words
 * after it ignored; an unknown name read as the first material's (when
 * there is one). Returns 0, or -1 when memory runs out. */
static int mpl_lenient_material(Mpl *M, Scene *scene, Record *rec, int k)
{
    Token *name = &rec->tok[k];
    double ignored;
    char q[64];

    if (M->strict || rec->count <= k || k >= LEX_MAX_TOKENS ||
        number_parse(name->text, name->len, &ignored) != NUMBER_SYNTAX)
        return 0; /* not a name where one goes: its own error */
    if (mpl_ignore_rest(M, scene, rec, k + 1, "word", "after the material's name") != 0)
        return -1;
    if (names_find(&M->names, scene, name) >= 0 || scene->named_count == 0)
        return 0;
    if (mpl_warn(M, scene, rec, name->column, "unknown material %s: read as the first one, '%s'",
                 lex_quote(q, sizeof q, name), scene->named[0].name) != 0)
        return -1;
    name->text = scene->named[0].name;
    name->len = strlen(scene->named[0].name);
    return 0;
}

/* primitive -> 'p' shape number* material */
static int mpl_primitive_record(Mpl *M, const Record *line, Scene *scene)
{
    Record copy = *line, *rec = &copy;
    const MplShape *shape = NULL;
    ShapesSpec numbers;
    RecordSpec spec;
    double v[SHAPE_NUMBERS_MAX];
    const char *fault = NULL;
    int rc, field = 0, n;
    Material m;
    char q[64];

    if (mpl_need(M, rec, 1, "the primitive's shape",
                 "Sphere, Plane, Triangle, Tri, Cube, Square, Cylinder or Cone") != 0)
        return -1;
    for (int k = 0; k < MPL_SHAPES; k++)
        if (mpl_word_is(&rec->tok[1], mpl_shapes[k].word))
            shape = &mpl_shapes[k];
    if (!shape) {
        mpl_fail(M, &rec->line, rec->tok[1].column,
                 "unknown primitive %s (expected Sphere, Plane, Triangle, Tri, Cube, Square, "
                 "Cylinder or Cone)",
                 lex_quote(q, sizeof q, &rec->tok[1]));
        return -1;
    }
    shapes_spec(&numbers, shape->kind, "material", 0, 0, NULL, NULL);
    spec = numbers.spec;
    spec.syntax = shape->syntax;
    if (strcmp(shape->word, "Tri") == 0) { /* size x y z: a triangle below */
        spec.count = 4;
        spec.names = mpl_tri_names;
        spec.kinds = mpl_tri_kinds;
    }
    n = spec.count;
    if (mpl_number_prefixes(M, scene, rec, 2, n) != 0 || mpl_lenient_material(M, scene, rec, 2 + n))
        return -1;
    if (names_numbers_and_material(&M->lex, &M->names, rec, 2, &spec, scene, "an m line", v, &m) !=
        0)
        return -1;
    if (shape->kind == SHAPE_TRIANGLE && n == 4) {
        /* The MPL ray tracer's Tri: size s at (x, y, z), upright in its z
         * plane: (x, y + s/4), (x - s/4, y - s/4), (x + s/4, y - s/4). */
        double s = v[0] / 4, x = v[1], y = v[2], z = v[3];
        double tri[9] = {x, y + s, z, x - s, y - s, z, x + s, y - s, z};
        memcpy(v, tri, sizeof tri);
    }
    rc = shapes_add(scene, shape->kind, v, &m, &fault, &field);
    if (rc == SHAPES_INVALID) {
        mpl_fail(M, &rec->line, rec->tok[field < 0 || n == 4 ? 0 : 2 + field].column, "%s", fault);
        return -1;
    }
    if (rc != 0)
        return mpl_fail_memory(M, rec, scene, rc);
    /* The MPL ray tracer's cone ends at its circle (cone.h). */
    if (shape->kind == SHAPE_CONE)
        ((Cone *)scene_items(scene, SHAPE_CONE))[scene_count_of(scene, SHAPE_CONE) - 1].finite = 1;
    return 0;
}

/* light -> 'l' DirectionLight dx dy dz r g b i | 'l' PointLight x y z r g b i [range] */
static int mpl_light_record(Mpl *M, const Record *line, Scene *scene)
{
    Record copy = *line, *rec = &copy;
    double v[8] = {0};
    Light light;
    int distant, rc, most;
    char q[64];

    if (mpl_need(M, rec, 1, "the light's kind", "DirectionLight or PointLight") != 0)
        return -1;
    distant = mpl_word_is(&rec->tok[1], "DirectionLight") ||
              mpl_word_is(&rec->tok[1], "DirectionalLight");
    if (!distant && !mpl_word_is(&rec->tok[1], "PointLight")) {
        mpl_fail(M, &rec->line, rec->tok[1].column,
                 "unknown light %s (expected DirectionLight or PointLight)",
                 lex_quote(q, sizeof q, &rec->tok[1]));
        return -1;
    }
    most = 2 + (distant ? 7 : 8);
    if (mpl_number_prefixes(M, scene, rec, 2, rec->count - 2) != 0)
        return -1;
    if (rec->count > most) {
        int numbers = most;
        while (numbers < rec->count && numbers < LEX_MAX_TOKENS &&
               number_parse(rec->tok[numbers].text, rec->tok[numbers].len, v) == NUMBER_OK)
            numbers++;
        if (numbers == rec->count &&
            mpl_ignore_rest(M, scene, rec, most, "number", "after the light's") != 0)
            return -1;
    }
    if (lex_numbers(&M->lex, rec, 2, distant ? &mpl_direction : &mpl_point, v) < 0)
        return -1;
    if (distant && v[0] == 0 && v[1] == 0 && v[2] == 0) {
        mpl_fail(M, &rec->line, rec->tok[2].column,
                 "the light's direction is the zero vector: a directional light needs the "
                 "direction its light travels");
        return -1;
    }
    light = light_point(vec3(v[0], v[1], v[2]), colour(v[3] * 255, v[4] * 255, v[5] * 255));
    light.intensity = v[6];
    if (distant) {
        light.distant = 1;
        light.to_light = vec3_neg(vec3_direction(light.position));
    } else {
        light.falloff = 1;
        light.range = v[7];
    }
    rc = scene_add_light(scene, &light);
    return rc != 0 ? mpl_fail_memory(M, rec, scene, rc) : 0;
}

/* scene -> line* */
static int mpl_lines(Mpl *M, Scene *scene)
{
    Record rec;
    int rc;
    char q[64];

    while ((rc = lex_next_record(&M->lex, &rec)) == 1) {
        const Token *t = &rec.tok[0];
        mpl_clean(&rec);
        if (lex_token_is(t, "m"))
            rc = mpl_material_record(M, &rec, scene);
        else if (lex_token_is(t, "p"))
            rc = mpl_primitive_record(M, &rec, scene);
        else if (lex_token_is(t, "l"))
            rc = mpl_light_record(M, &rec, scene);
        else if (lex_token_is(t, "c"))
            rc = mpl_setting_record(M, &rec, scene);
        else {
            mpl_fail(M, &rec.line, t->column,
                     "unknown line %s (expected 'm' a material, 'p' a primitive, 'l' a light or "
                     "'c' a setting)",
                     lex_quote(q, sizeof q, t));
            rc = -1;
        }
        if (rc != 0)
            return -1;
    }
    return rc;
}

int mpl_parse_text(const char *name, const char *text, size_t len, size_t memory_limit, int strict,
                   Scene *scene, SceneSource *source, Error *err)
{
    Mpl M;
    int rc;

    scene_init(scene);
    source_init(source);
    scene->memory_limit = memory_limit;
    scene->format = SCENE_MPL;
    scene->model = SCENE_MODEL_MPL;
    scene->mapping = SCENE_MAPPING_MPL;
    /* The MPL ray tracer's sky: white below, blue above. */
    scene->has_sky = 1;
    scene->sky = colour(0.5 * 255, 0.7 * 255, 255);
    scene->background = colour(255, 255, 255);
    lex_init(&M.lex, name, text, len, err);
    M.camera_line = M.background_line = M.ambient_line = M.samples_line = M.noise_line = 0;
    M.gicache_line = 0;
    M.ao_line = M.gi_line = M.model_line = 0;
    M.strict = strict;
    M.source = source;
    names_init(&M.names);
    rc = mpl_lines(&M, scene);
    names_free(&M.names);
    if (rc == 0 && !source->camera_line) {
        source->look_from = vec3(0, 0, 0);
        source->look_at = vec3(0, 0, 1);
        source->fov = MPL_DEFAULT_FOV;
        rc = camera_look_at(&scene->camera, source->look_from, source->look_at, ANGLE_PI / 2,
                            MPL_DEFAULT_SIZE, MPL_DEFAULT_SIZE) == CAMERA_VIEW_OK
                 ? 0
                 : -1;
    }
    if (rc != 0) {
        scene_free(scene);
        source_free(source);
        return -1;
    }
    if (!M.samples_line)
        scene->samples = MPL_DEFAULT_SAMPLES;
    scene_fit_scale(scene);
    return 0;
}
