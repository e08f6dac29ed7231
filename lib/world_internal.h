/* SPDX-License-Identifier: MIT */
/*
 * Private: the world's structures, shared by its stage files. Never
 * installed.
 *
 *   world.c          create, destroy, reserve, what the world tells,
 *                    validation
 *   world_object.c   the object API: definitions, setters and getters,
 *                    removal; placement (poses, the step's placements)
 *   world_step.c     noctWorldStep() and its stages in the order they run
 *   world_motion.c   motion and walls, the movers, a failed step's roll-back
 *   world_narrow.c   narrowphase dispatch of the broadphase's pairs
 *   world_events.c   the event records, sensors and the response
 *   world_near.c     the margin's near pairs
 *   world_track.c    keyframe tracks
 *   world_ignore.c   the pairs the program ignores
 *   world_query.c    the queries (query.h)
 *   world_contact.c  the colliding pairs' contacts, on request
 *   world_distance.c the distance queries (query.h) and the near pairs'
 *                    distances
 *
 * The files call one way: world.c and world_step.c call the stage files
 * and world_object.c, which calls none of them.
 *
 * The world is the broadphase's client: its objects are proxies of the
 * broadphase it embeds (same slots, same handles), whose local boxes are
 * their meshes' boxes, placed at the objects' positions. Each stage has
 * its own struct: the narrowphase dispatch knows nothing of the tree or
 * its sweeps, the events nothing of either.
 */
#ifndef NOCT_LIB_WORLD_INTERNAL_H
#define NOCT_LIB_WORLD_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#include <noctree/world.h>

#include "broadphase_internal.h"
#include "mesh_internal.h"
#include "vec3.h"
#include "array.h"

/* What the motion loop reads of an object: one record. */
typedef struct noct_object {
    double vel[3], speed;  /* vel = speed * unit direction */
    double mlo[3], mhi[3]; /* the mesh's box, copied here for the motion loop */
    bool alive;
    bool sensor;           /* reports overlaps in the sensor lists only */
    uint8_t type;          /* noctObjectType */
    bool box;              /* a box primitive (its pose holds half-extents) */
    uint8_t quality;       /* noctMotionQuality */
} noct_object;

/* What the program set of an object and the step never reads: its
 * shape and its rotation. */
typedef struct noct_pose {
    union {
        const noctMesh *mesh; /* the mesh it was made with ... */
        double half[3];       /* ... or a box primitive's half-extents
                                 (noct_object.box says which) */
    } shape;
    noctMesh *rotated;      /* shape with its vertices rotated by R, owned;
                               NULL when R is the identity; for a box, its
                               mesh once an exact test needed it */
    noctQuat q;             /* as given; its matrix is noctQuatToMatrix(q) */
} noct_pose;

/* Motion: the movers and what a failed step restores. */
typedef struct noct_motion {
    uint32_t *movers;      /* live moving objects, by slot */
    uint32_t nmovers;
    size_t capmovers;
    double vmax;           /* the movers' greatest speed */
    bool stale;            /* objects came or went since movers was made */
    size_t moving;         /* live objects with a non-zero speed */
    uint32_t *slow;        /* movers that failed the fast test */
    uint32_t nslow;
    size_t capslow;
    /* What roll_back restores: per mover, its position before the step,
     * as the bits the motion loop streams out (noct_keep_position), and,
     * for a step of sub-steps, its velocity; and which velocity
     * components the walls turned (the mover, and a bit an axis). */
    int64_t (*prev)[3];
    double (*prevvel)[3];
    uint32_t *flips;       /* movers the walls turned, and which axes */
    uint8_t *flip_axes;
    uint32_t nflips;
    size_t capprev;
} noct_motion;

/* Events: the colliding pairs now and before, what began and ended. */
/*
 * One kind of pair the world reports (world_events.c): the pairs found
 * this step (now) and the step before, what began and ended between them
 * (sorted lists), and what a failed step of sub-steps gives back (held:
 * now as the step began). A step rotates the record (now becomes before),
 * finds now, and diffs; a failed step restores it with one call.
 */
typedef struct noct_event_record {
    noct_pair_list now, before, began, ended, held;
} noct_event_record;

typedef struct noct_events {
    noct_event_record contact; /* colliding pairs, neither object a sensor */
    noct_event_record sensor;  /* colliding pairs of a sensor and another */
    noct_event_record near;    /* with a margin: the pairs within it
                                  (world_near.c); never held */
} noct_events;

/* Angular velocity (#NOCT_EFFECT_SPIN): each moving object's rotation per
 * step, per slot, made when the first object gets one (NULL before, so a
 * world without spin keeps none); and the spinners, made again when
 * objects, types or angular velocities change. */
typedef struct noct_spin {
    noctQuat *w;           /* per slot; NULL: every one the identity */
    size_t count;          /* live objects with one not the identity */
    uint32_t *spinners;    /* live moving objects with one, by slot */
    uint32_t nspinners;
    size_t cap;
    bool stale;
} noct_spin;

/* The objects' own margins (noctObjectDef::margin): per slot, made when
 * the first object gets one (NULL before: every one 0, and a world
 * without them pays nothing); how many live objects have one above 0;
 * and max, at least each live object's (the largest once a step has
 * refreshed it: stale says a margin that was the largest went down). */
typedef struct noct_margins {
    double *of;
    size_t count;
    double max;
    bool stale;
    uint64_t edits;        /* bumped when an object comes or goes, its
                              margin is set or it is made a sensor or
                              not: the near stage's kept candidates
                              (noct_near_kept) are made again */
    bool near;             /* the next step finds near pairs: a margin
                              (the world's or an object's), or pairs the
                              last one kept to end */
} noct_margins;

/* A proof of the last step's near stage kept for the next (world_near.c)
 * for pair (i, j), i < j: NOCT_HINT_NEAR, the coefficients of a point of
 * each solid's shrunk box form (h[0..2] i's, h[3..5] j's) that were
 * within the margin; NOCT_HINT_APART, an axis along which the box forms
 * were farther apart. Only a hint: the next step proves the pair afresh
 * from it (a few dozen operations, where the proofs take a thousand) and
 * decides as before when that fails, so a hint for another pair, another
 * object in the slot or a turned shape is merely useless. */
enum { NOCT_HINT_NEAR = 1, NOCT_HINT_APART = 2 };
typedef struct noct_near_hint {
    uint32_t i, j;
    uint32_t kind;
    float h[6];
    float turn[2]; /* a mark of each box form's turn then: a hint whose
                      objects turned since is not tried */
} noct_near_hint;

/* The hints of the last step's candidate pairs, sorted by (i, j); at most
 * one a candidate of that step, none when a step could not make them all
 * (the hints are never needed: a step without them decides the same
 * pairs); and the spare array the next step makes its hints in (the two
 * swap), so that a step allocates nothing once they are large enough
 * (the spare goes when it is far larger than the last step's hints). Both
 * freed when a step finds the margin gone; a removed object's hints go
 * with the next step's. */
typedef struct noct_near_hints {
    noct_near_hint *h, *spare;
    size_t n, cap, capspare;
} noct_near_hints;

/* The near stage's scratch (world_near.c), kept from step to step (a
 * step of 100 000 objects would otherwise map and fault in some 30
 * megabytes anew, one page at a time): the candidate pairs, and the
 * arrays that make a list (near_sweep holds it during a step); each at
 * most a few times what the last step's objects, candidates and list
 * needed (else freed), and all freed with the margin. */
typedef struct noct_near_scratch {
    noct_pair_list cand, spare; /* (spare: the sort's other half) */
    struct near_box *g;         /* the gathered boxes */
    size_t capg;
    struct near_key *key;
    size_t capkey;
    struct near_run *run;
    size_t caprun;
    size_t *idx; /* the columns' cells and counts, the sort's counts */
    size_t capidx;
} noct_near_scratch;

/* The margin's candidate pairs kept from one step to the next
 * (world_near.c, near_candidates()): the pairs (i, j), i < j, whose boxes
 * met with i's grown by its grow and a skin when the list was made,
 * sorted, and every object's box then (ref, by slot). While no box has
 * moved by more than about half the skin since and no object came, went,
 * changed its margin or became a sensor or not (edits), each step's
 * candidates are among them, and are found by testing these pairs alone.
 * S, G: the bound on the coordinates and the largest grow then (for the
 * roundings); W, M: the world's margin and the largest own one then;
 * rate: the largest displacement of a box a step that the last list saw
 * (the next skin is made from it). Freed with the hints. */
typedef struct noct_near_kept {
    uint32_t (*p)[2];
    size_t n, cap;
    noct_aabb *ref;
    size_t capref;
    double skin, S, G, W, M, rate;
    uint64_t edits;
    uint32_t slots, age;
    uint32_t hold; /* steps without a list still, after one too large */
    bool valid;  /* the pairs may serve */
    bool ref_ok; /* ref holds the boxes of age steps ago (with the pairs,
                    or alone while objects move too fast for a list) */
    /* this step's candidates were made before its pair search
     * (noct_world_near_pairs()): 0 not, 1 none could be (each object
     * queries), 2 they are in x.cand */
    uint8_t early;
    /* a step's scratch, kept for the next: each object's grow, and the
     * rest (noct_near_scratch; while a step runs, near_sweep holds it) */
    double *grow;
    size_t capgrow;
    noct_near_scratch x;
} noct_near_kept;

/*
 * Continuous detection (accuracy #NOCT_ACCURACY_CONTINUOUS, or objects of
 * continuous quality; world_sweep.c):
 * per slot, where each object's next step starts (its position at the end
 * of the last step, or where it was made); its mesh's local box (base) and
 * how far each side of it the broadphase's local box is grown (grow), so
 * that its box at the step's end holds its box at the step's start; the
 * objects a program or a stage placed since their growth was last made
 * (todo, with a flag a slot); and the hits of the step's began contacts.
 * All NULL (and unused) until the world is continuous or has had a
 * continuous object (on).
 */
typedef struct noct_sweeps {
    bool on;
    bool world;            /* the world's accuracy is continuous */
    double (*start)[3];
    noctQuat *start_q;     /* and its rotation then */
    double (*from)[3];     /* where the last step started, for objects it
                              moved: those whose from_tick is its tick */
    noctQuat *from_q;
    uint64_t *from_tick;
    double *radius;        /* the shape's farthest point from its origin,
                              rounded up: how far a turn moves it */
    double (*base)[6];     /* lo, hi */
    double (*grow)[3];
    uint32_t *todo;
    uint8_t *in_todo;
    uint32_t ntodo;
    noctSweepHit *hits;    /* parallel to the contact record's began, */
    size_t caphits;
    bool hits_made;        /* made since the last step */
} noct_sweeps;

/* An object's track (#NOCT_EFFECT_TRACK): its keyframes, owned. */
typedef struct noct_track {
    uint32_t slot;
    noctKeyframe *keys;
    noctKeyTurn *turns; /* owned; NULL: the shorter arcs */
    size_t n;
} noct_track;

/* The tracks: a list, and per slot the index of its track in it
 * (UINT32_MAX: none), made when the first track is set (NULL before). */
typedef struct noct_tracks {
    noct_track *list;
    uint32_t n;
    size_t cap;
    uint32_t *of;          /* capof entries */
    uint32_t capof;
} noct_tracks;

/* The pairs the program ignores (noctWorldIgnorePair(); world_ignore.c):
 * their keys (lower slot << 32 | higher slot), sorted, without repeats;
 * NULL until the first. */
typedef struct noct_ignored {
    uint64_t *key;
    size_t n, cap;
} noct_ignored;

/* What a stage that places objects before the motion (spin, tracks)
 * changed of one object, for a failed step to give back: its quaternion,
 * its rotated mesh (owned here while the step runs, when a new one
 * replaced it) and its position. */
typedef struct noct_placed {
    uint32_t s;
    bool new_mesh;
    noctQuat q;
    noctMesh *mesh;
    double p[3];
} noct_placed;

struct noctWorld {
    noctWorldDef def;
    noctBroadphase bp;     /* the world's objects are its proxies */
    /* Per slot, with the broadphase's capacity. */
    noct_object *obj;
    double (*pos)[3];      /* the position (translation) */
    const noctMesh **mesh; /* the mesh as placed: the shape, or its rotated
                              copy (noct_pose); NULL for a box primitive
                              until its exact test needs one */
    noct_pose *pose;       /* what the program set (not read by the step) */
    noct_turn **turn;      /* per mesh object turned more than once: what
                              turning its shape again needs, and the
                              spare copy it turns into (NULL before) */
    noct_box_slot *slot;   /* per object with a box-form mesh: with pos,
                              all the exact level reads of most pairs of
                              boxes (64-byte aligned, two lines each) */
    uint32_t capslots;
    noct_motion motion;
    noct_events events;
    noct_spin spin;
    noct_margins margins;
    noct_near_hints hints;
    noct_near_kept kept;
    noct_tracks tracks;
    noct_ignored ignored;
    noct_sweeps sweeps;
    noct_placed *placed;   /* this step's placements (spin, tracks) */
    uint32_t nplaced, capplaced;
    uint64_t tick;         /* steps done */
    size_t nsensors;       /* live sensors */
    bool moved, touched;   /* this step moved objects; changed the tree */
    uint64_t substeps;     /* this step's */
    /* noctWorldContacts(): the contacts of contact.now, made on the first
     * call after a step (world_contact.c); made is cleared by each step. */
    noctContact *contacts;
    size_t capcontacts;
    bool contacts_made;
    noctWorldCounters c;   /* the world's own stages'; the broadphase's
                              are added when they are read */
    noctDistanceResult *near_dist; /* noctWorldNearDistances(), made on */
    size_t capnear_dist;           /* request after a step (never before) */
    bool near_dist_made;
};

/* A pair list for the program: its pairs and their number. */
static inline size_t noct_list_out(const noct_pair_list *l, const noctPair **pairs)
{
    *pairs = l->p;
    return l->n;
}

/* The live object a handle names, or NULL for a stale or unknown one. */
static inline noct_object *noct_world_lookup(const noctWorld *w, noctObjectId id)
{
    if (id.index >= noct_bp_slots(&w->bp) || !w->obj[id.index].alive ||
        noct_bp_generation(&w->bp, id.index) != id.generation)
        return NULL;
    return &w->obj[id.index];
}

/* Object s's mesh as made (NULL for a box primitive). */
static inline const noctMesh *noct_world_shape_of(const noctWorld *w, uint32_t s)
{
    return w->obj[s].box ? NULL : w->pose[s].shape.mesh;
}

static inline bool noct_quat_is_identity(const noctQuat *q)
{
    return q->x == 0 && q->y == 0 && q->z == 0 && q->w == 1;
}

/* Object s's own margin (0 for none). */
static inline double noct_world_margin(const noctWorld *w, uint32_t s)
{
    return w->margins.of != NULL ? w->margins.of[s] : 0;
}

/* ---- world_object.c ------------------------------------------------------------- */

/* The world's per-slot arrays to the broadphase's capacity; false without
 * memory (each that grew is kept). */
bool noct_world_reserve_slots(noctWorld *w);

/* The largest live object margin, made again (after one went down). */
void noct_world_refresh_margins(noctWorld *w);

/* Object s is gone: its track goes too. */
void noct_world_drop_track(noctWorld *w, uint32_t s);


/* noctWorldCreateObject() for a velocity that is speed * d for a unit d
 * (noctWorldAdd(), the families, scene files): the speed is kept as given,
 * so that the motion's bounds are those of the scenes' definitions. */
noctStatus noct_world_add_object(noctWorld *w, const noctObjectDef *def, double speed,
                                 noctObjectId *id, noctError *err);

/* Object s's placed mesh, made now for a box primitive that has none
 * (kept while its rotation lasts); NULL, with *st, if that failed. */
const noctMesh *noct_world_mesh(noctWorld *w, uint32_t s, noctStatus *st);

/* Place object s at q and p for a stage of the step (spin, tracks), as
 * noctWorldSetTransform() would, recording in w->placed (room reserved)
 * what noct_world_unplace() gives back; on failure nothing changed. */
noctStatus noct_world_place(noctWorld *w, uint32_t s, const noctQuat *q, const double p[3],
                            noctError *err);

/* Give back this step's placements (a failed step), last first; the
 * tree, which saw them, is torn down for the next step to build again. */
void noct_world_unplace(noctWorld *w);

/* Room for n placements this step; false without memory. */
bool noct_world_reserve_placed(noctWorld *w, uint32_t n);

/* A step that succeeded keeps its placements: the meshes they replaced
 * go, a mesh object's as its spare (noct_turn). */
void noct_world_placements_done(noctWorld *w);

/* Is object s's turned copy of its mesh shape (if it has one) what
 * noct_mesh_rotated() makes anew of the shape and its rotation, bit for
 * bit (recycled copies are refilled in place)? INVARIANT if not, NOMEM. */
noctStatus noct_world_check_turned(const noctWorld *w, uint32_t s, noctError *err);

/* ---- world_sweep.c ---------------------------------------------------------------- */

/* The sweeps' per-slot arrays to cap slots; false without memory. */
bool noct_world_reserve_sweeps(noctWorld *w, uint32_t cap);
void noct_world_free_sweeps(noctWorld *w);

/* Object s was made, placed or moved by the program: its growth is made
 * again at the next step (and, made, it starts there). */
void noct_world_sweep_touch(noctWorld *w, uint32_t s, bool made);

/* Object s's local box is its mesh's again (a new rotation): base is
 * taken from obj[s], the growth is owed. */
void noct_world_sweep_reshaped(noctWorld *w, uint32_t s);

/* Before the motion: every object that may move this step gets the
 * growth its motion asks for. NOMEM (nothing is lost: a growth not made
 * is owed). */
noctStatus noct_world_stage_grow(noctWorld *w);

/* After a step that succeeded: each object's next step starts where it
 * is. */
void noct_world_sweeps_done(noctWorld *w);

/* Is object s's motion tested continuously (sweeps on)? */
static inline bool noct_world_continuous(const noctWorld *w, uint32_t s)
{
    const uint8_t q = w->obj[s].quality;
    return q == NOCT_QUALITY_CONTINUOUS || (q == NOCT_QUALITY_WORLD && w->sweeps.world);
}

/* Where object s's step starts, as the continuous level takes it: its
 * start if it is continuous, where it is now if not. */
static inline const double *noct_world_from(const noctWorld *w, uint32_t s)
{
    return noct_world_continuous(w, s) ? w->sweeps.start[s] : w->pos[s];
}

static inline const noctQuat *noct_world_from_q(const noctWorld *w, uint32_t s)
{
    return noct_world_continuous(w, s) ? &w->sweeps.start_q[s] : &w->pose[s].q;
}

/* Did object s turn since its step started (as continuous detection
 * takes it)? */
static inline bool noct_world_turned(const noctWorld *w, uint32_t s)
{
    return memcmp(noct_world_from_q(w, s), &w->pose[s].q, sizeof(noctQuat)) != 0;
}

/* Make the sweeps' records for every object (the first continuous object
 * of a discrete world); false without memory (nothing changed). */
bool noct_world_sweeps_enable(noctWorld *w);

/* The continuous level on a pair over the step under way: its verdict. */
noctStatus noct_world_sweep_pair(noctWorld *w, uint32_t a, uint32_t b, bool *colliding);

/* ---- world_ignore.c -------------------------------------------------------------- */

static inline uint64_t noct_ignored_key(uint32_t a, uint32_t b)
{
    return a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
}

/* Is the pair of slots a and b ignored? (A binary search: call it only
 * when w->ignored.n > 0.) */
static inline bool noct_world_ignored(const noctWorld *w, uint32_t a, uint32_t b)
{
    const uint64_t k = noct_ignored_key(a, b);
    const uint64_t *key = w->ignored.key;
    size_t lo = 0, hi = w->ignored.n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (key[mid] < k)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < w->ignored.n && key[lo] == k;
}

/* Object s is gone: the pairs of its slot are no longer ignored. */
void noct_world_forget_ignored(noctWorld *w, uint32_t s);

/* ---- world_track.c --------------------------------------------------------------- */

/* Place every tracked object at its track's pose at tick (the step's);
 * on failure give the placements back (noct_world_unplace()). */
noctStatus noct_world_stage_tracks(noctWorld *w, uint64_t tick, noctError *err);

void noct_world_free_tracks(noctWorld *w);

/* ---- world_query.c ----------------------------------------------------------------- */

/* A box primitive's shape as a read-only view of its corners. */
typedef struct noct_shape_view {
    noctMesh view;
    bvh_node leaf;
    double corners[24];
} noct_shape_view;

/* Object s's placed shape, to be placed at w->pos[s]: its mesh (rotated
 * as placed), or a view of its box primitive's corners in *v; reads the
 * world only (no mesh is made). */
const noctMesh *noct_world_shape(const noctWorld *w, uint32_t s, noct_shape_view *v);

/* A query's shape, placed by a transform's rotation: a mesh (rotated
 * when it must be) or a box primitive's corners as a view; with its box
 * slot when it has a box form. */
typedef struct noct_query_shape {
    const noctMesh *m;
    noctMesh *rotated;     /* owned: noctMeshDestroy() it */
    noctMesh view;
    bvh_node leaf;
    double v[24];
    noct_box_slot slot;
    bool has_slot;
} noct_query_shape;

/* Make the shape of mesh (or of the box primitive of half_extents when
 * mesh is NULL) at x's rotation, checking x and the half-extents as
 * noctWorldCreateObject() does. */
noctStatus noct_query_shape_make(noct_query_shape *q, const noctMesh *mesh,
                                 const double half_extents[3], const noctTransform *x,
                                 noctError *err);

/* ---- world_events.c (the lists) --- */

/* began += now - before, ended += before - now (sorted lists; a pair
 * whose objects' generations differ is another pair). NOMEM. */
noctStatus noct_world_diff_lists(const noct_pair_list *now, const noct_pair_list *before,
                                 noct_pair_list *began, noct_pair_list *ended);

/* ---- world_near.c ------------------------------------------------------------------ */

/* The near pairs after the step's pairs (the contact record's now is this
 * step's): the near record is rotated, now is found, and with events its
 * differences. On failure (NOMEM) now and before are as they were. */
noctStatus noct_world_stage_near(noctWorld *w, noctError *err);

/* Before a step's pair search, when it would find no pair that the near
 * stage's candidates and a query of each sensor's box do not hold (a
 * margin, few sensors, a leaf's pairs not all tested): the candidates
 * made now rather than in the near stage, and, when they could be made,
 * the pair search's pairs taken from them (the candidates whose boxes
 * overlap) and the sensors' queries, its search skipped. 1: the
 * pairs are found; 0: the search must find them; -1 without memory (the
 * step fails). noct_world_near_forget() after a step that failed. */
int noct_world_near_pairs(noctWorld *w);
void noct_world_near_forget(noctWorld *w);

/* Frees the near stage's kept list and scratch (w->kept) and empties it. */
void noct_world_free_kept(noctWorld *w);

/* ---- world_motion.c ---------------------------------------------------------------- */

/* The live movers in slot order and room for the step's records, after
 * objects came or went; false without memory. */
bool noct_world_update_movers(noctWorld *w);

/* Move every mover by fraction of its velocity, with the walls, and place
 * its box; with incremental maintenance, list in motion.slow those that
 * fail the fast test. first: the step's first sub-step (keep what
 * roll_back needs). Returns the first mover beyond NOCT_MAX_COORDINATE,
 * or UINT32_MAX. */
uint32_t noct_world_move(noctWorld *w, double fraction, bool first);

/* Has a mover's box left the root? */
bool noct_world_movers_escaped(const noctWorld *w);

/* After a failed stage: movers back to where the step began, and a tree
 * that was touched torn down. */
void noct_world_roll_back(noctWorld *w, bool moved, bool tree_touched);

/* The moving object that moves farthest for its size, and how far. */
double noct_world_step_ratio(const noctWorld *w, uint32_t *which);

/* ---- world_narrow.c ---------------------------------------------------------------- */

/* The narrowphase, at the world's accuracy, on the pairs whose boxes
 * overlap (sorted by their first object); the colliding ones are appended
 * to colliding, with their generations. */
noctStatus noct_world_narrow(noctWorld *w, const noct_pair_list *tested,
                             noct_pair_list *colliding);

/* ---- world_events.c ---------------------------------------------------------------- */

/* Before a search: now becomes before, and now is emptied. */
void noct_record_rotate(noct_event_record *r);

/* A search that failed: now and before as they were before
 * noct_record_rotate(). */
void noct_record_unrotate(noct_event_record *r);

/* began += now - before, ended += before - now; *events (if not NULL)
 * counts them.
 * NOMEM (the lists keep what they had, and perhaps a part of it). */
noctStatus noct_record_diff(noct_event_record *r, uint64_t *events);

/* Keep now in held, for a step of sub-steps; false without memory. */
bool noct_record_hold(noct_event_record *r);

/* began and ended emptied (a step starts; a step failed). */
void noct_record_clear(noct_event_record *r);

/* A step failed: its events go, and with held (a step of sub-steps, whose
 * searches replaced now), now is what it was when the step began. */
void noct_record_fail(noct_event_record *r, bool held);

void noct_record_free(noct_event_record *r);

/* Move the pairs of a sensor and an object that is not one from the
 * contact record's now to the sensor record's (both stay sorted). */
noctStatus noct_world_split_sensors(noct_events *e, const noct_object *obj);

/* The response: every object in a pair that began (from the from'th on)
 * reverses its direction once (marked with a new epoch in mark: the
 * broadphase's stamps, which every use starts with a new epoch). */
void noct_world_respond(noct_events *e, noct_object *obj, noctBroadphase *bp, size_t from,
                        uint64_t *reversals);

#endif /* NOCT_LIB_WORLD_INTERNAL_H */
