/* args.c: a command line read by a table of its options (see args.h). */
#include "cli/args.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "math/number.h"

int args_int(const char *text, int lo, int hi, int *out)
{
    long v = 0;

    if (!*text)
        return -1;
    for (const char *p = text; *p; p++) {
        if (*p < '0' || *p > '9')
            return -1;
        v = v * 10 + (*p - '0');
        if (v > hi)
            return -1;
    }
    if (v < lo)
        return -1;
    *out = (int)v;
    return 0;
}

int args_pair(const char *text, char sep, int lo, int hi, int *a, int *b)
{
    const char *s = strchr(text, sep);
    char first[16];
    size_t n = s ? (size_t)(s - text) : 0;

    if (!s || n == 0 || n >= sizeof first)
        return -1;
    memcpy(first, text, n);
    first[n] = '\0';
    return args_int(first, lo, hi, a) == 0 && args_int(s + 1, lo, hi, b) == 0 ? 0 : -1;
}

/* Reads whole digits (at least one) at *p into *out, moving *p past
 * them; returns 0, or -1 when there are none or they overflow. */
static int args_digits(const char **p, size_t *out)
{
    size_t v = 0;

    if (**p < '0' || **p > '9')
        return -1;
    for (; **p >= '0' && **p <= '9'; ++*p) {
        if (v > (SIZE_MAX - 9) / 10)
            return -1;
        v = v * 10 + (size_t)(**p - '0');
    }
    *out = v;
    return 0;
}

int args_size(const char *text, size_t *out)
{
    size_t v, unit = 1;
    const char *p = text;

    if (args_digits(&p, &v) != 0)
        return -1;
    if (*p == 'K' || *p == 'k')
        unit = (size_t)1 << 10;
    else if (*p == 'M' || *p == 'm')
        unit = (size_t)1 << 20;
    else if (*p == 'G' || *p == 'g')
        unit = (size_t)1 << 30;
    if (unit > 1)
        p++;
    if (*p || v > SIZE_MAX / unit)
        return -1;
    *out = v * unit;
    return 0;
}

/* If argv[*i] is option o, as "--name V", "--name=V", "-x V" or "-xV",
 * points *value at V and returns 1 (or -1 when V is missing, with msg
 * set); returns 0 when argv[*i] is another argument. */
static int args_match_value(const ArgSpec *o, int argc, char **argv, int *i, const char **value,
                            char *msg, size_t msg_size)
{
    const char *arg = argv[*i];
    size_t ln = strlen(o->long_name), sn = o->short_name ? strlen(o->short_name) : 0;

    if (strcmp(arg, o->long_name) == 0 || (o->short_name && strcmp(arg, o->short_name) == 0)) {
        if (*i + 1 >= argc) {
            snprintf(msg, msg_size, "option '%s' needs a value", arg);
            return -1;
        }
        *value = argv[++*i];
    } else if (strncmp(arg, o->long_name, ln) == 0 && arg[ln] == '=') {
        *value = arg + ln + 1;
    } else if (o->short_name && strncmp(arg, o->short_name, sn) == 0 && arg[sn] != '\0' &&
               arg[1] != '-') {
        *value = arg + sn;
    } else {
        return 0;
    }
    return 1;
}

/* Writes "option 'NAME' takes W1, W2 or W3, found 'VALUE'" to msg. */
static void args_fail_word(const ArgSpec *o, const char *value, char *msg, size_t msg_size)
{
    size_t n = (size_t)snprintf(msg, msg_size, "option '%s' takes ", o->long_name);
    int count = 0, k = 0;

    for (const ArgWord *w = o->words; w->word; w++)
        count += !w->alias;
    for (const ArgWord *w = o->words; w->word && n < msg_size; w++)
        if (!w->alias) {
            n += (size_t)snprintf(msg + n, msg_size - n, "%s%s",
                                  k == 0 ? "" : k == count - 1 ? " or " : ", ", w->word);
            k++;
        }
    if (n < msg_size)
        snprintf(msg + n, msg_size - n, ", found '%.40s'", value);
}

/* Writes to msg that option o's value is not one it takes. */
static void args_fail(const ArgSpec *o, const char *value, char *msg, size_t msg_size)
{
    switch (o->kind) {
    case ARG_INT:
        snprintf(msg, msg_size, "option '%s' takes a whole number from %d to %d, found '%.40s'",
                 o->long_name, (int)o->lo, (int)o->hi, value);
        break;
    case ARG_COUNT:
        snprintf(msg, msg_size, "option '%s' takes a whole number >= 0, found '%.40s'",
                 o->long_name, value);
        break;
    case ARG_REAL:
        if (isinf(o->hi))
            snprintf(msg, msg_size, "option '%s' takes a number >= %g, found '%.40s'",
                     o->long_name, o->lo, value);
        else
            snprintf(msg, msg_size, "option '%s' takes a number from %g to %g, found '%.40s'",
                     o->long_name, o->lo, o->hi, value);
        break;
    case ARG_SIZE:
        snprintf(msg, msg_size,
                 "option '%s' takes a size in bytes such as 512M or 8G (0: no limit), "
                 "found '%.40s'",
                 o->long_name, value);
        break;
    default: /* ARG_WORD */
        args_fail_word(o, value, msg, msg_size);
    }
}

/* Reads value, the value of option o, into its field of the struct at
 * dest; returns 0, or -1 with msg set when it is not one o takes. */
static int args_store(const ArgSpec *o, const char *value, void *dest, char *msg,
                      size_t msg_size)
{
    char *field = (char *)dest + o->field;
    const char *end = value;
    double v = 0;
    size_t size = 0;
    int n;

    switch (o->kind) {
    case ARG_INT:
        if (args_int(value, (int)o->lo, (int)o->hi, &n) != 0)
            break;
        memcpy(field, &n, sizeof n);
        return 0;
    case ARG_COUNT:
        if (args_digits(&end, &size) != 0 || *end)
            break;
        memcpy(field, &size, sizeof size);
        return 0;
    case ARG_REAL:
        if (number_parse(value, strlen(value), &v) != NUMBER_OK || !(v >= o->lo && v <= o->hi))
            break;
        memcpy(field, &v, sizeof v);
        return 0;
    case ARG_SIZE:
        if (args_size(value, &size) != 0)
            break;
        memcpy(field, &size, sizeof size);
        return 0;
    case ARG_WORD:
        for (const ArgWord *w = o->words; w->word; w++)
            if (strcmp(value, w->word) == 0) {
                memcpy(field, &w->value, sizeof w->value);
                return 0;
            }
        break;
    default: /* ARG_TEXT */
        memcpy(field, &value, sizeof value);
        return 0;
    }
    args_fail(o, value, msg, msg_size);
    return -1;
}

/* Reads the option at argv[*i] (and its value, which may be the next
 * argument) into the struct at dest; returns 0, -1 with msg set, or an
 * ARG_ACT option's act. */
static int args_one(const ArgTable *t, void *dest, int argc, char **argv, int *i, char *msg,
                    size_t msg_size)
{
    const char *arg = argv[*i], *value;

    for (size_t k = 0; k < t->count; k++) {
        const ArgSpec *o = &t->specs[k];
        int m;

        if (o->kind == ARG_ACT || o->kind == ARG_FLAG) {
            if (strcmp(arg, o->long_name) != 0 &&
                !(o->short_name && strcmp(arg, o->short_name) == 0))
                continue;
            if (o->kind == ARG_ACT)
                return o->act;
            *(int *)(void *)((char *)dest + o->field) = 1;
            return 0;
        }
        m = args_match_value(o, argc, argv, i, &value, msg, msg_size);
        if (m != 0)
            return m < 0 ? -1 : args_store(o, value, dest, msg, msg_size);
    }
    snprintf(msg, msg_size, "unknown option '%.40s'", arg);
    return -1;
}

int args_parse(const ArgTable *t, void *dest, int argc, char **argv, const char **operands,
               int *n, char *msg, size_t msg_size)
{
    int only_operands = 0;

    *n = 0;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        int rc;

        if (only_operands || arg[0] != '-' || strcmp(arg, "-") == 0) {
            if (t->max_operands > 0 && *n == t->max_operands) {
                snprintf(msg, msg_size, "too many arguments: '%.40s' after %s", arg,
                         t->operands);
                return -1;
            }
            operands[(*n)++] = arg;
        } else if (strcmp(arg, "--") == 0) {
            only_operands = 1;
        } else if ((rc = args_one(t, dest, argc, argv, &i, msg, msg_size)) != 0) {
            return rc;
        }
    }
    return 0;
}
