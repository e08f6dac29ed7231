/* SPDX-License-Identifier: MIT */
/*
 * Private: the layout of a mesh, shared by the files that make meshes
 * (mesh.c: checks, hull, packing; box_form.c: box forms; mesh_box.c: box
 * primitives and turned meshes; meshio.c: OFF and OBJ; bvh.c: the
 * hierarchy) and those that read them (narrowphase*.c, the world).
 * Never installed.
 */
#ifndef NOCT_LIB_MESH_INTERNAL_H
#define NOCT_LIB_MESH_INTERNAL_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/status.h>

/* A node of the bounding-volume hierarchy over a mesh's triangles. A leaf
 * (count > 0) holds triangles [first, first + count) of the mesh's
 * triangle array, which is stored in BVH order; an inner node's children
 * are nodes[first] and nodes[first + 1]. */
/* The separating-axis filter serves convex meshes with at most this many
 * distinct face normals and distinct edge directions. */
#define NOCT_SAT_MAX 16

/* An axis of the separating-axis filter and the interval the mesh's own
 * vertices project to on it, in floating point, in the mesh's frame. */
typedef struct sat_axis {
    double u[3];
    double lo, hi;
} sat_axis;

typedef struct bvh_node {
    double lo[3], hi[3];
    uint32_t first;
    uint32_t count;
} bvh_node;

/* The fields the exact level's filter reads for every pair come first.
 * A finished mesh is one allocation (noct_mesh_pack): the struct, then its
 * filter axes, vertices, planes, triangles, BVH and hull, so that the
 * filter reads a few consecutive cache lines. */
/*
 * A mesh of 8 vertices that are, within dev per coordinate, the corners
 * c + s0 e[0] + s1 e[1] + s2 e[2] (s = +-1) of a parallelepiped: a box,
 * rotated or not, with its corners rounded. The filter decides a pair of
 * such meshes from this description alone (the oriented-box test), so it
 * reads these few cache lines of each mesh and nothing else.
 */
typedef struct box_form {
    double c[3];
    double e[3][3]; /* half-edge vectors */
    double size;    /* bounds |c_k| + sum_i |e[i]_k| + dev: every vertex
                       coordinate, and the magnitudes the filter adds */
    /* Two bounds kept as floats rounded up, so that the form and the
     * flags fit two cache lines; a larger bound only makes the filter
     * and the witnesses more careful. */
    float own[3];   /* the box's radius on axis e[i]: sum_j |e[i].e[j]| */
    float dev;      /* bounds |vertex - its corner| per coordinate */
} box_form;

/* The cache lines at the start of a mesh that hold its box form and the
 * flags before it: all that noctCollide()'s filter reads of a mesh in a
 * pair of boxes (a world reads its own copy, noct_box_slot). */
#define NOCT_MESH_BOX_LINES 2

/*
 * For proving points inside a box-form mesh's solid (has_dual): g[i] is
 * the dual of the half-edge vectors (g[i].e[j] = (i == j) within eta), so
 * x = c + sum a_i e[i] has a_i = g[i].(x - c) up to eta; gmax bounds
 * |g[i]|_1. Only set when every triangle lies on a face of the ideal box
 * (its corners share a sign), so the surface the deviation bends stays
 * within sqrt(3) dev of that box's surface.
 */
typedef struct box_dual {
    double g[3][3];
    double gmax, eta;
    float shrink; /* 2 gmax dev + 8 eta + 2e-15 rounded up: the proof's
                     shrink of the ideal box (narrowphase.c) */
    /* Which vertex is at which corner, and which triangles on which face,
     * for the distance's closed form (narrowphase_distance.c): corner[p]
     * is the vertex at c + sum_j (bit j of p ? e[j] : -e[j]); face[2 j +
     * s] are the two triangles on the face of sign s (1: +e[j]) across
     * e[j]. */
    uint8_t corner[8];
    uint8_t face[6][2];
    /* The 8 vertices (+-h0, +-h1, +-h2) of a box about the origin
     * (noctMeshCreateBox()'s, any order): sign[i] says vertex i's signs
     * (bit 2: +h0, bit 1: +h1, bit 0: +h2), each sign once. The distance
     * places such a box from 9 products (narrowphase_distance.c). A
     * copy of a mesh with other vertices (a rotated view) must clear it. */
    bool about_origin;
    uint8_t sign[8];
    /* (about_origin) axis j of the corners (corner 7 ^ 2^j to corner 7)
     * is the mesh's axis frame_axis[j], the + side where bit j of
     * frame_plus is set */
    uint8_t frame_axis[3], frame_plus;
    /* edges within a factor 10^6 of each other, dev within 2^-30 of the
     * least half-edge (the distance's box_far_from_flat()) */
    bool far_from_flat;
} box_dual;

/*
 * A box form as the oriented-box test reads it: two cache lines, so that
 * a world keeps one per object in an array and decides a pair of boxes
 * from them and the translations, reading nothing else.
 */
typedef struct noct_box_slot {
    double c[3];
    double e[3][3];
    double size;
    float own[3];
    float dev;
    float shrink;   /* the dual's, or +inf without a dual; below 1 only
                       when the mesh's surface is the box's, bent by at
                       most dev (a dual's tiling), which the inside proofs
                       (noct_box_decide(), noct_point_slot_decide()) rely
                       on: a slot that only encloses a mesh must keep it
                       +inf */
    uint32_t has_box;
} noct_box_slot;

struct noctMesh {
    bool has_box;       /* box is valid */
    bool has_dual;      /* dual is valid (implies has_box) */
    bool convex;
    bool packed;        /* one allocation: the arrays follow the struct */
    bool turn_fine;     /* every rotation keeps every triangle far from the
                           degeneracy noctMeshCreate() rejects
                           (noct_mesh_turn_fine()) */
    /* A surface (noctMeshCreateSurface()): any triangles, enclosing
     * nothing. Never convex, no box form, dual, filter or planes; no
     * containment test is made into it (noct_contains() says no). */
    bool surface;
    box_form box;
    box_dual dual;
    double lo[3], hi[3];
    size_t nv;
    double *v;          /* 3 * nv coordinates */
    size_t nt;
    uint32_t *tri;      /* 3 * nt vertex indices, outward, BVH order */
    /* Separating-axis filter (small meshes with few directions, else
     * nsat_* = 0): unique face normal and edge directions, up to sign,
     * the faces' at axis[0, nsat_faces), the edges' after them. */
    size_t nsat_faces, nsat_edges;
    /* With the filter: each triangle's plane (unit outward normal n, offset
     * d, n.x = d on the plane), in floating point. The exact level's
     * witness search ranks candidate points by them; the decision itself
     * is made by exact predicates. NULL without the filter. */
    double (*plane)[4];
    sat_axis *axis;
    size_t nhull;
    uint32_t *hull;     /* vertices of the convex hull */
    /* The boundary's pieces (triangles connected through shared
     * vertices): a vertex of each. With the boundaries apart, each piece
     * lies wholly inside the other solid or wholly outside it, so the
     * containment tests ask of one vertex per piece (one for most
     * meshes; a mesh of two separate cubes has two). */
    size_t npieces;
    uint32_t *piece;
    double centre[3];   /* mean of the hull vertices */
    size_t nnodes;
    bvh_node *nodes;    /* nodes[0] is the root */
};

/* Does every rotation noctQuatToMatrix() can give (entries within
 * NOCT_ROTATION_SNAP of a rotation's) keep each of m's triangles far from
 * the degeneracy noctMeshCreate() rejects, by a bound on the rotated
 * vertices' error, so that rotated views need not check them
 * (narrowphase_distance.c, rotated_fine())? Conservative: false when
 * unsure (a triangle tiny beside the mesh's distance from its origin). */
bool noct_mesh_turn_fine(const noctMesh *m);

/* The box form of 8 vertices v (and its dual, if every one of the nt
 * triangles tri lies on a face of the ideal box), given three unit edge
 * directions d: see box_form and box_dual (box_form.c). */
void noct_box_form_of(const double *v, const double *const d[3], const uint32_t *tri,
                      size_t nt, box_form *b, bool *has_box, box_dual *x, bool *has_dual);

/* m's box form and dual (has_box, has_dual), from its vertices and its
 * filter's directions (box_form.c). */
void noct_mesh_box_form(noctMesh *m);

/* The slot of a mesh with a box form (has_box) (mesh_box.c). */
void noct_box_slot_fill(const noctMesh *m, noct_box_slot *s);

/* The slot of a box primitive of half-extents half turned by R, for its
 * corners noct_box_corners() (box_form.c), made as noct_box_slot_turned()
 * makes a mesh's. */
void noct_box_slot_of_half(const double half[3], const double R[9], noct_box_slot *s);

/* Which of m's vertices is at which corner of its box, and which
 * triangles on which face, as box_dual names them, when m is a box-form
 * mesh with a dual or a box view (noct_box_view()); false otherwise
 * (mesh_box.c). */
bool noct_box_topology(const noctMesh *m, const uint8_t **corner, const uint8_t (**face)[2]);

/* The slot of m's box form turned by R, for its vertices placed as
 * fl(fl(R v) + t): made of the form (its corners, deviation and dual
 * turned, with bounds on R's rounding), not of the turned vertices
 * (box_form.c). has_box 0 without a form, shrink +inf without a dual. */
void noct_box_slot_turned(const noctMesh *m, const double R[9], noct_box_slot *s);

/* The oriented-box test on two slots placed at ta and tb: -1 when it
 * proves the solids apart, 1 when it proves that they share a point (both
 * have duals), 0 when it cannot tell. */
/* Continuous detection (narrowphase_swept.c): two box slots, A moving
 * from ta0 to ta1 and B from tb0 to tb1, proved apart over the whole
 * motion and at the end placements by a separating axis (false when it
 * cannot prove it). */
bool noct_swept_slots_apart(const noct_box_slot *a, const double ta0[3], const double ta1[3],
                            const noct_box_slot *b, const double tb0[3], const double tb1[3]);

/* A hit of nothing (noctSweepHit): time 1, no feature, no indices. */
static inline void noct_sweep_hit_none(noctSweepHit *h)
{
    *h = (noctSweepHit){.time = 1, .feature = NOCT_SWEEP_NONE,
                        .a = {UINT32_MAX, UINT32_MAX, UINT32_MAX},
                        .b = {UINT32_MAX, UINT32_MAX, UINT32_MAX}};
}

/* The centre of the overlap of a's box placed at ta and b's at tb (a hit's
 * point where no feature gives one). */
void noct_box_overlap_centre(const noctMesh *a, const double ta[3], const noctMesh *b,
                             const double tb[3], double c[3]);

/* A shape's motion for the conservative level (narrowphase_turning.c):
 * a mesh (unrotated), or a box primitive of half-extents half when shape
 * is NULL, from rotation q0 and translation p0 to q1 and p1. */
typedef struct noct_turning {
    const noctMesh *shape;
    const double *half;
    noctQuat q0, q1;
    const double *p0, *p1;
} noct_turning;

/* The conservative level on two such motions (narrowphase.h,
 * noctCollideSweptTransformed()); NOMEM, or a rotated mesh's status. */
noctStatus noct_collide_turning(const noct_turning *a, const noct_turning *b, bool *colliding,
                                noctSweepHit *hit, noctNarrowStats *stats);

int noct_box_decide(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                    const double tb[3]);

/* Does the solid that slot b describes, placed at tb, contain point p?
 * -1 proved outside (noct_box_decide()'s separating axes with p as a box
 * of no size, bit for bit), 1 proved inside (b has a dual: p within the
 * shrunk box on each of b's three face normals, a proof of its own, as
 * noct_box_decide() never proves a box of no size inside), 0 not decided
 * (narrowphase.c). */
int noct_point_slot_decide(const double p[3], const noct_box_slot *b, const double tb[3]);

/* The exact level on two box-form meshes that noct_box_decide() left
 * undecided: the witnesses, then the triangles. */
noctStatus noct_collide_undecided_boxes(const noctMesh *a, const double ta[3],
                                        const noctMesh *b, const double tb[3], bool *colliding,
                                        noctNarrowStats *stats);

/* noctCollide() past its argument checks and the box test, for a caller
 * that made them already, the box test on the same placed boxes
 * [fl(lo + t), fl(hi + t)] (world.c's pair search). */
noctStatus noct_collide_overlapping(const noctMesh *a, const double ta[3], const noctMesh *b,
                                    const double tb[3], noctAccuracy accuracy,
                                    bool *colliding, noctNarrowStats *stats);

/* ---- the world's queries (narrowphase.c) ---- */

/* Does the closed solid of m placed at t contain point p? Decided exactly
 * (on its boundary counts); NUMERIC only if 64 tries of the containment
 * count were all ambiguous. */
noctStatus noct_point_in_solid(const noctMesh *m, const double t[3], const double p[3],
                               bool *inside);

/* Does the closed segment pq meet the closed solid of m placed at t?
 * Decided exactly. When it does, *fraction is where along pq it first
 * does, in floating point in [0, 1]: 0 when p is in the solid (then
 * *triangle is UINT32_MAX and normal is 0), else where it enters
 * *triangle (the least fraction, ties to the lowest triangle), whose
 * unit outward normal, in floating point, is normal, computed without
 * overflow or underflow at any size. A triangle without area as placed
 * (*flat: a shape far from the origin for its size) has the unit vector
 * against pq as normal, and the fraction where pq passes nearest its
 * first corner. */
noctStatus noct_segment_hit(const noctMesh *m, const double t[3], const double p[3],
                            const double q[3], bool *hit, double *fraction,
                            uint32_t *triangle, double normal[3], bool *flat);

/* Does the separating-axis test on two slots placed at ta and tb prove
 * them more than d apart (on one of its 15 axes, with the allowances of
 * noct_box_decide())? false when it cannot. */
bool noct_box_apart_by(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                       const double tb[3], double d);
/* noct_box_apart_by() with a point p as the first slot (one of no size
 * placed at p), the same answer from B's face axes alone when that is
 * true; else the three face axes' gaps together, when B's axes are
 * proved within cos 2^-21 of orthogonal (the sum of their squares less
 * a proved allowance for the axes' tilt and the rounding: the bound on a
 * point near an edge or a corner; see narrowphase_distance.c). */
bool noct_point_apart_by(const double p[3], const noct_box_slot *b, const double tb[3],
                         double d);
/* noct_box_apart_by(), and when true the axis (not unit) along which the
 * box forms were proved farther apart than d, into axis. */
bool noct_box_apart_axis(const noct_box_slot *a, const double ta[3], const noct_box_slot *b,
                         const double tb[3], double d, double axis[3]);

/* The slack of the distance test below for these placed meshes and d:
 * 2^-40 of the largest coordinate of their placed boxes or d, whichever
 * is larger; it bounds the rounding of the floating-point distances. */
double noct_distance_slack(const noctMesh *a, const double ta[3], const noctMesh *b,
                           const double tb[3], double d);

/* Are the boundaries of two placed meshes within d + the slack of each
 * other? Each pair of triangles' distance is bounded from below, proved in
 * floating point (the largest gap on the separating axes that contain the
 * closest points' direction); for two solids that do not meet, their
 * distance is their boundaries'. So: true for every pair at most d apart
 * (never missed), and false for every pair more than d + 2 slack apart. */
bool noct_solids_within(const noctMesh *a, const double ta[3], const noctMesh *b,
                        const double tb[3], double d);

/* The contact of two meshes placed at ta and tb (already rotated), each
 * treated as convex or not (narrowphase.h, noctContact): kind
 * NOCT_CONTACT_NONE when they share no point (decided exactly); NOMEM,
 * NUMERIC (narrowphase_contact.c). */
noctStatus noct_contact_placed(const noctMesh *a, const double ta[3], bool a_convex,
                               const noctMesh *b, const double tb[3], bool b_convex,
                               noctContact *contact);

/* ---- box primitives (mesh.c) ---- */

/* The corners fl(R v) of the box with these half-extents (bit 2 of the
 * corner's index: +x, bit 1: +y, bit 0: +z). */
void noct_box_corners(const double half[3], const double R[9], double v[24]);

/* A box form of that box's corners, as a slot (sound as the one of the
 * mesh noct_mesh_of_box() makes, though its numbers may differ), and
 * their bounding box. */
void noct_box_slot_of_box(const double half[3], const double R[9], noct_box_slot *s,
                          double lo[3], double hi[3]);

/* The same for 8 corners numbered as noct_box_corners() numbers them,
 * near a box whose edges run along R's columns (a query's box: its own
 * corners, R the identity); has_box is 0 when they are too far from one. */
void noct_box_slot_of_corners(const double v[24], const double R[9], noct_box_slot *s,
                              double lo[3], double hi[3]);

/* The mesh of that box: its corners and 12 triangles. */
noctStatus noct_mesh_of_box(const double half[3], const double R[9], noctMesh **mesh,
                            noctError *err);

/* A read-only view of the solid with these box corners (as
 * noct_box_corners() gives them; degenerate boxes too) as a mesh: its 12
 * triangles, outward, in the order noct_mesh_of_box() gives them to
 * noctMeshCreate(), one BVH leaf (*leaf), the corners as its hull, no box
 * form and no filter; it lives as long as v and leaf. For the exact and
 * convex levels and the queries, which read nothing else; never
 * noctMeshDestroy() it. */
void noct_box_view(const double v[24], noctMesh *view, bvh_node *leaf);

/* Are the corners of that box turned by R within the coordinate limit
 * (as noctMeshCreate() requires of vertices)? TOO_LARGE if not. */
noctStatus noct_check_box_corners(const double half[3], const double R[9], noctError *err);

/* Half-extents a rotated box accepts: finite, normal, within the
 * coordinate limit, the least at least 2^-29 of the largest. */
noctStatus noct_check_box_half(const double half[3], noctError *err);

/* ---- transform.c ---- */

/* Is R the identity matrix? */
bool noct_is_identity(const double R[9]);

/* noctTransformCheck() that also gives the matrix (noctQuatToMatrix())
 * it checked, for callers that need both. */
noctStatus noct_transform_matrix(const noctTransform *x, double R[9], noctError *err);

/* out = fl(R v) in transform.h's order. */
void noct_rotate(const double R[9], const double v[3], double out[3]);

/* Spherical interpolation from q0 (s = 0) to q1 (s = 1) along the shorter
 * arc, each product and sum rounded once in a fixed order (the tracks'
 * interpolation, noctTrackAt()); normalized. */
noctQuat noct_quat_slerp(const noctQuat *q0, const noctQuat *q1, double s);

/* A new mesh of m's triangles with the vertices fl(R v). */
noctStatus noct_mesh_rotated(const noctMesh *m, const double R[9], noctMesh **out,
                             noctError *err);

/* ---- turning into a recycled copy (mesh.c) ---- */

/*
 * What turning one source mesh into a recycled turned copy needs without
 * allocating (noct_mesh_turn_into()): scratch for its nt triangles, the
 * source's directed edges sorted once, and the spare, a copy turned
 * before that no one reads any more (owned; NULL when there is none).
 */
typedef struct noct_turn {
    size_t nt;
    uint32_t *order, *pos;    /* nt: the BVH's order and its inverse */
    uint32_t *tri;            /* 3 nt */
    double *centroid;         /* 3 nt */
    double (*plane)[4];       /* nt */
    struct dir_edge *edges;   /* 3 nt, sorted, triangles by src's index */
    noctMesh *spare;
} noct_turn;

/* A turn for src (no spare yet), or NULL without memory. */
noct_turn *noct_turn_new(const noctMesh *src);

/* Free t and its spare; t may be NULL. */
void noct_turn_free(noct_turn *t);

/* Fill m, a mesh noct_mesh_rotated() made of src (by any rotation, and
 * perhaps refilled by this since), with what noct_mesh_rotated(src, R)
 * would make, field for field, without allocating; t is src's turn.
 * false when that mesh would not fit m's layout (or not be made): m is
 * then garbage, only fit for noctMeshDestroy(). */
bool noct_mesh_turn_into(const noctMesh *src, const double R[9], noct_turn *t, noctMesh *m);

/* Do a and b hold the same mesh, bit for bit in every field a reader
 * reads (their arrays compared, not their addresses)? */
bool noct_mesh_same(const noctMesh *a, const noctMesh *b);

#endif /* NOCT_LIB_MESH_INTERNAL_H */
