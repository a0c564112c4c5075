/* colour.c: the one quantiser (see colour.h). */
#include "colour.h"

#include <math.h>

unsigned char colour_quantise(double x)
{
    if (!(x > 0)) /* also catches NaN */
        return 0;
    if (x >= 255)
        return 255;
    return (unsigned char)floor(x + 0.5);
}
