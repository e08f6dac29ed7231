/* SPDX-License-Identifier: MIT */
/* A small client whose object code tests/inline.sh inspects: compiled for
 * the efficient flavour it must contain no calls to the accessors. */
#include <noctree/octree.h>

int walk(octNode *n);

int walk(octNode *n)
{
    int sum = 0;
    while (octIsSplit(n)) {
        sum += octGeneration(n) + (int)octChildType(n);
        if (octData(n) == (void *)0)
            octSwapData(n, n);
        n = octChild(n, OCT_RUF);
    }
    return sum + (octParent(n) != (void *)0) + octSplit(n);
}
