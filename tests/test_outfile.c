/* test_outfile.c: all-or-nothing output files: what opening an output
 * removes beside it (a killed process's temporary names). */
#include <stdio.h>
#include <string.h>

#ifdef _WIN32
#include <process.h> /* _getpid */
#define outfile_test_pid() ((unsigned long)_getpid())
#else
#include <unistd.h>
#define outfile_test_pid() ((unsigned long)getpid())
#endif

#include "base/outfile.h"
#include "test.h"

/* Says whether a file of that name (ASCII) can be opened. */
static int outfile_test_exists(const char *name)
{
    FILE *f = fopen(name, "rb");

    if (f)
        fclose(f);
    return f != NULL;
}

/* Makes a file of that name holding text. */
static void outfile_test_make(const char *name, const char *text)
{
    FILE *f = fopen(name, "wb");

    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* Opening an output removes the temporary names beside it of this
 * machine's processes that no longer run, and nothing else: not those of
 * a process that runs (this one), of another machine, or other files. */
static void outfile_open_sweeps_dead_processes_names(void)
{
    const char *dest = "test-outfile.ppm", *mine = ".test-outfile.ppm.mine";
    char dead[OUTFILE_PATH_MAX], live[OUTFILE_PATH_MAX], other[OUTFILE_PATH_MAX], back[8] = "";
    size_t host = strlen(".test-outfile.ppm.");
    OutFile out;
    Error err;
    FILE *f;

    /* No process has this number on Linux (pid_max is at most 2^22) or
     * Windows (numbers are multiples of 4). */
    CHECK_INT(0, outfile_temp_name(dest, 0x7ffffff1ul, 0, dead, sizeof dead));
    CHECK_INT(0, outfile_temp_name(dest, outfile_test_pid(), 3, live, sizeof live));
    strcpy(other, dead);
    other[host] = other[host] == '0' ? '1' : '0'; /* another machine's hash */
    CHECK(strncmp(dead, ".test-outfile.ppm.", host) == 0 && dead[host + 8] == '-');
    outfile_test_make(dest, "old");
    outfile_test_make(dead, "left by a killed render");
    outfile_test_make(live, "being written");
    outfile_test_make(other, "another machine's");
    outfile_test_make(mine, "the user's");
    CHECK_INT(0, outfile_open(&out, dest, &err));
    fputs("new", out.fp);
    CHECK_INT(0, outfile_commit(&out, &err));
    CHECK(!outfile_test_exists(dead));
    CHECK(outfile_test_exists(live));
    CHECK(outfile_test_exists(other));
    CHECK(outfile_test_exists(mine));
    f = fopen(dest, "rb");
    CHECK(f && fread(back, 1, sizeof back - 1, f) == 3 && strcmp(back, "new") == 0);
    if (f)
        fclose(f);
    remove(dest);
    remove(dead);
    remove(live);
    remove(other);
    remove(mine);
}

const TestCase outfile_tests[] = {
    {"outfile_open_sweeps_dead_processes_names", outfile_open_sweeps_dead_processes_names},
    {NULL, NULL},
};
