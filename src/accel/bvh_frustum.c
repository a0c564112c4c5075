/* bvh_frustum.c: whether a pyramid of rays reaches the hierarchy's
 * primitives (see bvh.h). */
#include "accel/bvh.h"

/* Says whether no ray of f can meet child k of node: its box in the
 * scene's units, widened past the rounding of the way there (a float of
 * the frame, over a power of two, plus the frame's centre), is proven
 * beyond the pyramid; an unused child is met by no ray. */
static int bvh_frustum_misses_child(const Bvh *bvh, const BvhNode *node, int k, const Frustum *f)
{
    real lo[3], hi[3];

    if (!(node->box[0][k] <= node->box[3][k]))
        return 1;
    for (int a = 0; a < 3; a++) {
        double l = node->box[a][k] / bvh->scale + bvh->centre[a];
        double h = node->box[3 + a][k] / bvh->scale + bvh->centre[a];
        double pad = 4 * REAL_EPSILON * (fabs(l) + fabs(h)) + REAL_TRUE_MIN;
        lo[a] = (real)(l - pad);
        hi[a] = (real)(h + pad);
    }
    return frustum_misses_box(f, vec3(lo[0], lo[1], lo[2]), vec3(hi[0], hi[1], hi[2]));
}

int bvh_frustum_clear(const Bvh *bvh, const Frustum *f)
{
    /* Each visit takes one node off the stack and puts at most
     * BVH_WIDTH on. */
    uint32_t stack[BVH_FRUSTUM_VISITS * (BVH_WIDTH - 1) + 1];
    int top = 0, visits = 0;

    if (bvh->node_count == 0)
        return 1;
    stack[top++] = 0; /* the root */
    while (top > 0) {
        const BvhNode *node = &bvh->nodes[stack[--top]];
        if (++visits > BVH_FRUSTUM_VISITS)
            return 0;
        for (int k = 0; k < BVH_WIDTH; k++) {
            if (bvh_frustum_misses_child(bvh, node, k, f))
                continue;
            if (bvh_link_count(node->link[k]) != 0)
                return 0; /* a leaf some ray may reach */
            stack[top++] = bvh_link_index(node->link[k]);
        }
    }
    return 1;
}
