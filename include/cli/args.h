/*
 * args.h: a command line read by a table of its options; raytrace,
 * raytrace-diff and raytrace-merge each describe theirs with one.
 *
 * Options come as "--name V", "--name=V", "-x V" or "-xV"; "--" ends them
 * and "-" alone is an operand (standard input or output).
 */
#ifndef RAYTRACE_ARGS_H
#define RAYTRACE_ARGS_H

#include <stddef.h>

/* What an option is, and where its value goes. */
typedef enum {
    ARG_FLAG,  /* no value: the int field is set to 1 */
    ARG_INT,   /* a whole number from lo to hi, into an int field */
    ARG_COUNT, /* a whole number >= 0, into a size_t field */
    ARG_REAL,  /* a decimal number from lo to hi (hi may be infinite), into
                  a double field */
    ARG_SIZE,  /* a size in bytes (args_size()), into a size_t field */
    ARG_WORD,  /* one of words, whose value goes into an int field */
    ARG_TEXT,  /* any string, into a const char * field */
    ARG_ACT    /* no value: args_parse() returns act at once */
} ArgKind;

/* A word an option may take, and the value it stands for. */
typedef struct {
    const char *word;
    int value;
    int alias; /* 1: an old spelling, taken but never listed */
} ArgWord;

/* An option of a command line. */
typedef struct {
    const char *long_name;  /* "--max-depth" */
    const char *short_name; /* "-d", or NULL */
    ArgKind kind;
    size_t field;           /* offsetof(the command's options, its field) */
    double lo, hi;          /* INT and REAL: the accepted range */
    const ArgWord *words;   /* WORD: its words, ending with a NULL word */
    int act;                /* ACT: what it asks for, > 0 */
} ArgSpec;

/* A command's options and operands. */
typedef struct {
    const ArgSpec *specs;
    size_t count;
    int max_operands;       /* operands it takes at most; 0: any number */
    const char *operands;   /* their names, for "too many arguments: 'X'
                               after SCENE and OUTPUT" */
} ArgTable;

/* Reads argv[1..argc-1] by table t: each option's value into its field
 * of the struct at dest, the other arguments into operands[] (room for
 * t->max_operands, or argc when any number), their count in *n. Returns
 * 0, the act of the first ARG_ACT option met (at once), or -1 with a
 * one-line message in msg. */
int args_parse(const ArgTable *t, void *dest, int argc, char **argv, const char **operands,
               int *n, char *msg, size_t msg_size);

/* Reads the whole number in text, from lo to hi, into *out; returns 0, or
 * -1 when text is not one. */
int args_int(const char *text, int lo, int hi, int *out);

/* Reads "A<sep>B" (as 640x480 or 3/8), each a whole number from lo to hi,
 * into *a and *b; returns 0 or -1. */
int args_pair(const char *text, char sep, int lo, int hi, int *a, int *b);

/* Reads a size in bytes, "0" or whole digits with an optional K, M or G
 * (powers of 1024), into *out; returns 0, or -1 when it is none or too
 * large. */
int args_size(const char *text, size_t *out);

#endif
