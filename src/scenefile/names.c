/* names.c: the named materials' hash table (see names.h). */
#include "scenefile/names.h"

#include <stdlib.h>
#include <string.h>

#include "math/number.h"

/* Returns the FNV-1a hash of the len bytes at s. */
static uint32_t names_hash(const char *s, size_t len)
{
    uint32_t h = 2166136261u;

    for (size_t i = 0; i < len; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h;
}

void names_init(Names *names)
{
    names->slots = NULL;
    names->size = 0;
}

void names_free(Names *names)
{
    free(names->slots);
    names_init(names);
}

int names_find(const Names *names, const Scene *scene, const Token *t)
{
    if (names->size == 0)
        return -1;
    for (size_t i = names_hash(t->text, t->len) & (names->size - 1);;
         i = (i + 1) & (names->size - 1)) {
        uint32_t slot = names->slots[i];
        const char *name;
        if (slot == 0)
            return -1;
        name = scene->named[slot - 1].name;
        if (strlen(name) == t->len && memcmp(name, t->text, t->len) == 0)
            return (int)slot - 1;
    }
}

/* Files material k of scene in the table slots of size slots. */
static void names_put(uint32_t *slots, size_t size, const Scene *scene, size_t k)
{
    const char *name = scene->named[k].name;
    size_t i = names_hash(name, strlen(name)) & (size - 1);

    while (slots[i])
        i = (i + 1) & (size - 1);
    slots[i] = (uint32_t)k + 1;
}

int names_add(Names *names, const Scene *scene, size_t index)
{
    if (2 * (index + 1) > names->size) {
        size_t size = names->size ? 2 * names->size : 64;
        uint32_t *slots = calloc(size, sizeof *slots);
        if (!slots)
            return -1;
        for (size_t k = 0; k < index; k++)
            names_put(slots, size, scene, k);
        free(names->slots);
        names->slots = slots;
        names->size = size;
    }
    names_put(names->slots, names->size, scene, index);
    return 0;
}

/* Says whether token t reads as a number (valid or not: "1e400", "nan"). */
static int names_is_number(const Token *t)
{
    double ignored;

    return number_parse(t->text, t->len, &ignored) != NUMBER_SYNTAX;
}

int names_numbers_and_material(Lexer *L, const Names *names, const Record *rec, int first,
                               const RecordSpec *spec, const Scene *scene, const char *definer,
                               double *values, Material *m)
{
    int fields = rec->count - first, n = spec->count, index;
    const Token *name;
    char q[64];

    for (int i = 0; i < fields && i < n; i++) {
        const Token *t = &rec->tok[first + i];
        if (i == fields - 1 && !names_is_number(t)) {
            /* The name came early: numbers are missing. */
            lex_fail(L, &rec->line, t->column,
                     "expected %d numbers before the material of %s (%s), found %d", n,
                     spec->what, spec->syntax, i);
            return -1;
        }
        if (lex_number(L, rec, first + i, spec, i, &values[i]) != 0)
            return -1;
    }
    if (fields <= n) {
        lex_fail(L, &rec->line, rec->end_column,
                 "expected the name of a material after the numbers of %s (%s), found the end "
                 "of the line",
                 spec->what, spec->syntax);
        return -1;
    }
    name = &rec->tok[first + n];
    if (names_is_number(name)) {
        if (fields > n + 1) {
            int numbers = n + 1;
            while (numbers < fields && first + numbers < LEX_MAX_TOKENS &&
                   names_is_number(&rec->tok[first + numbers]))
                numbers++;
            lex_fail(L, &rec->line, name->column, "expected %d numbers for %s (%s), found %d%s", n,
                     spec->what, spec->syntax, numbers,
                     first + numbers < LEX_MAX_TOKENS ? "" : " or more");
        } else {
            lex_fail(L, &rec->line, name->column,
                     "expected the name of a material for %s (%s), found the number %s",
                     spec->what, spec->syntax, lex_quote(q, sizeof q, name));
        }
        return -1;
    }
    if (fields > n + 1)
        return lex_fail_extra(L, rec, first + n + 1, "the material's name");
    index = names_find(names, scene, name);
    if (index < 0) {
        lex_fail(L, &rec->line, name->column, "unknown material %s: %s must define it before %s",
                 lex_quote(q, sizeof q, name), definer, spec->what);
        return -1;
    }
    *m = scene->named[index].base;
    return 0;
}

