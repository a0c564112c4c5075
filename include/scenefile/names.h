/*
 * names.h: a hash table of the scene's named materials, for the readers
 * whose objects name their material (the keyword and MPL formats): a
 * scene of 10^5 materials is read in linear time.
 */
#ifndef RAYTRACE_NAMES_H
#define RAYTRACE_NAMES_H

#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"
#include "scenefile/lex.h"

typedef struct {
    uint32_t *slots; /* material indices + 1, 0 = free; owned */
    size_t size;     /* slots, a power of two, or 0 */
} Names;

/* Makes *names an empty table. */
void names_init(Names *names);

/* Releases what *names holds. */
void names_free(Names *names);

/* Returns the index in scene->named of the material named by token t, or
 * -1 when there is none. */
int names_find(const Names *names, const Scene *scene, const Token *t);

/* Files material `index` of scene (the last added) under its name, growing
 * the table to keep it at most half full; returns 0, or -1 when memory
 * runs out. */
int names_add(Names *names, const Scene *scene, size_t index);

/* Reads the numbers of spec from rec's token `first` on, then the name of
 * a material as the last field, into values and *m (a copy of the named
 * material); returns 0, or -1 with the fault at the field that is wrong
 * recorded in L (an unknown material's message says `definer`, "a
 * material line", must define it first). */
int names_numbers_and_material(Lexer *L, const Names *names, const Record *rec, int first,
                               const RecordSpec *spec, const Scene *scene, const char *definer,
                               double *values, Material *m);

#endif
