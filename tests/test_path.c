/* test_path.c: file names as this system reads them (base/path.h,
 * base/file.h): the folder a scene's files are found in, relative paths
 * for --save, and UTF-8 names opened as they are. The same tests run on
 * Windows (make test-windows), where '\' and drives count too. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _WIN32
#include <wchar.h> /* _wremove */
#endif

#include "base/file.h"
#include "base/path.h"
#include "test.h"

/* Checks that path_beside(file, folder, name) is want. */
static void path_check_beside(const char *file, const char *folder, const char *name,
                              const char *want)
{
    char *got = path_beside(file, folder, name, strlen(name));

    if (!got || strcmp(got, want) != 0)
        test_fail(__FILE__, __LINE__, "path_beside(\"%s\", \"%s\", \"%s\"): expected \"%s\", "
                  "got \"%s\"", file, folder, name, want, got ? got : "(null)");
    free(got);
}

/* Checks that path_relative(from, to) is want. */
static void path_check_relative(const char *from, const char *to, const char *want)
{
    char *got = path_relative(from, to);

    if (!got || strcmp(got, want) != 0)
        test_fail(__FILE__, __LINE__, "path_relative(\"%s\", \"%s\"): expected \"%s\", got \"%s\"",
                  from, to, want, got ? got : "(null)");
    free(got);
}

static void path_files_beside_the_scene(void)
{
    path_check_beside("scene.txt", "", "tex.ppm", "tex.ppm");
    path_check_beside("scenes/a.txt", "", "tex.ppm", "scenes/tex.ppm");
    path_check_beside("scenes/a.txt", "textures/", "t.ppm", "scenes/textures/t.ppm");
    path_check_beside("/x/a.txt", "", "/abs/t.ppm", "/abs/t.ppm");
    path_check_beside("/x/a.txt", "", "été/t.ppm", "/x/été/t.ppm");
    CHECK(path_is_absolute("/a", 2));
    CHECK(!path_is_absolute("a/b", 3));
    CHECK(!path_is_absolute("", 0));
    CHECK_INT(0, (long long)path_dir_length("a.txt"));
    CHECK_INT(2, (long long)path_dir_length("a/b.txt"));
#ifdef _WIN32
    /* Windows: both separators, drives, servers' shares. */
    path_check_beside("scenes\\a.txt", "", "tex.ppm", "scenes\\tex.ppm");
    path_check_beside("C:a.txt", "", "tex.ppm", "C:tex.ppm");
    path_check_beside("scenes\\a.txt", "", "C:\\t.ppm", "C:\\t.ppm");
    path_check_beside("scenes/a.txt", "", "\\\\srv\\share\\t.ppm", "\\\\srv\\share\\t.ppm");
    CHECK(path_is_absolute("C:\\a", 4));
    CHECK(path_is_absolute("c:/a", 4));
    CHECK(path_is_absolute("\\a", 2));
    CHECK_INT(3, (long long)path_root_length("C:\\a\\b"));
    CHECK_INT(12, (long long)path_root_length("\\\\srv\\share\\x\\y"));
#else
    /* POSIX: '\' and ':' are a name's own characters. */
    path_check_beside("scenes\\a.txt", "", "tex.ppm", "tex.ppm");
    path_check_beside("s/a.txt", "", "C:\\t.ppm", "s/C:\\t.ppm");
    CHECK(!path_is_absolute("C:\\a", 4));
    CHECK_INT(1, (long long)path_root_length("/a"));
#endif
}

static void path_relative_from_a_folder(void)
{
#ifdef _WIN32
    path_check_relative("C:\\work\\saved", "C:\\work\\scenes\\m.obj", "../scenes/m.obj");
    path_check_relative("C:\\work", "C:\\work\\m.obj", "m.obj");
    path_check_relative("C:\\a\\b", "D:\\m.obj", "D:\\m.obj"); /* another drive */
#else
    path_check_relative("/work/saved", "/work/scenes/models/m.obj", "../scenes/models/m.obj");
    path_check_relative("/work", "/work/m.obj", "m.obj");
    path_check_relative("/a/b/c", "/m.obj", "../../../m.obj");
    path_check_relative("/", "/x/m.obj", "x/m.obj");
    path_check_relative("/work/sav", "/work/saved/m.obj", "../saved/m.obj"); /* not a prefix */
    path_check_relative("/work/", "/work/m.obj", "m.obj");
#endif
}

/* A file named in UTF-8 is made, found again and read back, and is the
 * same file as itself but not as another. */
static void path_utf8_names_open(void)
{
    const char *name = "test-path-\xc3\xa9t\xc3\xa9-\xe2\x82\xac.tmp", *other = "test-path-other.tmp";
    FILE *f = file_open(name, "wb");
    char *data = NULL;
    size_t len = 0;
    Error err;

    CHECK(f != NULL);
    if (!f)
        return;
    fputs("r\xc3\xa9sum\xc3\xa9\n", f);
    fclose(f);
    CHECK_INT(0, file_read_all(name, &data, &len, &err));
    CHECK(data && len == 9 && memcmp(data, "r\xc3\xa9sum\xc3\xa9\n", 9) == 0);
    free(data);
    f = file_open(other, "wb");
    CHECK(f != NULL);
    if (f)
        fclose(f);
    CHECK(file_same(name, name));
    CHECK(!file_same(name, other));
    CHECK(!file_same(name, "test-path-none.tmp"));
    remove(other);
#ifdef _WIN32
    /* remove() reads the system's code page, not UTF-8. */
    CHECK_INT(0, _wremove(L"test-path-\u00e9t\u00e9-\u20ac.tmp"));
#else
    CHECK_INT(0, remove(name));
#endif
}

const TestCase path_tests[] = {
    {"path_files_beside_the_scene", path_files_beside_the_scene},
    {"path_relative_from_a_folder", path_relative_from_a_folder},
    {"path_utf8_names_open", path_utf8_names_open},
    {NULL, NULL},
};
