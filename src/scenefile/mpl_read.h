/*
 * mpl_read.h: the MPL reader's state and the steps that share it (private
 * to scenefile/; mpl.h is the reader's contract):
 *   mpl_fields.c    fields and the MPL ray tracer's spellings: words in any case,
 *                   stray commas and float suffixes, lenient lines read
 *                   with a warning
 *   mpl_settings.c  the 'c' lines: camera, background or sky, ambient
 *                   light, samples, AO and GI, noise, model
 *   mpl.c           the whole: materials, primitives, lights, and the
 *                   lines in order (it calls the others, none calls it)
 */
#ifndef RAYTRACE_MPL_READ_H
#define RAYTRACE_MPL_READ_H

#include "base/error.h"
#include "scene/scene.h"
#include "scenefile/lex.h"
#include "scenefile/names.h"
#include "scenefile/source.h"

/* The reader's state. */
typedef struct {
    Lexer lex;           /* the cursor over the input */
    SceneSource *source; /* its camera line as written */
    int camera_line;     /* line of each setting, 0 before it */
    int background_line; /* (Background or Sky) */
    int ambient_line;
    int samples_line;
    int ao_line;         /* (c AO, c GI) */
    int gi_line;
    int model_line;
    int noise_line;
    int gicache_line;
    Names names;         /* the materials by name */
    int strict;          /* 1: lines the MPL ray tracer read leniently are
                            errors; 0: read as it did, with a warning */
} Mpl;

/* Records a fault at column of line. */
#define mpl_fail(M, line, column, ...) lex_fail(&(M)->lex, line, column, __VA_ARGS__)

/* Says whether token t spells word in any case. */
int mpl_word_is(const Token *t, const char *word);

/* Writes the MPL ray tracer's spellings of numbers as plain ones in rec: stray
 * commas before or after a field, or standing alone, go; so does a C float
 * literal's 'f' ("1.f", "0.5f"). The tokens keep the column of their first
 * character. */
void mpl_clean(Record *rec);

/* Records that rec's element could not be stored, scene_add_*() having
 * returned rc; returns -1. */
int mpl_fail_memory(Mpl *M, const Record *rec, const Scene *scene, long rc);

/* Checks that rec has a token at k, what the record needs there;
 * returns 0, or -1 with "expected WHAT (SYNTAX), found the end of the
 * line" recorded. */
int mpl_need(Mpl *M, const Record *rec, int k, const char *what, const char *syntax);

/* Keeps a warning at column of rec's line: a line the MPL ray tracer read,
 * read here as it read it; returns 0, or -1 with the fault recorded when
 * memory runs out. */
int mpl_warn(Mpl *M, Scene *scene, const Record *rec, int column, const char *fmt, ...)
    ERROR_FORMAT(5, 6);

/* Reads tokens first .. first + count - 1 of rec that are not numbers but
 * start with one followed by a letter ("1.5abc") as the MPL ray tracer
 * did, up to the letter, with a warning each (not when strict); returns 0,
 * or -1 when memory runs out. */
int mpl_number_prefixes(Mpl *M, Scene *scene, Record *rec, int first, int count);

/* Leaves out, with a warning (not when strict), rec's tokens from keep on:
 * what the MPL ray tracer did not read ("2 words after the material's
 * name": noun "word", after "after the material's name"); returns 0, or
 * -1 when memory runs out. */
int mpl_ignore_rest(Mpl *M, Scene *scene, Record *rec, int keep, const char *noun,
                    const char *after);

/* setting -> 'c' Camera ... | Background r g b | Sky r g b r g b | Ambient r g b
 *          | Samples n | AO n [distance] | GI n [bounces] | Model name
 *          | Noise level [min [max]] */
int mpl_setting_record(Mpl *M, const Record *rec, Scene *scene);

#endif
