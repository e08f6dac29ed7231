/* SPDX-License-Identifier: MIT */
/*
 * The collision world (world.h): objects with meshes, positions and
 * velocities, as proxies of the broadphase it embeds, and noctWorldStep()
 * as the sequence of its stages, each in its own file (world_internal.h):
 * motion, maintenance through the broadphase, the pair search, the
 * narrowphase dispatch, events and response, in sub-steps if the scene
 * asks for them.
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <noctree/world.h>

#include "world_internal.h"

/* ---- the world and its objects ----------------------------------------------------- */

noctWorldDef noctDefaultWorldDef(void)
{
    noctWorldDef d;
    d.N = NOCT_AUTO;
    d.max_depth = NOCT_AUTO;
    d.accuracy = NOCT_ACCURACY_EXACT;
    d.effects = NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE;
    d.maintenance = NOCT_MAINTAIN_INCREMENTAL;
    for (int k = 0; k < 3; ++k)
        d.walls_lo[k] = d.walls_hi[k] = 0;
    d.margin = 0;
    return d;
}

noctStatus noctWorldCreate(const noctWorldDef *def, noctWorld **world, noctError *err)
{
    NOCT_REQUIRE(def != NULL && world != NULL);
    *world = NULL;
    if (def->accuracy != NOCT_ACCURACY_BOX && def->accuracy != NOCT_ACCURACY_CONVEX &&
        def->accuracy != NOCT_ACCURACY_EXACT)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown accuracy %d",
                         (int)def->accuracy);
    if (def->effects & ~(unsigned)(NOCT_EFFECT_MOTION | NOCT_EFFECT_EVENTS |
                                   NOCT_EFFECT_RESPONSE | NOCT_EFFECT_WALLS |
                                   NOCT_EFFECT_SUBSTEP | NOCT_EFFECT_SPIN |
                                   NOCT_EFFECT_TRACK))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown effect bits 0x%x",
                         def->effects);
    if (def->maintenance != NOCT_MAINTAIN_INCREMENTAL &&
        def->maintenance != NOCT_MAINTAIN_REBUILD)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown maintenance mode %d",
                         (int)def->maintenance);
    if (def->effects & NOCT_EFFECT_WALLS)
        for (int k = 0; k < 3; ++k)
            if (!isfinite(def->walls_lo[k]) || !isfinite(def->walls_hi[k]) ||
                !(def->walls_lo[k] < def->walls_hi[k]))
                return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                                 "the walls need a finite container with lo < hi "
                                 "on every axis");
    if (!(def->margin >= 0 && def->margin <= NOCT_MAX_COORDINATE))
        return noct_fail(err, isnan(def->margin) ? NOCT_ERR_NONFINITE : NOCT_ERR_INVALID, -1, 0,
                         "margin %g: it must be 0 to %g", def->margin, NOCT_MAX_COORDINATE);
    noctWorld *w = calloc(1, sizeof *w);
    if (w == NULL)
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    /* N and the depth are checked (and, for NOCT_AUTO, chosen) there */
    noctBroadphaseDef bd = noctDefaultBroadphaseDef();
    bd.N = def->N;
    bd.max_depth = def->max_depth;
    noctStatus st = noct_bp_init(&w->bp, &bd, err);
    if (st != NOCT_OK) {
        free(w);
        return st;
    }
    w->bp.rebuild_mode = def->maintenance == NOCT_MAINTAIN_REBUILD;
    w->def = *def;
    *world = w;
    return NOCT_OK;
}


void noctWorldDestroy(noctWorld *w)
{
    if (w == NULL)
        return;
    for (uint32_t i = 0; i < w->bp.nslots; ++i)
        if (w->obj[i].alive)
            noctMeshDestroy(w->pose[i].rotated);
    noct_bp_fini(&w->bp);
    free(w->obj);
    free(w->pose);
    free(w->pos);
    free(w->mesh);
    free(w->slot);
    free(w->motion.movers);
    free(w->motion.slow);
    free(w->motion.prev);
    free(w->motion.prevvel);
    free(w->motion.flips);
    free(w->motion.flip_axes);
    free(w->events.colliding.p);
    free(w->events.previous.p);
    free(w->events.began.p);
    free(w->events.ended.p);
    free(w->events.held.p);
    free(w->events.sensing.p);
    free(w->events.sensing_prev.p);
    free(w->events.sensor_began.p);
    free(w->events.sensor_ended.p);
    free(w->events.sensing_held.p);
    free(w->events.near.p);
    free(w->events.near_prev.p);
    free(w->events.near_began.p);
    free(w->events.near_ended.p);
    free(w->spin.w);
    free(w->spin.spinners);
    free(w->placed);
    noct_world_free_tracks(w);
    free(w);
}

_Static_assert(sizeof(noct_pose) == 64, "a pose is one cache line");

static noct_object *lookup(const noctWorld *w, noctObjectId id)
{
    if (id.index >= w->bp.nslots || !w->obj[id.index].alive ||
        w->bp.gen[id.index] != id.generation)
        return NULL;
    return &w->obj[id.index];
}

/* The world's per-slot arrays to the broadphase's capacity; each that
 * grew is kept even if a later one fails. */
static bool reserve_slots(noctWorld *w)
{
    const uint32_t cap = w->bp.capslots;
    if (cap <= w->capslots)
        return true;
#define GROW(field)                                                      \
    do {                                                                 \
        void *q = realloc(w->field, (size_t)cap * sizeof *w->field);     \
        if (q == NULL)                                                   \
            return false;                                                \
        w->field = q;                                                    \
    } while (0)
    GROW(obj);
    GROW(pos);
    GROW(mesh);
    if (w->spin.w != NULL)
        GROW(spin.w);
#undef GROW
    /* aligned, so not realloc: a pose is one cache line */
    noct_pose *poses = aligned_alloc(64, cap * sizeof *poses);
    if (poses == NULL)
        return false;
    if (w->capslots > 0)
        memcpy(poses, w->pose, w->capslots * sizeof *poses);
    free(w->pose);
    w->pose = poses;
    noct_box_slot *slots = aligned_alloc(64, cap * sizeof *slots);
    if (slots == NULL)
        return false;
    if (w->capslots > 0)
        memcpy(slots, w->slot, w->capslots * sizeof *slots);
    free(w->slot);
    w->slot = slots;
    w->capslots = cap;
    return true;
}

noctStatus noctWorldReserve(noctWorld *w, size_t more, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (more > 0x80000000u)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                         "room for %zu more objects: a world holds at most 2^31", more);
    if (!noct_bp_reserve(&w->bp, (uint32_t)more))
        return (uint64_t)w->bp.nslots - w->bp.nfree + more > 0x80000000u
                   ? noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                               "room for %zu more objects: a world holds at most 2^31",
                               more)
                   : noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (!reserve_slots(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    return NOCT_OK;
}

noctObjectDef noctDefaultObjectDef(void)
{
    noctObjectDef d;
    memset(&d, 0, sizeof d);
    d.mesh = NULL;
    d.transform = noctIdentityTransform();
    d.type = NOCT_OBJECT_MOVING;
    d.user_data = NULL;
    d.category = d.mask = NOCT_FILTER_ALL;
    d.angular_velocity = (noctQuat){0, 0, 0, 1};
    return d;
}

static noctStatus check_velocity(const double v[3], noctError *err)
{
    for (int k = 0; k < 3; ++k)
        if (!isfinite(v[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                             "velocity (%g, %g, %g) is not finite", v[0], v[1], v[2]);
    return NOCT_OK;
}

/* A translation as noctTransformCheck() checks it. */
static noctStatus check_position(const double p[3], noctError *err)
{
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(p[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                             "translation (%g, %g, %g) is not finite", p[0], p[1], p[2]);
        if (fabs(p[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                             "translation (%g, %g, %g) lies beyond %g", p[0], p[1], p[2],
                             NOCT_MAX_COORDINATE);
    }
    return NOCT_OK;
}

/* The failure of a handle that names no live object. */
static noctStatus stale(noctObjectId id, noctError *err)
{
    return noct_fail(err, NOCT_ERR_INVALID, (long)id.index, 0,
                     "stale or unknown object handle (%u, %u)", id.index, id.generation);
}

static bool known_type(noctObjectType t)
{
    return t == NOCT_OBJECT_STATIC || t == NOCT_OBJECT_KINEMATIC || t == NOCT_OBJECT_MOVING;
}

/* |v|, rounded up a little: the motion's reach and sub-steps take it as
 * a bound on the distance moved. */
static double speed_of(const double v[3])
{
    const double m = noct_max(noct_max(fabs(v[0]), fabs(v[1])), fabs(v[2]));
    const double a = v[0] / m, b = v[1] / m, c = v[2] / m; /* no overflow */
    return m * sqrt(a * a + b * b + c * c) * (1 + 0x1p-40);
}

/* The mesh of a shape rotated by R: the shape itself for the identity,
 * else a new rotated copy in *rotated. */
static noctStatus rotate_shape(const noctMesh *shape, const double R[9], noctMesh **rotated,
                               noctError *err)
{
    *rotated = NULL;
    if (shape == NULL || noct_is_identity(R))
        return NOCT_OK; /* a box primitive's mesh is made when needed */
    noctStatus st = noct_mesh_rotated(shape, R, rotated, err);
    if (st != NOCT_OK && err != NULL) {
        char why[NOCT_ERROR_MESSAGE_SIZE];
        memcpy(why, err->message, sizeof why);
        noct_fail(err, st, err->index, 0, "the rotated mesh: %s", why);
    }
    return st;
}

/* Object s's mesh as made (NULL for a box primitive). */
static const noctMesh *shape_of(const noctWorld *w, uint32_t s)
{
    return w->obj[s].box ? NULL : w->pose[s].shape.mesh;
}

/* The local box of object s's shape turned by R: of the mesh (rotated,
 * or the shape), or of a box primitive's corners. */
static void local_box(const noctWorld *w, uint32_t s, const noctMesh *rotated,
                      const double R[9], double lo[3], double hi[3])
{
    if (w->obj[s].box) {
        noct_box_slot slot;
        noct_box_slot_of_box(w->pose[s].shape.half, R, &slot, lo, hi);
        return;
    }
    const noctMesh *m = rotated != NULL ? rotated : w->pose[s].shape.mesh;
    memcpy(lo, m->lo, 3 * sizeof *lo);
    memcpy(hi, m->hi, 3 * sizeof *hi);
}

/* An object's placed mesh (a box primitive's, once made: NULL before),
 * its box form and local box, from its pose. */
static void place_mesh(noctWorld *w, uint32_t s)
{
    const noct_pose *p = &w->pose[s];
    noct_object *o = &w->obj[s];
    if (o->box) {
        w->mesh[s] = p->rotated;
        double R[9];
        noctQuatToMatrix(&p->q, R, NULL);
        noct_box_slot_of_box(p->shape.half, R, &w->slot[s], o->mlo, o->mhi);
        return;
    }
    const noctMesh *m = p->rotated != NULL ? p->rotated : p->shape.mesh;
    w->mesh[s] = m;
    memcpy(o->mlo, m->lo, sizeof o->mlo);
    memcpy(o->mhi, m->hi, sizeof o->mhi);
    if (m->has_box)
        noct_box_slot_fill(m, &w->slot[s]);
    else
        w->slot[s].has_box = 0;
}

const noctMesh *noct_world_mesh(noctWorld *w, uint32_t s, noctStatus *st)
{
    if (w->mesh[s] != NULL)
        return w->mesh[s];
    noct_pose *p = &w->pose[s];
    NOCT_INVARIANT(w->obj[s].box && p->rotated == NULL);
    /* the corners were checked (noct_check_box_corners) when the object
     * was made or turned */
    double R[9];
    noctQuatToMatrix(&p->q, R, NULL);
    *st = noct_mesh_of_box(p->shape.half, R, &p->rotated, NULL);
    if (*st != NOCT_OK)
        return NULL;
    w->mesh[s] = p->rotated;
    return p->rotated;
}

/* Make object o moving at velocity v, or not moving (v kept in its pose). */
static void set_motion(noctWorld *w, uint32_t s, noctObjectType type, const double v[3])
{
    noct_object *o = &w->obj[s];
    const bool was = o->speed > 0;
    o->type = (uint8_t)type;
    /* a static or kinematic object keeps its velocity here too, but with
     * speed 0 neither the motion nor the response reads it */
    memcpy(o->vel, v, sizeof o->vel);
    o->speed = type == NOCT_OBJECT_MOVING && (v[0] != 0 || v[1] != 0 || v[2] != 0)
                   ? speed_of(v)
                   : 0;
    const bool is = o->speed > 0;
    NOCT_INVARIANT(w->motion.moving >= (size_t)was);
    w->motion.moving = w->motion.moving - was + is;
    /* the movers list and its greatest speed are made again */
    w->motion.stale = w->motion.stale || was || is;
    w->spin.stale = true;
}

/* An object's velocity: the moving one's, or the one its pose keeps. */
static const double *velocity_of(const noctWorld *w, uint32_t s)
{
    return w->obj[s].vel;
}

static bool is_identity_quat(const noctQuat *q)
{
    return q->x == 0 && q->y == 0 && q->z == 0 && q->w == 1;
}

/* Give slot s the angular velocity q (checked), making the per-slot array
 * when the first one that is not the identity comes; false without
 * memory (then nothing changed). */
static bool set_spin(noctWorld *w, uint32_t s, const noctQuat *q, bool was_live)
{
    const bool none = is_identity_quat(q);
    if (w->spin.w == NULL) {
        if (none)
            return true;
        noctQuat *a = malloc(w->capslots * sizeof *a);
        if (a == NULL)
            return false;
        for (uint32_t i = 0; i < w->capslots; ++i)
            a[i] = (noctQuat){0, 0, 0, 1};
        w->spin.w = a;
    }
    const bool had = was_live && !is_identity_quat(&w->spin.w[s]);
    w->spin.w[s] = *q;
    w->spin.count = w->spin.count - had + !none;
    w->spin.stale = true;
    return true;
}

/* An angular velocity as noctQuatToMatrix() checks a rotation. */
static noctStatus check_spin(const noctQuat *q, noctError *err)
{
    double R[9];
    noctStatus st = noctQuatToMatrix(q, R, err);
    if (st != NOCT_OK && err != NULL) {
        char why[NOCT_ERROR_MESSAGE_SIZE];
        memcpy(why, err->message, sizeof why);
        noct_fail(err, st, -1, 0, "angular velocity: %s", why);
    }
    return st;
}

noctStatus noctWorldCreateObject(noctWorld *w, const noctObjectDef *def, noctObjectId *id,
                                 noctError *err)
{
    NOCT_REQUIRE(w != NULL && def != NULL && id != NULL);
    id->index = id->generation = 0;
    noctStatus st = noctTransformCheck(&def->transform, err);
    if (st == NOCT_OK && def->mesh == NULL) {
        if (def->half_extents[0] == 0 && def->half_extents[1] == 0 &&
            def->half_extents[2] == 0)
            return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                             "an object needs a mesh or a box's half-extents");
        st = noct_check_box_half(def->half_extents, err);
    }
    if (st == NOCT_OK)
        st = check_velocity(def->velocity, err);
    if (st == NOCT_OK)
        st = check_spin(&def->angular_velocity, err);
    if (st != NOCT_OK)
        return st;
    if (!known_type(def->type))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown object type %d",
                         (int)def->type);
    if (def->category == 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                         "an object's category is 0: it could never pair");
    double R[9];
    noctQuatToMatrix(&def->transform.q, R, NULL); /* checked above */
    if (def->mesh == NULL && (st = noct_check_box_corners(def->half_extents, R, err)) != NOCT_OK)
        return st;
    noctMesh *rotated;
    st = rotate_shape(def->mesh, R, &rotated, err);
    if (st != NOCT_OK)
        return st;
    const uint32_t slot = noct_bp_new_slot(&w->bp);
    if (slot == UINT32_MAX) {
        noctMeshDestroy(rotated);
        return w->bp.nslots >= 0x80000000u
                   ? noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "too many objects")
                   : noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    if (!reserve_slots(w)) {
        noct_bp_unuse_slot(&w->bp, slot);
        noctMeshDestroy(rotated);
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    noct_object *o = &w->obj[slot];
    memset(o, 0, sizeof *o);
    noct_pose *p = &w->pose[slot];
    memset(p, 0, sizeof *p);
    o->box = def->mesh == NULL;
    if (o->box)
        memcpy(p->shape.half, def->half_extents, sizeof p->shape.half);
    else
        p->shape.mesh = def->mesh;
    p->rotated = rotated;
    p->q = def->transform.q;
    place_mesh(w, slot);
    memcpy(w->pos[slot], def->transform.p, sizeof w->pos[slot]);
    if (!set_spin(w, slot, &def->angular_velocity, false)) {
        /* not in the broadphase yet: the slot goes back as it is */
        noct_bp_unuse_slot(&w->bp, slot);
        st = NOCT_ERR_NOMEM;
    } else {
        /* on failure noct_bp_add gives the slot back itself */
        st = noct_bp_add(&w->bp, slot, o->mlo, o->mhi, w->pos[slot], def->user_data,
                         def->category, def->mask);
    }
    if (st != NOCT_OK) {
        if (w->spin.w != NULL && !is_identity_quat(&w->spin.w[slot])) {
            w->spin.w[slot] = (noctQuat){0, 0, 0, 1};
            --w->spin.count;
        }
        p->rotated = NULL;
        noctMeshDestroy(rotated);
        return noct_fail(err, st, -1, 0, "out of memory");
    }
    o->alive = true;
    o->sensor = def->sensor;
    w->nsensors += def->sensor;
    set_motion(w, slot, def->type, def->velocity);
    id->index = slot;
    id->generation = w->bp.gen[slot];
    return NOCT_OK;
}

noctStatus noctWorldAdd(noctWorld *w, const noctMesh *mesh, const double position[3],
                        const double direction[3], double speed, noctObjectId *id,
                        noctError *err)
{
    NOCT_REQUIRE(w != NULL && mesh != NULL && position != NULL && direction != NULL);
    NOCT_REQUIRE(id != NULL);
    id->index = id->generation = 0;
    for (int k = 0; k < 3; ++k)
        if (!isfinite(position[k]))
            return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "object position is not finite");
    if (!isfinite(speed))
        return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0, "object speed is not finite");
    if (speed < 0)
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "object speed %g is negative",
                         speed);
    for (int k = 0; k < 3; ++k)
        if (fabs(position[k]) > NOCT_MAX_COORDINATE)
            return noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0,
                             "object position beyond %g", NOCT_MAX_COORDINATE);
    /* A static object's direction is ignored, whatever it holds. */
    double unit[3] = {0, 0, 0};
    if (speed > 0) {
        for (int k = 0; k < 3; ++k)
            if (!isfinite(direction[k]))
                return noct_fail(err, NOCT_ERR_NONFINITE, -1, 0,
                                 "object direction is not finite");
        if (!noct_unit_direction(direction, unit))
            return noct_fail(err, NOCT_ERR_INVALID, -1, 0,
                             "a moving object needs a non-zero direction");
    }
    noctObjectDef def = noctDefaultObjectDef();
    def.mesh = mesh;
    memcpy(def.transform.p, position, sizeof def.transform.p);
    for (int k = 0; k < 3; ++k)
        def.velocity[k] = speed * unit[k];
    return noct_world_add_object(w, &def, speed, id, err);
}

noctStatus noct_world_add_object(noctWorld *w, const noctObjectDef *def, double speed,
                                 noctObjectId *id, noctError *err)
{
    noctStatus st = noctWorldCreateObject(w, def, id, err);
    if (st == NOCT_OK && speed > 0 && w->obj[id->index].speed > 0)
        w->obj[id->index].speed = speed; /* as given: |velocity| within 1e-9 */
    return st;
}

noctStatus noctWorldRemove(noctWorld *w, noctObjectId id, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    noct_object *o = lookup(w, id);
    if (o == NULL)
        return stale(id, err);
    set_motion(w, id.index, NOCT_OBJECT_STATIC, velocity_of(w, id.index));
    noct_bp_free_slot(&w->bp, id.index); /* cannot fail */
    o->alive = false;
    NOCT_INVARIANT(w->nsensors >= (size_t)o->sensor);
    w->nsensors -= o->sensor;
    o->sensor = false;
    if (w->spin.w != NULL) {
        w->spin.count -= !is_identity_quat(&w->spin.w[id.index]);
        w->spin.w[id.index] = (noctQuat){0, 0, 0, 1};
        w->spin.stale = true;
    }
    noctMeshDestroy(w->pose[id.index].rotated);
    w->pose[id.index].rotated = NULL;
    noct_world_drop_track(w, id.index);
    /* The lists stay: the colliding one holds its pairs, which the next
     * step's diff ends. */
    return NOCT_OK;
}

noctStatus noctWorldSetTransform(noctWorld *w, noctObjectId id, const noctTransform *x,
                                 noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL);
    /* lookup() through the proxy, whose line the fast test reads anyway
     * (a world object is alive when its proxy is: noctWorldValidate()) */
    const uint32_t s = id.index;
    if (s >= w->bp.nslots || !w->bp.proxy[s].alive || w->bp.gen[s] != id.generation)
        return stale(id, err);
    noct_pose *p = &w->pose[s];
    /* The same quaternion, bit for bit (a program that only moves the
     * object): it was checked when it was set, the object keeps its
     * rotated shape, and the fast test may settle the move at once. */
    const bool same = memcmp(&x->q, &p->q, sizeof x->q) == 0;
    noctStatus st = same ? check_position(x->p, err) : noctTransformCheck(x, err);
    if (st != NOCT_OK)
        return st;
    if (same && !w->bp.tree_owed &&
        noct_bp_move_fast(&w->bp, s, x->p)) {
        memcpy(w->pos[s], x->p, sizeof w->pos[s]);
        return NOCT_OK;
    }
    double R[9], was[9];
    bool turned = false;
    if (!same) {
        noctQuatToMatrix(&x->q, R, NULL); /* checked above */
        noctQuatToMatrix(&p->q, was, NULL);
        turned = memcmp(R, was, sizeof R) != 0;
    }
    noctMesh *rotated = p->rotated;
    if (turned && w->obj[s].box &&
        (st = noct_check_box_corners(p->shape.half, R, err)) != NOCT_OK)
        return st;
    if (turned && (st = rotate_shape(shape_of(w, s), R, &rotated, err)) != NOCT_OK)
        return st;
    double lo[3], hi[3];
    if (turned) {
        local_box(w, s, rotated, R, lo, hi);
    } else {
        memcpy(lo, w->obj[s].mlo, sizeof lo);
        memcpy(hi, w->obj[s].mhi, sizeof hi);
    }
    st = noct_bp_move_to(&w->bp, s, lo, hi, x->p);
    if (st != NOCT_OK) {
        if (turned && rotated != p->rotated)
            noctMeshDestroy(rotated);
        return noct_fail(err, st, (long)s, 0, "moving object %u: out of memory", s);
    }
    if (turned) {
        noctMeshDestroy(p->rotated);
        p->rotated = rotated;
        p->q = x->q;
        place_mesh(w, s);
    }
    p->q = x->q;
    memcpy(w->pos[s], x->p, sizeof w->pos[s]);
    return NOCT_OK;
}

noctStatus noctWorldGetTransform(const noctWorld *w, noctObjectId id, noctTransform *x)
{
    NOCT_REQUIRE(w != NULL && x != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(x->p, w->pos[id.index], sizeof x->p);
    x->q = w->pose[id.index].q;
    return NOCT_OK;
}

noctStatus noctWorldSetVelocity(noctWorld *w, noctObjectId id, const double velocity[3],
                                noctError *err)
{
    NOCT_REQUIRE(w != NULL && velocity != NULL);
    if (lookup(w, id) == NULL)
        return stale(id, err);
    noctStatus st = check_velocity(velocity, err);
    if (st != NOCT_OK)
        return st;
    set_motion(w, id.index, (noctObjectType)w->obj[id.index].type, velocity);
    return NOCT_OK;
}

noctStatus noctWorldGetVelocity(const noctWorld *w, noctObjectId id, double velocity[3])
{
    NOCT_REQUIRE(w != NULL && velocity != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(velocity, velocity_of(w, id.index), 3 * sizeof *velocity);
    return NOCT_OK;
}

noctStatus noctWorldSetType(noctWorld *w, noctObjectId id, noctObjectType type,
                            noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (lookup(w, id) == NULL)
        return stale(id, err);
    if (!known_type(type))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown object type %d", (int)type);
    double v[3];
    memcpy(v, velocity_of(w, id.index), sizeof v);
    set_motion(w, id.index, type, v);
    return NOCT_OK;
}

noctStatus noctWorldGetType(const noctWorld *w, noctObjectId id, noctObjectType *type)
{
    NOCT_REQUIRE(w != NULL && type != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    *type = (noctObjectType)w->obj[id.index].type;
    return NOCT_OK;
}

noctStatus noctWorldSetFilter(noctWorld *w, noctObjectId id, uint64_t category, uint64_t mask,
                              noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (lookup(w, id) == NULL)
        return stale(id, err);
    if (category == 0)
        return noct_fail(err, NOCT_ERR_INVALID, (long)id.index, 0,
                         "an object's category is 0: it could never pair");
    return noctBroadphaseSetFilter(&w->bp, id, category, mask);
}

noctStatus noctWorldGetFilter(const noctWorld *w, noctObjectId id, uint64_t *category,
                              uint64_t *mask)
{
    NOCT_REQUIRE(w != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    return noctBroadphaseProxy(&w->bp, id, NULL, NULL, NULL, category, mask);
}

noctStatus noctWorldSetSensor(noctWorld *w, noctObjectId id, bool sensor, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    noct_object *o = lookup(w, id);
    if (o == NULL)
        return stale(id, err);
    w->nsensors = w->nsensors - o->sensor + sensor;
    o->sensor = sensor;
    return NOCT_OK;
}

noctStatus noctWorldGetSensor(const noctWorld *w, noctObjectId id, bool *sensor)
{
    NOCT_REQUIRE(w != NULL && sensor != NULL);
    const noct_object *o = lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    *sensor = o->sensor;
    return NOCT_OK;
}

noctStatus noctWorldSetAngularVelocity(noctWorld *w, noctObjectId id, const noctQuat *q,
                                       noctError *err)
{
    NOCT_REQUIRE(w != NULL && q != NULL);
    if (lookup(w, id) == NULL)
        return stale(id, err);
    noctStatus st = check_spin(q, err);
    if (st != NOCT_OK)
        return st;
    if (!set_spin(w, id.index, q, true))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    return NOCT_OK;
}

noctStatus noctWorldGetAngularVelocity(const noctWorld *w, noctObjectId id, noctQuat *q)
{
    NOCT_REQUIRE(w != NULL && q != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    *q = w->spin.w != NULL ? w->spin.w[id.index] : (noctQuat){0, 0, 0, 1};
    return NOCT_OK;
}

noctStatus noctWorldSetUserData(noctWorld *w, noctObjectId id, void *user_data,
                                noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (lookup(w, id) == NULL)
        return stale(id, err);
    w->bp.proxy[id.index].user = user_data;
    return NOCT_OK;
}

void *noctWorldGetUserData(const noctWorld *w, noctObjectId id)
{
    NOCT_REQUIRE(w != NULL);
    return lookup(w, id) != NULL ? w->bp.proxy[id.index].user : NULL;
}

const noctMesh *noctWorldGetMesh(const noctWorld *w, noctObjectId id)
{
    NOCT_REQUIRE(w != NULL);
    return lookup(w, id) != NULL ? shape_of(w, id.index) : NULL;
}

noctStatus noctWorldGetHalfExtents(const noctWorld *w, noctObjectId id, double half[3])
{
    NOCT_REQUIRE(w != NULL && half != NULL);
    if (lookup(w, id) == NULL || !w->obj[id.index].box)
        return NOCT_ERR_INVALID;
    memcpy(half, w->pose[id.index].shape.half, sizeof w->pose[id.index].shape.half);
    return NOCT_OK;
}

/* ---- the step ------------------------------------------------------------------------ */

/*
 * Motion: the movers move and their boxes are placed; the fast test lists
 * those whose leaves may have changed. Returns TOO_LARGE (naming the
 * object) for a mover that would leave the coordinate range.
 */
static noctStatus stage_motion(noctWorld *w, double fraction, bool first, noctError *err)
{
    const uint32_t far = noct_world_move(w, fraction, first);
    w->moved = true;
    if (far != UINT32_MAX)
        return noct_fail(err, NOCT_ERR_TOO_LARGE, (long)far, 0,
                         "object %u would move beyond %g; no object moved", far,
                         NOCT_MAX_COORDINATE);
    w->c.moved += w->motion.nmovers;
    /* |velocity| is the speed within 1e-9; a placed box moves by it and a
     * few roundings of the root's coordinates: the pair search's reach. */
    const noct_aabb root = noct_bp_root_box(&w->bp);
    double r = 0;
    for (int k = 0; k < 3; ++k)
        r = noct_max(r, noct_max(fabs(root.lo[k]), fabs(root.hi[k])));
    w->bp.reach = w->motion.vmax * fraction * (1 + 1e-6) + 8 * 0x1p-52 * (isfinite(r) ? r : 0);
    return NOCT_OK;
}

/* Maintenance through the broadphase: the movers that failed the fast
 * test, or a rebuild; then the root grows or shrinks, and merges owed
 * are made. */
static noctStatus stage_maintenance(noctWorld *w, bool moving)
{
    noctStatus st = NOCT_OK;
    bool escaped = false;
    if (w->bp.root != NULL && moving) {
        if (w->def.maintenance == NOCT_MAINTAIN_REBUILD) {
            escaped = noct_world_movers_escaped(w);
            if (!escaped)
                st = noct_bp_rebuild(&w->bp, 0);
        } else {
            st = noct_bp_maintain(&w->bp, (const double (*)[3])w->pos, w->motion.slow,
                                  w->motion.nslow, w->motion.nmovers - w->motion.nslow,
                                  &escaped);
        }
    }
    if (st == NOCT_OK)
        st = noct_bp_settle(&w->bp, escaped);
    return st;
}

/* The colliding and sensing lists back to the ones before stage_pairs(). */
static void unswap_pairs(noct_events *e)
{
    noct_pair_list tmp = e->colliding;
    e->colliding = e->previous;
    e->previous = tmp;
    tmp = e->sensing;
    e->sensing = e->sensing_prev;
    e->sensing_prev = tmp;
}

/* The pair search, narrowphase and events: the colliding list becomes
 * the previous one, the broadphase's pairs go through the narrowphase,
 * and what began and ended is found. On failure the colliding list is
 * the one before. */
static noctStatus stage_pairs(noctWorld *w, size_t *from_began)
{
    noct_events *e = &w->events;
    noct_pair_list tmp = e->previous;
    e->previous = e->colliding;
    e->colliding = tmp;
    e->colliding.n = 0;
    tmp = e->sensing_prev;
    e->sensing_prev = e->sensing;
    e->sensing = tmp;
    e->sensing.n = 0;
    noctStatus st = noct_bp_search(&w->bp);
    if (st == NOCT_OK && !noct_bp_sort_tested(&w->bp))
        st = NOCT_ERR_NOMEM;
    if (st == NOCT_OK)
        st = noct_world_narrow(w, &w->bp.tested, &e->colliding);
    *from_began = e->began.n;
    if (st == NOCT_OK)
        noct_pairs_sort_partners(&e->colliding);
    if (st == NOCT_OK && w->nsensors > 0)
        st = noct_world_split_sensors(e, w->obj);
    if (st == NOCT_OK && (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)))
        st = noct_world_diff_events(e, &w->c.events);
    if (st != NOCT_OK)
        unswap_pairs(e);
    return st;
}

/* Objects a program moved since the last step (noctWorldSetTransform())
 * moved at most pending_reach each, on top of the motion: the pair
 * search's reach grows by it, and by the rounding of the root's
 * coordinates. */
static void add_teleports_reach(noctWorld *w)
{
    const noct_aabb root = noct_bp_root_box(&w->bp);
    double r = 0;
    for (int k = 0; k < 3; ++k)
        r = noct_max(r, noct_max(fabs(root.lo[k]), fabs(root.hi[k])));
    w->bp.reach += w->bp.pending_reach * (1 + 1e-6) + 8 * 0x1p-52 * (isfinite(r) ? r : 0);
}

/* One step, or one of k sub-steps (fraction = 1/k of the velocity); the
 * near pairs after the last. */
static noctStatus substep(noctWorld *w, double fraction, bool first, bool last,
                         noctError *err)
{
    ++w->bp.clock; /* the enter check's stamps: one tick per sub-step */
    ++w->bp.frame;
    noctStatus st = NOCT_OK;
    const double t0 = noct_seconds();
    const bool moving = (w->def.effects & NOCT_EFFECT_MOTION) != 0 && w->motion.moving > 0;
    w->bp.reach = 0;
    if (moving && (st = stage_motion(w, fraction, first, err)) != NOCT_OK)
        return st;
    if (first && w->bp.pending_reach > 0)
        add_teleports_reach(w);
    const double t1 = noct_seconds();
    if (moving)
        w->c.seconds_motion += t1 - t0;
    w->touched = true; /* from here on, the tree may change */
    st = stage_maintenance(w, moving);
    if (moving)
        w->c.seconds_maintenance += noct_seconds() - t1;
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "octree maintenance: %s; no object moved",
                         noctStatusString(st));
    const double t2 = noct_seconds();
    size_t from_began;
    st = stage_pairs(w, &from_began);
    if (st != NOCT_OK)
        return noct_fail(err, st, -1, 0, "pair search: %s; no object moved",
                         noctStatusString(st));
    if (last && w->def.margin > 0 && (st = noct_world_stage_near(w, err)) != NOCT_OK) {
        unswap_pairs(&w->events);
        w->events.began.n = from_began;
        return st;
    }
    if (first) { /* the teleports' travel is in this search's reach */
        w->bp.pending_reach = 0;
        ++w->bp.search_epoch;
    }
    w->c.colliding_pairs += w->events.colliding.n;
    const double t3 = noct_seconds();
    w->c.seconds_pairs += t3 - t2;
    if (w->def.effects & (NOCT_EFFECT_EVENTS | NOCT_EFFECT_RESPONSE)) {
        if (w->def.effects & NOCT_EFFECT_RESPONSE)
            noct_world_respond(&w->events, w->obj, &w->bp, from_began, &w->c.reversals);
        w->c.seconds_response += noct_seconds() - t3;
    }
    return NOCT_OK;
}

/* How many sub-steps this step takes (1 without #NOCT_EFFECT_SUBSTEP), or
 * 0 with err set when it would be too many. */
static uint64_t substeps_for(noctWorld *w, noctError *err)
{
    if (!(w->def.effects & NOCT_EFFECT_SUBSTEP) || !(w->def.effects & NOCT_EFFECT_MOTION))
        return 1;
    uint32_t which;
    const double ratio = noct_world_step_ratio(w, &which);
    uint64_t k = 1;
    /* Each sub-step moves every object at most half its smallest size. */
    if (ratio > 0.5) {
        if (!(2 * ratio <= (double)NOCT_MAX_SUBSTEPS)) {
            noct_fail(err, NOCT_ERR_TOO_LARGE, (long)which, 0,
                      "object %u moves %g times its smallest size a step; "
                      "sub-steps of half its size would be more than %u",
                      which, ratio, (unsigned)NOCT_MAX_SUBSTEPS);
            return 0;
        }
        k = (uint64_t)ceil(2 * ratio);
    }
    w->c.substeps += k;
    return k;
}

/* ---- spin (#NOCT_EFFECT_SPIN) ------------------------------------------------------ */

/* The spinners (live moving objects whose angular velocity is not the
 * identity); false without memory. */
static bool update_spinners(noctWorld *w)
{
    noct_spin *sp = &w->spin;
    if (!sp->stale)
        return true;
    uint32_t n = 0;
    for (uint32_t i = 0; i < w->bp.nslots; ++i)
        n += w->obj[i].alive && w->obj[i].type == NOCT_OBJECT_MOVING &&
             !is_identity_quat(&sp->w[i]);
    if (n > sp->cap) {
        uint32_t *a = realloc(sp->spinners, n * sizeof *a);
        if (a == NULL)
            return false;
        sp->spinners = a;
        sp->cap = n;
    }
    sp->nspinners = 0;
    for (uint32_t i = 0; i < w->bp.nslots; ++i)
        if (w->obj[i].alive && w->obj[i].type == NOCT_OBJECT_MOVING &&
            !is_identity_quat(&sp->w[i]))
            sp->spinners[sp->nspinners++] = i;
    sp->stale = false;
    return true;
}

/* ---- placements before the motion (spin, tracks) ------------------------------------ */

bool noct_world_reserve_placed(noctWorld *w, uint32_t n)
{
    w->nplaced = 0;
    if (n <= w->capplaced)
        return true;
    noct_placed *a = realloc(w->placed, n * sizeof *a);
    if (a == NULL)
        return false;
    w->placed = a;
    w->capplaced = n;
    return true;
}

noctStatus noct_world_place(noctWorld *w, uint32_t s, const noctQuat *q, const double p[3],
                            noctError *err)
{
    NOCT_INVARIANT(w->nplaced < w->capplaced);
    noct_pose *ps = &w->pose[s];
    noctStatus st = check_position(p, err);
    double R[9];
    if (st == NOCT_OK)
        st = noctQuatToMatrix(q, R, err);
    if (st != NOCT_OK)
        return st;
    /* The same quaternion, bit for bit: the same shape, turned as it is. */
    const bool same = memcmp(q, &ps->q, sizeof *q) == 0;
    noctMesh *rotated = ps->rotated;
    if (!same && w->obj[s].box && (st = noct_check_box_corners(ps->shape.half, R, err)) != NOCT_OK)
        return st;
    if (!same && (st = rotate_shape(shape_of(w, s), R, &rotated, err)) != NOCT_OK)
        return st;
    double lo[3], hi[3];
    if (same) {
        memcpy(lo, w->obj[s].mlo, sizeof lo);
        memcpy(hi, w->obj[s].mhi, sizeof hi);
    } else {
        local_box(w, s, rotated, R, lo, hi);
    }
    st = noct_bp_move_to(&w->bp, s, lo, hi, p);
    if (st != NOCT_OK) {
        if (!same)
            noctMeshDestroy(rotated);
        return noct_fail(err, st, (long)s, 0, "placing object %u: out of memory", s);
    }
    noct_placed *r = &w->placed[w->nplaced++];
    r->s = s;
    r->new_mesh = !same;
    r->q = ps->q;
    r->mesh = ps->rotated;
    memcpy(r->p, w->pos[s], sizeof r->p);
    ps->rotated = rotated;
    ps->q = *q;
    memcpy(w->pos[s], p, sizeof w->pos[s]);
    if (!same)
        place_mesh(w, s);
    return NOCT_OK;
}

void noct_world_unplace(noctWorld *w)
{
    for (uint32_t k = w->nplaced; k-- > 0;) {
        const noct_placed *r = &w->placed[k];
        const uint32_t s = r->s;
        noct_pose *p = &w->pose[s];
        if (r->new_mesh) {
            noctMeshDestroy(p->rotated);
            p->rotated = r->mesh;
        }
        p->q = r->q;
        memcpy(w->pos[s], r->p, sizeof w->pos[s]);
        place_mesh(w, s);
        noct_proxy *o = &w->bp.proxy[s];
        memcpy(o->mlo, w->obj[s].mlo, sizeof o->mlo);
        memcpy(o->mhi, w->obj[s].mhi, sizeof o->mhi);
        noct_place_box(o->mlo, o->mhi, w->pos[s], &w->bp.box[s]);
        noct_forget_home(&w->bp, s);
    }
    if (w->nplaced > 0 && w->bp.root != NULL)
        noct_bp_drop_tree(&w->bp);
    w->nplaced = 0;
}

/* A step that succeeded keeps its placements: the meshes they replaced go. */
static void placements_done(noctWorld *w)
{
    for (uint32_t k = 0; k < w->nplaced; ++k)
        if (w->placed[k].new_mesh)
            noctMeshDestroy(w->placed[k].mesh);
    w->nplaced = 0;
}

/* Turn each spinner by its angular velocity, q <- noctQuatCompose(w, q),
 * where it is; on failure give every placement back. */
static noctStatus stage_spin(noctWorld *w, noctError *err)
{
    noct_spin *sp = &w->spin;
    for (uint32_t k = 0; k < sp->nspinners; ++k) {
        const uint32_t s = sp->spinners[k];
        const noctQuat q = noctQuatCompose(&sp->w[s], &w->pose[s].q);
        const double p[3] = {w->pos[s][0], w->pos[s][1], w->pos[s][2]};
        noctStatus st = noct_world_place(w, s, &q, p, err);
        if (st != NOCT_OK) {
            noct_world_unplace(w);
            return st;
        }
    }
    return NOCT_OK;
}

/* Keep what a failed step of k sub-steps goes back to: the colliding list
 * (the sub-steps replace it) and the movers' velocities (responses may
 * turn them). */
static bool hold_list(noct_pair_list *h, const noct_pair_list *c)
{
    if (h->cap < c->n) {
        noctPair *q = realloc(h->p, c->n * sizeof *q);
        if (q == NULL)
            return false;
        h->p = q;
        h->cap = c->n;
    }
    if (c->n > 0)
        memcpy(h->p, c->p, c->n * sizeof *h->p);
    h->n = c->n;
    return true;
}

static bool hold_for_substeps(noctWorld *w, uint64_t k)
{
    if (k < 2)
        return true;
    if (!hold_list(&w->events.held, &w->events.colliding) ||
        !hold_list(&w->events.sensing_held, &w->events.sensing))
        return false;
    if (w->def.effects & NOCT_EFFECT_MOTION)
        for (uint32_t m = 0; m < w->motion.nmovers; ++m)
            memcpy(w->motion.prevvel[m], w->obj[w->motion.movers[m]].vel,
                   sizeof w->motion.prevvel[m]);
    return true;
}

noctStatus noctWorldStep(noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    w->events.began.n = w->events.ended.n = 0;
    w->events.sensor_began.n = w->events.sensor_ended.n = 0;
    w->events.near_began.n = w->events.near_ended.n = 0;
    if (w->bp.tree_owed) {
        noctStatus st = noct_bp_rebuild(&w->bp, 0);
        if (st != NOCT_OK)
            return noct_fail(err, st, -1, 0, "rebuilding the octree: %s",
                             noctStatusString(st));
    }
    const uint64_t k = substeps_for(w, err);
    if (k == 0)
        return NOCT_ERR_TOO_LARGE;
    if ((w->def.effects & NOCT_EFFECT_MOTION) && w->motion.moving > 0 &&
        !noct_world_update_movers(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (!hold_for_substeps(w, k))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    const bool spin = (w->def.effects & NOCT_EFFECT_SPIN) && w->spin.count > 0;
    if (spin && !update_spinners(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    const bool tracks = (w->def.effects & NOCT_EFFECT_TRACK) && w->tracks.n > 0;
    if (!noct_world_reserve_placed(w, (spin ? w->spin.nspinners : 0) +
                                          (tracks ? w->tracks.n : 0)))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    w->substeps = k;
    ++w->c.steps;
    w->moved = w->touched = false;
    if (tracks) {
        noctStatus st = noct_world_stage_tracks(w, w->tick + 1, err);
        if (st != NOCT_OK)
            return st;
    }
    if (spin) {
        noctStatus st = stage_spin(w, err);
        if (st != NOCT_OK)
            return st;
    }
    for (uint64_t i = 0; i < k; ++i) {
        noctStatus st = substep(w, k == 1 ? 1 : 1.0 / (double)k, i == 0, i + 1 == k, err);
        if (st != NOCT_OK) {
            noct_world_roll_back(w, w->moved, w->touched);
            noct_world_unplace(w);
            if (k > 1) {
                noct_pair_list t = w->events.colliding;
                w->events.colliding = w->events.held;
                w->events.held = t;
                t = w->events.sensing;
                w->events.sensing = w->events.sensing_held;
                w->events.sensing_held = t;
            }
            w->events.began.n = w->events.ended.n = 0;
            w->events.sensor_began.n = w->events.sensor_ended.n = 0;
            w->events.near_began.n = w->events.near_ended.n = 0;
            return st;
        }
    }
    placements_done(w);
    ++w->tick;
    return NOCT_OK;
}

/* ---- what the world tells ---------------------------------------------------------- */

/* A pair list for the program: its pairs and their number. */
static size_t list_of(const noct_pair_list *l, const noctPair **pairs)
{
    *pairs = l->p;
    return l->n;
}

size_t noctWorldColliding(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return list_of(&w->events.colliding, pairs);
}

size_t noctWorldSensing(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return list_of(&w->events.sensing, pairs);
}

size_t noctWorldSensorBegan(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return list_of(&w->events.sensor_began, pairs);
}

size_t noctWorldSensorEnded(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return list_of(&w->events.sensor_ended, pairs);
}

size_t noctWorldBegan(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return list_of(&w->events.began, pairs);
}

size_t noctWorldEnded(const noctWorld *w, const noctPair **pairs)
{
    NOCT_REQUIRE(w != NULL && pairs != NULL);
    return list_of(&w->events.ended, pairs);
}

noctStatus noctWorldObject(const noctWorld *w, noctObjectId id, double position[3],
                           double direction[3])
{
    NOCT_REQUIRE(w != NULL);
    const noct_object *o = lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    if (position != NULL)
        memcpy(position, w->pos[id.index], sizeof w->pos[id.index]);
    if (direction != NULL)
        for (int k = 0; k < 3; ++k)
            direction[k] = o->speed > 0 ? o->vel[k] / o->speed : 0;
    return NOCT_OK;
}

size_t noctWorldObjectCount(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return w->bp.alive;
}

void noctWorldGetCounters(const noctWorld *w, noctWorldCounters *counters)
{
    NOCT_REQUIRE(w != NULL && counters != NULL);
    *counters = w->c;
    const noctBroadphaseCounters *b = &w->bp.c;
    counters->inside_fast = b->inside_fast;
    counters->leaves_left = b->leaves_left;
    counters->leaves_entered = b->leaves_entered;
    counters->neighbor_queries = b->neighbor_queries;
    counters->reinserts = b->reinserts;
    counters->splits = b->splits;
    counters->merges = b->merges;
    counters->rebuilds = b->rebuilds;
    counters->leaves_visited = b->leaves_visited;
    counters->leaves_skipped = b->leaves_skipped;
    counters->candidate_pairs = b->candidate_pairs;
}

double noctWorldMaxStepRatio(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    uint32_t which;
    return noct_world_step_ratio(w, &which);
}

octNode *noctWorldRoot(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return w->bp.root;
}

const noctBroadphase *noctWorldBroadphase(const noctWorld *w)
{
    NOCT_REQUIRE(w != NULL);
    return &w->bp;
}

void noctWorldPrintCell(FILE *strm, const void *data)
{
    NOCT_REQUIRE(strm != NULL && data != NULL);
    noctBroadphasePrintCell(strm, data);
}

size_t noctWorldCell(const noctWorld *w, const octNode *node, double lo[3], double *size,
                     noctObjectId *objects, size_t max)
{
    NOCT_REQUIRE(w != NULL && node != NULL && (objects != NULL || max == 0));
    return noctBroadphaseCell(&w->bp, node, lo, size, objects, max);
}

noctStatus noctWorldObjectBox(const noctWorld *w, noctObjectId id, double lo[3],
                              double hi[3])
{
    NOCT_REQUIRE(w != NULL && lo != NULL && hi != NULL);
    if (lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(lo, w->bp.box[id.index].lo, sizeof w->bp.box[id.index].lo);
    memcpy(hi, w->bp.box[id.index].hi, sizeof w->bp.box[id.index].hi);
    return NOCT_OK;
}

noctStatus noctWorldValidate(const noctWorld *w, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    /* the world's own records against the broadphase's proxies */
    for (uint32_t i = 0; i < w->bp.nslots; ++i) {
        if (w->obj[i].alive != w->bp.proxy[i].alive)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u is %s but its proxy is not", i,
                             w->obj[i].alive ? "alive" : "dead");
        if (!w->obj[i].alive)
            continue;
        const noct_pose *p = &w->pose[i];
        if (w->mesh[i] != (p->rotated != NULL ? p->rotated : shape_of(w, i)))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's placed mesh is not its shape or its rotated copy",
                             i);
        double R[9];
        noctQuatToMatrix(&p->q, R, NULL);
        if (!w->obj[i].box && (p->rotated == NULL) != noct_is_identity(R))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u has %s rotated copy", i,
                             p->rotated == NULL ? "no" : "a needless");
        if ((w->obj[i].speed > 0) != (w->obj[i].type == NOCT_OBJECT_MOVING &&
                                      (w->obj[i].vel[0] != 0 || w->obj[i].vel[1] != 0 ||
                                       w->obj[i].vel[2] != 0)))
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's speed does not match its type and velocity", i);
        noct_aabb b;
        noct_place_box(w->obj[i].mlo, w->obj[i].mhi, w->pos[i], &b);
        if (memcmp(&b, &w->bp.box[i], sizeof b) != 0)
            return noct_fail(err, NOCT_ERR_INVARIANT, (long)i, 0,
                             "object %u's box is not its proxy's", i);
    }
    return noctBroadphaseValidate(&w->bp, err);
}
