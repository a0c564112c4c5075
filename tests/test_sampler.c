#include "test.h"
const TestCase sampler_tests[] = {{NULL, NULL}};
