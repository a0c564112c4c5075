/*
 * scene.h: everything a render needs, as the parser builds it.
 *
 * A Scene owns its arrays of lights, shapes and textures; scene_free()
 * releases them. Shapes keep the order of the scene file within their kind,
 * and each records its position among all objects, which decides exact ties
 * between hits. Flags say which optional features the scene uses, so that
 * the renderer spends nothing on the others.
 */
#ifndef RAYTRACE_SCENE_H
#define RAYTRACE_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "geometry/shape_list.h"
#include "math/colour.h"
#include "math/vec3.h"
#include "scene/camera.h"
#include "scene/texture.h"

typedef struct {
    Vec3 position;    /* a point light: where it is, scene units; a distant
                         light: the direction its light travels, as written */
    Colour colour;    /* Cs, 0..255 per channel */
    int distant;      /* 1: a distant light (keyword and MPL formats) */
    double intensity; /* i: the named materials' lights are scaled by it */
    Vec3 to_light;    /* a distant light: unit vector towards it */
    int falloff;      /* 1: a point light whose strength falls off as
                         i / d^2, and to 0 at range (shade.h) */
    double range;     /* with falloff: no light at distance range or
                         beyond, scene units; 0 for no limit */
} Light;

/* Returns the point light at position of colour c. */
static inline Light light_point(Vec3 position, Colour c)
{
    Light light = {position, c, 0, 0, {0, 0, 0}, 0, 0};
    return light;
}

/* A scene's shapes of one kind: count of them, room for capacity, of the
 * kind's type (Sphere, Plane, ...: scene_spheres() and the like read
 * them); items is NULL when there are none. */
typedef struct {
    void *items;
    size_t count;
    size_t capacity;
} ShapeArray;

/* The most ambient occlusion or global illumination rays a point casts,
 * and the most diffuse bounces gathered. */
enum { SCENE_MAX_INDIRECT = 4096, SCENE_MAX_BOUNCES = 64 };
enum { SCENE_MAX_SPP = 1 << 20 }; /* most samples a pixel under --noise */
/* The irradiance cache's accuracy (render/gicache.h): least and most. */
#define SCENE_GI_CACHE_MIN_ERROR 0.01
#define SCENE_GI_CACHE_MAX_ERROR 2.0

/* The scene formats raytrace reads; SCENE_AUTO asks the loader to tell
 * them apart by content. */
typedef enum { SCENE_AUTO = -1, SCENE_COURSE, SCENE_KEYWORD, SCENE_MPL } SceneFormat;

/* How a scene's picture is made from it: which rules light its surfaces
 * and how its colours become bytes. */
typedef enum {
    SCENE_MODEL_PHYSICAL, /* the course's rule and Blinn-Phong (trace.h,
                             shade.h), ambient occlusion of the ambient light
                             and gathered light (trace.h); linear bytes */
    SCENE_MODEL_MPL   /* the MPL ray tracer's rules (mpl_light.h): its
                             lighting, occlusion and gathering; bytes
                             encoded with gamma 2.2 */
} SceneModel;

/* Where a texture and stripes fall on each shape (texture coordinates). */
typedef enum {
    SCENE_MAPPING_OURS,   /* each shape's own (the geometry headers) */
    SCENE_MAPPING_MPL /* the MPL ray tracer's conventions (mapping.h) */
} SceneMapping;

struct Bvh;

typedef struct Scene {
    Camera camera;          /* eye, screen, image size and lens */
    Colour background;      /* seen where a ray hits nothing, 0..255 (with a
                               sky: seen looking straight down) */
    Colour sky;             /* with has_sky, seen looking straight up, and
                               blended linearly with the background by the
                               direction's y in between (the MPL ray tracer's sky) */
    int has_sky;            /* the background is that gradient */
    Colour ambient;         /* course: Ca, added to every lit surface, 0 by
                               default; keyword: Ia, the ambient record or
                               else the sum of i Cs over the lights */
    int has_ambient;        /* an ambient record set it */
    Light *lights;          /* course: lights[0] is the header's light */
    size_t light_count;     /* lights in use, >= 1 once a course scene is
                               parsed */
    size_t light_capacity;  /* lights allocated */
    ShapeArray shapes[SHAPE_KINDS]; /* each kind's (shape_list.h), in
                               file order (but scene_build_accel()'s
                               spheres) */
    Material *materials;    /* the triangles' (spheres and planes hold
                               their own) */
    size_t material_count;
    size_t material_capacity;
    TriangleShading *shading; /* the triangles' that have texture
                               coordinates or vertex normals */
    size_t shading_count;
    size_t shading_capacity;
    Texture *textures;      /* one per distinct texture file */
    size_t texture_count;
    size_t texture_capacity;
    NamedMaterial *named;   /* the keyword and MPL formats' named materials */
    size_t named_count;
    size_t named_capacity;
    Error *warnings;        /* what the reader assumed of lines it read
                               leniently (the MPL ray tracer's ways), for
                               the command to say; at most SCENE_WARNINGS_MAX */
    size_t warning_count;
    size_t warnings_dropped; /* warnings past SCENE_WARNINGS_MAX, counted */
    SceneFormat format;     /* the format it was read from */
    SceneModel model;       /* the rules its picture is made by: the MPL
                               format's default is SCENE_MODEL_MPL, the
                               others' SCENE_MODEL_PHYSICAL */
    SceneMapping mapping;   /* its texture coordinates: the MPL format's
                               are the MPL ray tracer's */
    struct Bvh *accel;      /* hierarchy over the bounded shapes
                               (shape_list.h), or NULL: every ray then
                               tests every object */
    struct LightBuffer *eye_buffer; /* the primary rays' light buffer
                               (light_buffer.h) around a pinhole eye, or
                               NULL: they walk the hierarchy */
    struct LightBuffer *light_buffers; /* light_count of them, each point
                               light's shadow rays' (empty, first NULL, when
                               it has none), or NULL: none */
    unsigned kinds;         /* bit k set: the scene holds shapes of ShapeKind
                               k (so the loops pass over absent kinds) */
    int has_transparency;   /* some object has T > 0 */
    int filter_override;    /* the filter scene_set_texture_filter() gave
                               every texture and stripes, or -1 */
    int reads_footprint;    /* some material reads a texture or stripes by
                               an averaging filter (material.h): the
                               tracer then carries ray differentials
                               (scene_filter.h sets it) */
    int samples;            /* samples per pixel a samples: record asks for,
                               0 when the scene does not say */
    int ao_samples;         /* ambient occlusion rays the scene asks for
                               (the MPL ray tracer's c AO), 0: none; -1 when it does
                               not say */
    double ao_distance;     /* their distance, in the file's units; 0: not
                               said */
    int gi_samples;         /* global illumination rays it asks for (c GI);
                               -1 when it does not say */
    int gi_bounces;         /* their bounces; 0: not said */
    int gi_cache;           /* 1: their light through the irradiance cache
                               (MPL c GICache, keyword gicache) */
    double gi_cache_error;  /* its accuracy; 0: not said */
    double noise;           /* the error a pixel may keep (MPL c Noise;
                               render/noise.h), levels; 0: not said */
    int noise_min_spp;      /* its least and most samples a pixel, 1 to
                               SCENE_MAX_SPP; 0: not said */
    int noise_max_spp;
    int length_exponent;    /* every length above is the scene file's times
                               2^length_exponent: 0 unless scene_fit_scale()
                               (scale.h)
                               enlarged a tiny scene */
    size_t memory_limit;    /* bytes the scene's arrays, meshes being read and
                               hierarchy may take together; 0: no limit */
    uint64_t source_hash;   /* fingerprint of what it was read from: its
                               texture texels, mesh files and, once read
                               (load.h), its text and format */
} Scene;

/* The scene's spheres and triangles, and its shapes of each kind (of the
 * kind's type), as arrays. */
static inline Sphere *scene_spheres(const Scene *scene)
{
    return (Sphere *)scene->shapes[SHAPE_SPHERE].items;
}
static inline Triangle *scene_triangles(const Scene *scene)
{
    return (Triangle *)scene->shapes[SHAPE_TRIANGLE].items;
}
static inline Plane *scene_planes(const Scene *scene)
{
    return (Plane *)scene->shapes[SHAPE_PLANE].items;
}
static inline void *scene_items(const Scene *scene, ShapeKind kind)
{
    return scene->shapes[kind].items;
}

/* Returns how many shapes of kind the scene holds. */
static inline size_t scene_count_of(const Scene *scene, ShapeKind kind)
{
    return scene->shapes[kind].count;
}

/* What scene_add_*() and scene_build_accel() return when the memory limit
 * would be passed (-1 is for memory running out). */
#define SCENE_OVER_LIMIT (-2)

/* Makes *scene an empty scene that owns nothing. */
void scene_init(Scene *scene);

/* Releases what *scene owns and leaves it empty. */
void scene_free(Scene *scene);

/* Each scene_add_*() appends a copy of its argument, giving a shape its
 * position among the scene's objects (a sphere the material *m, in the
 * scene's table when it is not plain, shared with the sphere before when
 * that one's is the same; a triangle a material of its own,
 * a copy of *m, and no shading: scene_shade_triangle() gives it some);
 * returns 0, or -1 when memory runs out or SCENE_OVER_LIMIT when it would
 * pass the memory limit, the scene unchanged. */
int scene_add_light(Scene *scene, const Light *light);
int scene_add_sphere(Scene *scene, Vec3 centre, real radius, const Material *m);
int scene_add_triangle(Scene *scene, const Triangle *t, const Material *m);

/* Appends a copy of *shape, a shape of kind that holds its material
 * (shape_list.h), as scene_add_*() do. */
int scene_add_shape(Scene *scene, ShapeKind kind, const void *shape);

/* Appends a copy of *shape, of any kind, with material *m (a kind that
 * holds its material has it already), as scene_add_*() do. */
int scene_add_any(Scene *scene, ShapeKind kind, const void *shape, const Material *m);

/* Appends n >= 1 spheres of plain materials (sphere_plain()) at once, as n
 * calls of scene_add_sphere() would (the same room; their positions among
 * the objects set here): fill(room, ctx) writes their centres and radii
 * into room, and their materials with sphere_set_plain(), on any threads,
 * and returns 0. Returns 0, or
 * what fill() returned (non-zero), -1 or SCENE_OVER_LIMIT, with the scene
 * as it was, when fill() or one of those calls would fail. */
int scene_add_spheres(Scene *scene, size_t n, int (*fill)(Sphere *room, void *ctx), void *ctx);

/* Gives triangle i the shading *sh (in an entry of the scene's shading of
 * its own); returns 0, -1 when memory runs out or SCENE_OVER_LIMIT, the
 * triangle unchanged. */
int scene_shade_triangle(Scene *scene, size_t i, const TriangleShading *sh);

/* Returns the material of tri, a triangle of scene (writable: the parser's
 * texture records set it). */
static inline Material *scene_material_of(const Scene *scene, const Triangle *tri)
{
    return &scene->materials[tri->material];
}

/* Returns the position among the scene's objects of shape index of kind. */
unsigned scene_order_of(const Scene *scene, ShapeKind kind, size_t index);

/* A walk over the scene's shapes in the order of the file. */
typedef struct {
    size_t next[SHAPE_KINDS]; /* the next of each kind */
} SceneWalk;

/* Starts *w at the scene's first shape. */
void scene_walk_start(SceneWalk *w);

/* Stores in *kind and *index the next shape of w in file order and
 * returns 1, or returns 0 when there are no more. */
int scene_walk_next(const Scene *scene, SceneWalk *w, ShapeKind *kind, size_t *index);

/* Returns where the material of shape index of kind, not a sphere, is
 * held. */
Material *scene_shape_material(const Scene *scene, ShapeKind kind, size_t index);

/* Returns the material of the shape of kind and index in scene. Inline:
 * every ray that hits something asks. */
static inline Material scene_material(const Scene *scene, ShapeKind kind, size_t index)
{
    const Sphere *s;

    if (kind != SHAPE_SPHERE)
        return *scene_shape_material(scene, kind, index);
    s = &scene_spheres(scene)[index];
    return s->plain ? sphere_material(s) : scene->materials[s->material.index];
}

/* Returns the material of the shape of kind and index in scene, to be
 * changed (the readers' texture records set it; a mesh's triangles share
 * one), valid until the next shape or material is added; a sphere is
 * first given a copy of its own in the scene's table. Returns NULL, the
 * scene unchanged, when that needs memory there is not (SCENE_OVER_LIMIT
 * or -1 in *rc). */
Material *scene_material_edit(Scene *scene, ShapeKind kind, size_t index, int *rc);

/* Returns tri's shading, a triangle of scene, or NULL when it is plain. */
static inline const TriangleShading *scene_shading_of(const Scene *scene, const Triangle *tri)
{
    return tri->shading == TRIANGLE_PLAIN ? NULL : &scene->shading[tri->shading];
}

/* Appends *m to the triangles' materials; returns its index, or -1 when
 * memory runs out or SCENE_OVER_LIMIT. */
long scene_add_material(Scene *scene, const Material *m);

/* Appends a copy of *t with the material of index material and, unless sh
 * is NULL, the shading *sh; returns 0, or -1 or SCENE_OVER_LIMIT with the
 * scene unchanged. */
int scene_append_triangle(Scene *scene, const Triangle *t, size_t material,
                          const TriangleShading *sh);

/* Appends up to n triangles at once, each with a shading entry when shaded
 * is set: fill(tris, sh, ctx) writes them into room for n (sh NULL when
 * not shaded), on any threads, the kept ones first, and returns how many
 * it kept (at most n), or more than n when it fails. Their material
 * indices are fill's plus `material`; their positions among the objects
 * and shading indices are set here, and the arrays' capacities are those
 * that adding the kept ones one by one would make. Returns how many were
 * added, or -1 or SCENE_OVER_LIMIT with the scene as it was. */
long scene_add_triangles(Scene *scene, size_t n, size_t material, int shaded,
                         size_t (*fill)(Triangle *tris, TriangleShading *sh, void *ctx),
                         void *ctx);

/* Appends *m, taking ownership of its name and texture name (freed on
 * failure); returns its
 * index, or -1 when memory runs out. */
int scene_add_named(Scene *scene, NamedMaterial *m);

enum { SCENE_WARNINGS_MAX = 100 }; /* warnings kept; the rest are counted */

/* Keeps warning *w (a position and a message, as an error has) for the
 * command to say, or counts it past SCENE_WARNINGS_MAX; returns 0, or -1
 * when memory runs out. */
int scene_add_warning(Scene *scene, const Error *w);

/* Takes ownership of *tex as the scene's next texture; returns its index, or
 * -1 (tex released) when memory runs out. */
int scene_add_texture(Scene *scene, Texture *tex);

/* Returns the bytes the scene holds: its arrays at their capacity, its
 * textures' texels and its hierarchy. */
size_t scene_memory(const Scene *scene);

/* Returns the budget to give obj_load() for a mesh of this scene: the bytes
 * left under the limit (at least 1), or 0 without a limit. */
size_t scene_obj_budget(const Scene *scene);

/* Returns the bytes of the limit left for more (SIZE_MAX without a limit,
 * 0 once it is used up). */
size_t scene_memory_left(const Scene *scene);

/* Sets bytes of the memory limit aside for what the scene's render needs
 * besides the scene (its image): what is added later, and the hierarchy,
 * must fit in what is left. Returns 0, or SCENE_OVER_LIMIT (nothing set
 * aside) when the scene already leaves less than that. */
int scene_set_aside(Scene *scene, size_t bytes);

/* Returns the number of objects (shapes) in the scene. */
size_t scene_object_count(const Scene *scene);

/* Returns the scene's size: the diagonal of the box around its bounded
 * objects and the points that place its unbounded ones (a plane's point, a
 * cylinder's centre, a cone's circle and apex), or, with none, around the
 * camera and its screen. */
double scene_size(const Scene *scene);

/* Says whether scene is drawn by the MPL ray tracer's rules (its model),
 * which its texture coordinates follow too (mapping.h); the lighting
 * models' other choices are render/model.h's. */
static inline int scene_mpl_light_rules(const Scene *scene)
{
    return scene->model == SCENE_MODEL_MPL;
}

#endif
