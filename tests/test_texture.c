#include "test.h"
const TestCase texture_tests[] = {{NULL, NULL}};
