/* mpl_fields.c: the MPL reader's fields and the MPL ray tracer's spellings of them
 * (see mpl_read.h). */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "math/number.h"
#include "mpl_read.h"

int mpl_word_is(const Token *t, const char *word)
{
    size_t n = strlen(word);

    if (t->len != n)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char a = t->text[i], b = word[i];
        if ((a >= 'A' && a <= 'Z' ? a - 'A' + 'a' : a) != (b >= 'A' && b <= 'Z' ? b - 'A' + 'a' : b))
            return 0;
    }
    return 1;
}

/* Says whether the len bytes at s are a C float literal's digits: a
 * number that only its trailing 'f' or 'F' keeps from reading. */
static int mpl_float_suffix(const char *s, size_t len)
{
    double ignored;

    return len >= 2 && (s[len - 1] == 'f' || s[len - 1] == 'F') &&
           number_parse(s, len - 1, &ignored) != NUMBER_SYNTAX;
}

void mpl_clean(Record *rec)
{
    int kept = 0, dropped = 0, stored = rec->count < LEX_MAX_TOKENS ? rec->count : LEX_MAX_TOKENS;

    for (int k = 0; k < stored; k++) {
        Token t = rec->tok[k];
        while (k > 0 && t.len > 0 && t.text[t.len - 1] == ',')
            t.len--;
        while (k > 0 && t.len > 0 && t.text[0] == ',') {
            t.text++;
            t.len--;
            t.column++;
        }
        if (t.len == 0) {
            dropped++;
            continue;
        }
        if (k > 0 && mpl_float_suffix(t.text, t.len))
            t.len--;
        rec->tok[kept++] = t;
    }
    rec->count -= dropped;
}

int mpl_fail_memory(Mpl *M, const Record *rec, const Scene *scene, long rc)
{
    return lex_fail_memory(&M->lex, rec, rc == SCENE_OVER_LIMIT, scene->memory_limit);
}

int mpl_need(Mpl *M, const Record *rec, int k, const char *what, const char *syntax)
{
    if (rec->count > k)
        return 0;
    mpl_fail(M, &rec->line, rec->end_column, "expected %s (%s), found the end of the line", what,
             syntax);
    return -1;
}

int mpl_warn(Mpl *M, Scene *scene, const Record *rec, int column, const char *fmt, ...)
{
    char message[ERROR_MESSAGE_MAX];
    Error w;
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    error_set_at(&w, M->lex.name, rec->line.number, column, rec->line.text, rec->line.len,
                 "%s (as the MPL ray tracer did; --strict refuses it)", message);
    return scene_add_warning(scene, &w) == 0 ? 0 : mpl_fail_memory(M, rec, scene, -1);
}

int mpl_number_prefixes(Mpl *M, Scene *scene, Record *rec, int first, int count)
{
    for (int k = first; !M->strict && k < first + count && k < rec->count && k < LEX_MAX_TOKENS;
         k++) {
        Token *t = &rec->tok[k];
        double v;
        size_t n = t->len;
        char q[64];
        if (number_parse(t->text, t->len, &v) != NUMBER_SYNTAX)
            continue;
        while (n > 0 && (number_parse(t->text, n, &v) != NUMBER_OK ||
                         !isalpha((unsigned char)t->text[n])))
            n--;
        if (n == 0)
            continue; /* no number there: its own error */
        if (mpl_warn(M, scene, rec, t->column + (int)n, "read %s as %.*s, up to its first letter",
                     lex_quote(q, sizeof q, t), (int)n, t->text) != 0)
            return -1;
        t->len = n;
    }
    return 0;
}

int mpl_ignore_rest(Mpl *M, Scene *scene, Record *rec, int keep, const char *noun,
                    const char *after)
{
    int extra = rec->count - keep;

    if (M->strict || extra <= 0 || keep >= LEX_MAX_TOKENS)
        return 0;
    if (mpl_warn(M, scene, rec, rec->tok[keep].column, "ignored %d %s%s %s", extra, noun,
                 extra == 1 ? "" : "s", after) != 0)
        return -1;
    rec->count = keep;
    rec->end_column = rec->tok[keep - 1].column + (int)rec->tok[keep - 1].len;
    return 0;
}
