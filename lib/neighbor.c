/* SPDX-License-Identifier: MIT */
/*
 * Neighbor finding after Samet (Applications of Spatial Data Structures,
 * 1990, pp. 87-90), for the report's neighbor.h.
 *
 * Frame: L/R = -x/+x, D/U = -y/+y, B/F = -z/+z. An octant (a vertex
 * direction) O = OCT_LDB + 4r + 2u + f has r = 1 on the R (+x) half of its
 * parent block, u = 1 on the U half and f = 1 on the F half.
 *
 * The four tables below are Samet's ADJ, REFLECT, COMMON_FACE and
 * COMMON_EDGE, written out literally so each query is one look-up. Rows
 * are directions I in octDirection order, columns the octants O in the
 * order LDB, LDF, LUB, LUF, RDB, RDF, RUB, RUF. The test suite recomputes
 * every entry from coordinates.
 */
#include "config.h"

#include <math.h>
#include <stdint.h>

#include <noctree/neighbor.h>

#include "internal.h"

#define VERTEX_INDEX(O) ((unsigned)(O) - (unsigned)OCT_LDB)

/*
 * ADJ[I][O]: does octant O touch the I face, edge or vertex of its parent
 * block? Geometrically: on every axis that I names, O is in the half of the
 * parent that I points to. Example: ADJ[L][LUF] is true (LUF is on the left
 * half, so it touches the parent's left face); ADJ[LU][LDF] is false (LDF
 * is on the down half, away from the left-up edge). When ADJ holds, O's
 * equal-size neighbor in direction I lies outside O's parent.
 */
static const bool ADJ[OCT_NUM_DIRECTIONS][8] = {
    /* L     */ { true,  true,  true,  true, false, false, false, false},
    /* R     */ {false, false, false, false,  true,  true,  true,  true},
    /* D     */ { true,  true, false, false,  true,  true, false, false},
    /* U     */ {false, false,  true,  true, false, false,  true,  true},
    /* B     */ { true, false,  true, false,  true, false,  true, false},
    /* F     */ {false,  true, false,  true, false,  true, false,  true},
    /* LD    */ { true,  true, false, false, false, false, false, false},
    /* LU    */ {false, false,  true,  true, false, false, false, false},
    /* LB    */ { true, false,  true, false, false, false, false, false},
    /* LF    */ {false,  true, false,  true, false, false, false, false},
    /* RD    */ {false, false, false, false,  true,  true, false, false},
    /* RU    */ {false, false, false, false, false, false,  true,  true},
    /* RB    */ {false, false, false, false,  true, false,  true, false},
    /* RF    */ {false, false, false, false, false,  true, false,  true},
    /* DB    */ { true, false, false, false,  true, false, false, false},
    /* DF    */ {false,  true, false, false, false,  true, false, false},
    /* UB    */ {false, false,  true, false, false, false,  true, false},
    /* UF    */ {false, false, false,  true, false, false, false,  true},
    /* LDB   */ { true, false, false, false, false, false, false, false},
    /* LDF   */ {false,  true, false, false, false, false, false, false},
    /* LUB   */ {false, false,  true, false, false, false, false, false},
    /* LUF   */ {false, false, false,  true, false, false, false, false},
    /* RDB   */ {false, false, false, false,  true, false, false, false},
    /* RDF   */ {false, false, false, false, false,  true, false, false},
    /* RUB   */ {false, false, false, false, false, false,  true, false},
    /* RUF   */ {false, false, false, false, false, false, false,  true},
};

/*
 * REFLECT[I][O]: the child type of the equal-size block that shares O's I
 * face, edge or vertex. Stepping one block-width in direction I changes the
 * half on every axis I names and keeps the others, inside or outside O's
 * parent alike. Example: REFLECT[R][LUB] is RUB (one step right from the
 * left-up-back octant lands on a right-up-back octant: a sibling), and
 * REFLECT[R][RUB] is LUB (the left half of the next block to the right).
 */
static const octDirection REFLECT[OCT_NUM_DIRECTIONS][8] = {
    /* L     */ {OCT_RDB, OCT_RDF, OCT_RUB, OCT_RUF, OCT_LDB, OCT_LDF, OCT_LUB, OCT_LUF},
    /* R     */ {OCT_RDB, OCT_RDF, OCT_RUB, OCT_RUF, OCT_LDB, OCT_LDF, OCT_LUB, OCT_LUF},
    /* D     */ {OCT_LUB, OCT_LUF, OCT_LDB, OCT_LDF, OCT_RUB, OCT_RUF, OCT_RDB, OCT_RDF},
    /* U     */ {OCT_LUB, OCT_LUF, OCT_LDB, OCT_LDF, OCT_RUB, OCT_RUF, OCT_RDB, OCT_RDF},
    /* B     */ {OCT_LDF, OCT_LDB, OCT_LUF, OCT_LUB, OCT_RDF, OCT_RDB, OCT_RUF, OCT_RUB},
    /* F     */ {OCT_LDF, OCT_LDB, OCT_LUF, OCT_LUB, OCT_RDF, OCT_RDB, OCT_RUF, OCT_RUB},
    /* LD    */ {OCT_RUB, OCT_RUF, OCT_RDB, OCT_RDF, OCT_LUB, OCT_LUF, OCT_LDB, OCT_LDF},
    /* LU    */ {OCT_RUB, OCT_RUF, OCT_RDB, OCT_RDF, OCT_LUB, OCT_LUF, OCT_LDB, OCT_LDF},
    /* LB    */ {OCT_RDF, OCT_RDB, OCT_RUF, OCT_RUB, OCT_LDF, OCT_LDB, OCT_LUF, OCT_LUB},
    /* LF    */ {OCT_RDF, OCT_RDB, OCT_RUF, OCT_RUB, OCT_LDF, OCT_LDB, OCT_LUF, OCT_LUB},
    /* RD    */ {OCT_RUB, OCT_RUF, OCT_RDB, OCT_RDF, OCT_LUB, OCT_LUF, OCT_LDB, OCT_LDF},
    /* RU    */ {OCT_RUB, OCT_RUF, OCT_RDB, OCT_RDF, OCT_LUB, OCT_LUF, OCT_LDB, OCT_LDF},
    /* RB    */ {OCT_RDF, OCT_RDB, OCT_RUF, OCT_RUB, OCT_LDF, OCT_LDB, OCT_LUF, OCT_LUB},
    /* RF    */ {OCT_RDF, OCT_RDB, OCT_RUF, OCT_RUB, OCT_LDF, OCT_LDB, OCT_LUF, OCT_LUB},
    /* DB    */ {OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB, OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB},
    /* DF    */ {OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB, OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB},
    /* UB    */ {OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB, OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB},
    /* UF    */ {OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB, OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB},
    /* LDB   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* LDF   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* LUB   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* LUF   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* RDB   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* RDF   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* RUB   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
    /* RUF   */ {OCT_RUF, OCT_RUB, OCT_RDF, OCT_RDB, OCT_LUF, OCT_LUB, OCT_LDF, OCT_LDB},
};

/*
 * COMMON_FACE[I][O], for edge and vertex directions I (rows LD .. RUF): the
 * face of O's parent block through which the step from O in direction I
 * leaves the parent, when it leaves through a face. Of the axes I names,
 * those on which O lies on I's side are the axes on which the step crosses
 * the parent's boundary: exactly one means a face (the entry is that face),
 * none means the neighbor is a sibling and two or three mean the step
 * crosses an edge or vertex of the parent only (the entry is OMEGA).
 * Example: COMMON_FACE[LD][LUB] is L: LUB touches the parent's left face
 * but is on the up half, so a left-down step leaves leftward only, and the
 * neighbor is a child of the parent's left face neighbor.
 */
static const octDirection COMMON_FACE[OCT_NUM_DIRECTIONS - 6][8] = {
    /* LD    */ {OCT_OMEGA, OCT_OMEGA,     OCT_L,     OCT_L,     OCT_D,     OCT_D, OCT_OMEGA, OCT_OMEGA},
    /* LU    */ {    OCT_L,     OCT_L, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,     OCT_U,     OCT_U},
    /* LB    */ {OCT_OMEGA,     OCT_L, OCT_OMEGA,     OCT_L,     OCT_B, OCT_OMEGA,     OCT_B, OCT_OMEGA},
    /* LF    */ {    OCT_L, OCT_OMEGA,     OCT_L, OCT_OMEGA, OCT_OMEGA,     OCT_F, OCT_OMEGA,     OCT_F},
    /* RD    */ {    OCT_D,     OCT_D, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,     OCT_R,     OCT_R},
    /* RU    */ {OCT_OMEGA, OCT_OMEGA,     OCT_U,     OCT_U,     OCT_R,     OCT_R, OCT_OMEGA, OCT_OMEGA},
    /* RB    */ {    OCT_B, OCT_OMEGA,     OCT_B, OCT_OMEGA, OCT_OMEGA,     OCT_R, OCT_OMEGA,     OCT_R},
    /* RF    */ {OCT_OMEGA,     OCT_F, OCT_OMEGA,     OCT_F,     OCT_R, OCT_OMEGA,     OCT_R, OCT_OMEGA},
    /* DB    */ {OCT_OMEGA,     OCT_D,     OCT_B, OCT_OMEGA, OCT_OMEGA,     OCT_D,     OCT_B, OCT_OMEGA},
    /* DF    */ {    OCT_D, OCT_OMEGA, OCT_OMEGA,     OCT_F,     OCT_D, OCT_OMEGA, OCT_OMEGA,     OCT_F},
    /* UB    */ {    OCT_B, OCT_OMEGA, OCT_OMEGA,     OCT_U,     OCT_B, OCT_OMEGA, OCT_OMEGA,     OCT_U},
    /* UF    */ {OCT_OMEGA,     OCT_F,     OCT_U, OCT_OMEGA, OCT_OMEGA,     OCT_F,     OCT_U, OCT_OMEGA},
    /* LDB   */ {OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,     OCT_L, OCT_OMEGA,     OCT_D,     OCT_B, OCT_OMEGA},
    /* LDF   */ {OCT_OMEGA, OCT_OMEGA,     OCT_L, OCT_OMEGA,     OCT_D, OCT_OMEGA, OCT_OMEGA,     OCT_F},
    /* LUB   */ {OCT_OMEGA,     OCT_L, OCT_OMEGA, OCT_OMEGA,     OCT_B, OCT_OMEGA, OCT_OMEGA,     OCT_U},
    /* LUF   */ {    OCT_L, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,     OCT_F,     OCT_U, OCT_OMEGA},
    /* RDB   */ {OCT_OMEGA,     OCT_D,     OCT_B, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,     OCT_R},
    /* RDF   */ {    OCT_D, OCT_OMEGA, OCT_OMEGA,     OCT_F, OCT_OMEGA, OCT_OMEGA,     OCT_R, OCT_OMEGA},
    /* RUB   */ {    OCT_B, OCT_OMEGA, OCT_OMEGA,     OCT_U, OCT_OMEGA,     OCT_R, OCT_OMEGA, OCT_OMEGA},
    /* RUF   */ {OCT_OMEGA,     OCT_F,     OCT_U, OCT_OMEGA,     OCT_R, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA},
};

/*
 * COMMON_EDGE[I][O], for vertex directions I (rows LDB .. RUF): the edge of
 * O's parent block across which the step from O in direction I leaves the
 * parent, when O lies on I's side on exactly two of the three axes; OMEGA
 * otherwise. Example: COMMON_EDGE[LDB][LDF] is LD: LDF touches the parent's
 * left-down edge but lies on the front half, so a left-down-back step
 * leaves across that edge, into a child of the parent's LD edge neighbor.
 */
static const octDirection COMMON_EDGE[8][8] = {
    /* LDB   */ {OCT_OMEGA,    OCT_LD,    OCT_LB, OCT_OMEGA,    OCT_DB, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA},
    /* LDF   */ {   OCT_LD, OCT_OMEGA, OCT_OMEGA,    OCT_LF, OCT_OMEGA,    OCT_DF, OCT_OMEGA, OCT_OMEGA},
    /* LUB   */ {   OCT_LB, OCT_OMEGA, OCT_OMEGA,    OCT_LU, OCT_OMEGA, OCT_OMEGA,    OCT_UB, OCT_OMEGA},
    /* LUF   */ {OCT_OMEGA,    OCT_LF,    OCT_LU, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,    OCT_UF},
    /* RDB   */ {   OCT_DB, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,    OCT_RD,    OCT_RB, OCT_OMEGA},
    /* RDF   */ {OCT_OMEGA,    OCT_DF, OCT_OMEGA, OCT_OMEGA,    OCT_RD, OCT_OMEGA, OCT_OMEGA,    OCT_RF},
    /* RUB   */ {OCT_OMEGA, OCT_OMEGA,    OCT_UB, OCT_OMEGA,    OCT_RB, OCT_OMEGA, OCT_OMEGA,    OCT_RU},
    /* RUF   */ {OCT_OMEGA, OCT_OMEGA, OCT_OMEGA,    OCT_UF, OCT_OMEGA,    OCT_RF,    OCT_RU, OCT_OMEGA},
};

bool octAdj(octDirection I, octDirection O)
{
    NOCT_REQUIRE((unsigned)I < OCT_NUM_DIRECTIONS);
    NOCT_REQUIRE(OCT_IS_VERTEX(O));
    return ADJ[I][VERTEX_INDEX(O)];
}

octDirection octReflect(octDirection I, octDirection O)
{
    NOCT_REQUIRE((unsigned)I < OCT_NUM_DIRECTIONS);
    NOCT_REQUIRE(OCT_IS_VERTEX(O));
    return REFLECT[I][VERTEX_INDEX(O)];
}

octDirection octCommonFace(octDirection I, octDirection O)
{
    NOCT_REQUIRE(OCT_IS_EDGE(I) || OCT_IS_VERTEX(I));
    NOCT_REQUIRE(OCT_IS_VERTEX(O));
    return COMMON_FACE[I - OCT_LD][VERTEX_INDEX(O)];
}

octDirection octCommonEdge(octDirection I, octDirection O)
{
    NOCT_REQUIRE(OCT_IS_VERTEX(I));
    NOCT_REQUIRE(OCT_IS_VERTEX(O));
    return COMMON_EDGE[VERTEX_INDEX(I)][VERTEX_INDEX(O)];
}

/*
 * The direction in which Samet's recursion continues from a node of child
 * type O that is looking in direction I: I itself if O touches its parent's
 * I feature (the neighbor is beyond the parent in the same direction); else
 * the common edge, else the common face (the neighbor is beyond the
 * parent's edge or face); else OMEGA: the parent is the nearest common
 * ancestor and the climb stops.
 */
static octDirection climb_direction(octDirection I, unsigned o)
{
    if (ADJ[I][o])
        return I;
    if (OCT_IS_VERTEX(I) && COMMON_EDGE[VERTEX_INDEX(I)][o] != OCT_OMEGA)
        return COMMON_EDGE[VERTEX_INDEX(I)][o];
    if (!OCT_IS_FACE(I))
        return COMMON_FACE[I - OCT_LD][o];
    return OCT_OMEGA;
}

/* Levels of the climb whose reflected child types are kept on the stack;
 * a deeper climb recomputes the rest (see below). */
#define CLIMB_BUFFER 64

/*
 * Samet's GTEQ_*_NEIGHBOR, unrolled. Climb from P towards the nearest
 * common ancestor A of P and its neighbor, noting at each level k the child
 * type R_k that the neighbor's ancestor has at that level (REFLECT of the
 * direction in force there). If the climb passes the root, the neighboring
 * cube is outside the tree. Then descend from A through R_(K-1) ... R_0,
 * stopping early at a leaf (the larger neighbor) or after K levels (the
 * neighbor of P's generation, split or not).
 *
 * The directions in force change at most three times during a climb (each
 * change drops an axis), so levels beyond the buffer are recomputed from
 * P's ancestors and those change points: O(K^2) only for climbs of over 64
 * levels, and no recursion or allocation for any depth.
 */
static octNode *gteq_neighbor(octNode *P, octDirection I)
{
    uint8_t reflected[CLIMB_BUFFER];
    size_t change_level[4];
    octDirection change_dir[4];
    size_t nchanges = 0, levels = 0;
    octDirection dir = I;
    octNode *n = P;

    for (;;) {
        if (n->parent_ == NULL)
            return NULL;
        unsigned o = (unsigned)n->childType_ - OCT_LDB;
        if (levels < CLIMB_BUFFER)
            reflected[levels] = (uint8_t)REFLECT[dir][o];
        ++levels;
        octDirection next = climb_direction(dir, o);
        n = n->parent_;
        if (next == OCT_OMEGA)
            break;
        if (next != dir) {
            change_level[nchanges] = levels;
            change_dir[nchanges++] = next;
            dir = next;
        }
    }

    while (levels > 0 && n->children_ != NULL) {
        --levels;
        unsigned r;
        if (levels < CLIMB_BUFFER) {
            r = reflected[levels];
        } else {
            /* Direction in force at this level, and P's ancestor there. */
            octDirection d = I;
            for (size_t c = 0; c < nchanges && change_level[c] <= levels; ++c)
                d = change_dir[c];
            const octNode *a = P;
            for (size_t k = 0; k < levels; ++k)
                a = a->parent_;
            r = REFLECT[d][(unsigned)a->childType_ - OCT_LDB];
        }
        n = &n->children_[r - OCT_LDB];
    }
    return n;
}

octNode *octGtEqFaceNeighbor(octNode *P, octDirection I)
{
    NOCT_REQUIRE(P != NULL);
    NOCT_REQUIRE(OCT_IS_FACE(I));
    return gteq_neighbor(P, I);
}

octNode *octGtEqEdgeNeighbor(octNode *P, octDirection I)
{
    NOCT_REQUIRE(P != NULL);
    NOCT_REQUIRE(OCT_IS_EDGE(I));
    return gteq_neighbor(P, I);
}

octNode *octGtEqVertexNeighbor(octNode *P, octDirection I)
{
    NOCT_REQUIRE(P != NULL);
    NOCT_REQUIRE(OCT_IS_VERTEX(I));
    return gteq_neighbor(P, I);
}

octNode *octGtEqNeighbor(octNode *P, octDirection I)
{
    NOCT_REQUIRE(P != NULL);
    NOCT_REQUIRE((unsigned)I < OCT_NUM_DIRECTIONS);
    return gteq_neighbor(P, I);
}

/*
 * Directions named by a set of axes with signs, indexed by the sign of x,
 * y and z each as 0 (zero), 1 (positive) or 2 (negative): the face, edge or
 * vertex direction with those components, or OMEGA for the zero vector.
 */
static const octDirection BY_SIGNS[3][3][3] = {
    /* x = 0 */
    {{OCT_OMEGA, OCT_F, OCT_B}, {OCT_U, OCT_UF, OCT_UB}, {OCT_D, OCT_DF, OCT_DB}},
    /* x > 0 */
    {{OCT_R, OCT_RF, OCT_RB}, {OCT_RU, OCT_RUF, OCT_RUB}, {OCT_RD, OCT_RDF, OCT_RDB}},
    /* x < 0 */
    {{OCT_L, OCT_LF, OCT_LB}, {OCT_LU, OCT_LUF, OCT_LUB}, {OCT_LD, OCT_LDF, OCT_LDB}},
};

static unsigned sign_index(double v)
{
    return v > 0 ? 1u : v < 0 ? 2u : 0u;
}

octDirection noct_direction_of(int x, int y, int z)
{
    return BY_SIGNS[sign_index(x)][sign_index(y)][sign_index(z)];
}

size_t octVectorToDirections(double x, double y, double z,
                             octDirection dirs[OCT_MAX_MOTION_DIRECTIONS])
{
    NOCT_REQUIRE(dirs != NULL);
    NOCT_REQUIRE(!isnan(x) && !isnan(y) && !isnan(z));
    const unsigned s[3] = {sign_index(x), sign_index(y), sign_index(z)};
    size_t n = 0;
    /* Subsets of the axes by size: faces {x}, {y}, {z}; edges {x,y},
     * {x,z}, {y,z}; the vertex {x,y,z}. This is octDirection order within
     * each group. */
    static const unsigned char subsets[7] = {4, 2, 1, 6, 5, 3, 7};
    for (size_t i = 0; i < 7; ++i) {
        unsigned m = subsets[i];
        unsigned sx = (m & 4) ? s[0] : 0, sy = (m & 2) ? s[1] : 0,
                 sz = (m & 1) ? s[2] : 0;
        /* Only subsets whose every axis moves: an axis with a zero
         * component contributes no direction. */
        if (((m & 4) && !sx) || ((m & 2) && !sy) || ((m & 1) && !sz))
            continue;
        dirs[n++] = BY_SIGNS[sx][sy][sz];
    }
    dirs[n] = OCT_OMEGA;
    return n;
}
