/* load.c: either scene format, by content or by name (see load.h). */
#include "scenefile/load.h"

#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/hash.h"
#include "math/number.h"
#include "scenefile/course.h"
#include "scenefile/keyword.h"
#include "scenefile/mpl.h"

SceneFormat load_detect(const char *text, size_t len)
{
    size_t i = 0;

    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        i = 3;
    while (i < len) {
        size_t start;
        double ignored;
        char ch = text[i];

        if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n') {
            i++;
            continue;
        }
        if (ch == '#') {
            while (i < len && text[i] != '\n')
                i++;
            continue;
        }
        if (!((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z')))
            return SCENE_COURSE;
        start = i;
        while (i < len && text[i] != ' ' && text[i] != '\t' && text[i] != '\r' &&
               text[i] != '\n' && text[i] != '#')
            i++;
        if (i - start == 1 && strchr("mplc", ch))
            return SCENE_MPL;
        return number_parse(text + start, i - start, &ignored) == NUMBER_SYNTAX ? SCENE_KEYWORD
                                                                                : SCENE_COURSE;
    }
    return SCENE_AUTO; /* no element: an empty scene */
}

int load_scene_text(const char *name, const char *text, size_t len, SceneFormat format,
                    size_t memory_limit, int strict, Scene *scene, SceneSource *source, Error *err)
{
    SceneSource unkept;
    int rc;

    if (!source)
        source = &unkept;
    if (format == SCENE_AUTO && (format = load_detect(text, len)) == SCENE_AUTO) {
        scene_init(scene);
        source_init(source);
        error_set(err, name, "the scene is empty: %s",
                  len == 0 ? "the file holds no byte" : "it holds only blank lines and comments");
        return -1;
    }
    if (format == SCENE_KEYWORD)
        rc = keyword_parse_text(name, text, len, memory_limit, scene, source, err);
    else if (format == SCENE_MPL)
        rc = mpl_parse_text(name, text, len, memory_limit, strict, scene, source, err);
    else
        rc = course_parse_text(name, text, len, memory_limit, scene, source, err);
    if (rc == 0)
        scene->source_hash = hash_bytes(hash_u64(scene->source_hash, (uint64_t)format), text, len);
    if (source == &unkept)
        source_free(source);
    return rc;
}

int load_scene_file(const char *path, SceneFormat format, size_t memory_limit, int strict,
                    Scene *scene, SceneSource *source, Error *err)
{
    char *text;
    size_t len;
    int rc;

    scene_init(scene);
    if (source)
        source_init(source);
    if (file_read_all(path, &text, &len, err) != 0)
        return -1;
    rc = load_scene_text(file_display_name(path), text, len, format, memory_limit, strict, scene,
                         source, err);
    free(text);
    return rc;
}
