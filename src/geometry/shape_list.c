/* shape_list.c: each kind's record and word, from the list (see
 * shape_list.h). */
#include "geometry/shape_list.h"

#define SHAPE_RECORD(K, T, name, ...) &name##_record,
const ShapeRecord *const shape_records[SHAPE_KINDS] = {SHAPE_LIST(SHAPE_RECORD)};
#undef SHAPE_RECORD

#define SHAPE_WORD(K, T, name, ...) #name,
const char *const shape_words[SHAPE_KINDS] = {SHAPE_LIST(SHAPE_WORD)};
#undef SHAPE_WORD
