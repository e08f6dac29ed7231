/* SPDX-License-Identifier: MIT */
/*
 * The world's objects (world.h): definitions, creation and removal, every
 * setter and getter, and placement: an object's pose (its shape turned by
 * its rotation, the placed mesh, the box form and local box) and the
 * placements the step's stages make before the motion (spin, tracks),
 * which a failed step gives back.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <noctree/world.h>

#include "world_internal.h"

NOCT_DEFINE_RESIZE(resize_objects, noct_object)
NOCT_DEFINE_RESIZE(resize_vectors, noct_vec3)
NOCT_DEFINE_RESIZE(resize_meshes, const noctMesh *)
NOCT_DEFINE_RESIZE(resize_quats, noctQuat)
NOCT_DEFINE_RESIZE(resize_doubles, double)
NOCT_DEFINE_RESIZE(resize_turns, noct_turn *)

NOCT_DEFINE_RESIZE(resize_placed, noct_placed)

/* ---- objects ---------------------------------------------------------------------------- */

bool noct_world_reserve_slots(noctWorld *w)
{
    const uint32_t cap = noct_bp_capacity(&w->bp);
    if (cap <= w->capslots)
        return true;
    if (!resize_objects(&w->obj, cap) || !resize_vectors(&w->pos, cap) ||
        !resize_meshes(&w->mesh, cap) || !resize_turns(&w->turn, cap) ||
        (w->spin.w != NULL && !resize_quats(&w->spin.w, cap)) ||
        (w->margins.of != NULL && !resize_doubles(&w->margins.of, cap)) ||
        !noct_world_reserve_sweeps(w, cap))
        return false;
    for (uint32_t i = w->capslots; i < cap; ++i) {
        w->turn[i] = NULL;
        if (w->margins.of != NULL)
            w->margins.of[i] = 0;
    }
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

/* The object's track goes with it (world_track.c keeps the tracks). */
void noct_world_drop_track(noctWorld *w, uint32_t s)
{
    noct_tracks *t = &w->tracks;
    if (t->of == NULL || s >= t->capof || t->of[s] == UINT32_MAX)
        return;
    const uint32_t i = t->of[s];
    free(t->list[i].keys);
    free(t->list[i].turns);
    t->of[s] = UINT32_MAX;
    /* the last track takes its place */
    if (i != --t->n) {
        t->list[i] = t->list[t->n];
        t->of[t->list[i].slot] = i;
    }
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
    d.margin = 0;
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

static bool known_quality(noctMotionQuality q)
{
    return q == NOCT_QUALITY_WORLD || q == NOCT_QUALITY_DISCRETE ||
           q == NOCT_QUALITY_CONTINUOUS;
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

/* Object s's shape turned by R, as rotate_shape() makes it: into the
 * spare copy its turn keeps, without allocating, when there is one and
 * the copy fits; else a new one. */
static noctStatus turn_shape(noctWorld *w, uint32_t s, const double R[9], noctMesh **rotated,
                             noctError *err)
{
    const noctMesh *shape = noct_world_shape_of(w, s);
    noct_turn *t = w->turn[s];
    if (shape != NULL && t != NULL && t->spare != NULL && !noct_is_identity(R)) {
        noctMesh *m = t->spare;
        t->spare = NULL;
        if (noct_mesh_turn_into(shape, R, t, m)) {
            *rotated = m;
            return NOCT_OK;
        }
        noctMeshDestroy(m);
    }
    return rotate_shape(shape, R, rotated, err);
}

/* A turned copy of object s's shape that nothing reads any more (NULL,
 * or a box primitive's mesh, go): kept as the spare of the object's
 * turn, which is made now if make is set (a step that succeeded, which
 * may allocate), else it goes. */
static void keep_spare(noctWorld *w, uint32_t s, noctMesh *m, bool make)
{
    if (m == NULL)
        return;
    if (!w->obj[s].box && w->turn[s] == NULL && make)
        w->turn[s] = noct_turn_new(w->pose[s].shape.mesh);
    noct_turn *t = w->obj[s].box ? NULL : w->turn[s];
    if (t == NULL) {
        noctMeshDestroy(m);
        return;
    }
    noctMeshDestroy(t->spare);
    t->spare = m;
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
        noct_world_sweep_reshaped(w, s);
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
    noct_world_sweep_reshaped(w, s);
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
    noct_world_sweep_touch(w, s, false); /* its growth follows */
}

/* An object's velocity: the moving one's, or the one its pose keeps. */
static const double *velocity_of(const noctWorld *w, uint32_t s)
{
    return w->obj[s].vel;
}

/* Give slot s the angular velocity q (checked), making the per-slot array
 * when the first one that is not the identity comes; false without
 * memory (then nothing changed). */
static bool set_spin(noctWorld *w, uint32_t s, const noctQuat *q, bool was_live)
{
    const bool none = noct_quat_is_identity(q);
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
    const bool had = was_live && !noct_quat_is_identity(&w->spin.w[s]);
    w->spin.w[s] = *q;
    w->spin.count = w->spin.count - had + !none;
    w->spin.stale = true;
    return true;
}

/* An object's margin: finite, 0 to NOCT_MAX_COORDINATE. */
static noctStatus check_margin(double m, long index, noctError *err)
{
    if (!isfinite(m))
        return noct_fail(err, NOCT_ERR_NONFINITE, index, 0, "object margin is not finite");
    if (!(m >= 0 && m <= NOCT_MAX_COORDINATE))
        return noct_fail(err, NOCT_ERR_INVALID, index, 0,
                         "object margin %g: it must be 0 to %g", m, NOCT_MAX_COORDINATE);
    return NOCT_OK;
}

/* The per-slot margins, made (all 0) for the world's first margin; false
 * without memory. */
static bool margins_enable(noctWorld *w)
{
    if (w->margins.of != NULL)
        return true;
    w->margins.of = calloc(w->capslots > 0 ? w->capslots : 1, sizeof *w->margins.of);
    return w->margins.of != NULL;
}

/* Object s's margin becomes m (the array made, if m > 0). */
static void set_margin(noctWorld *w, uint32_t s, double m)
{
    noct_margins *g = &w->margins;
    ++g->edits; /* (objects come and go through here too) */
    if (g->of == NULL)
        return;
    const double old = g->of[s];
    g->count = g->count - (old > 0) + (m > 0);
    g->of[s] = m;
    g->near = g->near || g->count > 0;
    if (m > g->max)
        g->max = m;
    else if (old == g->max && m < old)
        g->stale = true;
}

void noct_world_refresh_margins(noctWorld *w)
{
    noct_margins *g = &w->margins;
    double max = 0;
    if (g->of != NULL && g->count > 0)
        for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i)
            if (w->obj[i].alive && g->of[i] > max)
                max = g->of[i];
    g->max = max;
    g->stale = false;
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
    if (st == NOCT_OK)
        st = check_margin(def->margin, -1, err);
    if (st != NOCT_OK)
        return st;
    if (!known_type(def->type))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown object type %d",
                         (int)def->type);
    if (!known_quality(def->quality))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown motion quality %d",
                         (int)def->quality);
    if (def->quality == NOCT_QUALITY_CONTINUOUS && !noct_world_sweeps_enable(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    if (def->margin > 0 && !margins_enable(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
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
        return noct_bp_slots(&w->bp) >= 0x80000000u
                   ? noct_fail(err, NOCT_ERR_TOO_LARGE, -1, 0, "too many objects")
                   : noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    }
    if (!noct_world_reserve_slots(w)) {
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
        if (w->spin.w != NULL && !noct_quat_is_identity(&w->spin.w[slot])) {
            w->spin.w[slot] = (noctQuat){0, 0, 0, 1};
            --w->spin.count;
        }
        p->rotated = NULL;
        noctMeshDestroy(rotated);
        return noct_fail(err, st, -1, 0, "out of memory");
    }
    o->alive = true;
    o->sensor = def->sensor;
    o->quality = (uint8_t)def->quality;
    w->nsensors += def->sensor;
    if (w->margins.of != NULL)
        w->margins.of[slot] = 0; /* (a slot's margin is 0 while it is dead) */
    set_margin(w, slot, def->margin);
    noct_world_sweep_touch(w, slot, true);
    set_motion(w, slot, def->type, def->velocity);
    id->index = slot;
    id->generation = noct_bp_generation(&w->bp, slot);
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
    noct_object *o = noct_world_lookup(w, id);
    if (o == NULL)
        return stale(id, err);
    set_motion(w, id.index, NOCT_OBJECT_STATIC, velocity_of(w, id.index));
    noct_bp_free_slot(&w->bp, id.index); /* cannot fail */
    o->alive = false;
    NOCT_INVARIANT(w->nsensors >= (size_t)o->sensor);
    w->nsensors -= o->sensor;
    o->sensor = false;
    set_margin(w, id.index, 0);
    if (w->spin.w != NULL) {
        w->spin.count -= !noct_quat_is_identity(&w->spin.w[id.index]);
        w->spin.w[id.index] = (noctQuat){0, 0, 0, 1};
        w->spin.stale = true;
    }
    noctMeshDestroy(w->pose[id.index].rotated);
    w->pose[id.index].rotated = NULL;
    noct_turn_free(w->turn[id.index]);
    w->turn[id.index] = NULL;
    noct_world_drop_track(w, id.index);
    noct_world_forget_ignored(w, id.index);
    /* The lists stay: the colliding one holds its pairs, which the next
     * step's diff ends. */
    return NOCT_OK;
}

noctStatus noctWorldObjectAt(const noctWorld *w, uint32_t index, noctObjectId *id)
{
    NOCT_REQUIRE(w != NULL && id != NULL);
    if (index >= noct_bp_slots(&w->bp) || !noct_bp_proxy(&w->bp, index)->alive) {
        id->index = id->generation = 0;
        return NOCT_ERR_INVALID;
    }
    id->index = index;
    id->generation = noct_bp_generation(&w->bp, index);
    return NOCT_OK;
}

noctStatus noctWorldSetTransform(noctWorld *w, noctObjectId id, const noctTransform *x,
                                 noctError *err)
{
    NOCT_REQUIRE(w != NULL && x != NULL);
    /* noct_world_lookup() through the proxy, whose line the fast test reads anyway
     * (a world object is alive when its proxy is: noctWorldValidate()) */
    const uint32_t s = id.index;
    if (s >= noct_bp_slots(&w->bp) || !noct_bp_proxy(&w->bp, s)->alive || noct_bp_generation(&w->bp, s) != id.generation)
        return stale(id, err);
    noct_pose *p = &w->pose[s];
    /* The same quaternion, bit for bit (a program that only moves the
     * object): it was checked when it was set, the object keeps its
     * rotated shape, and the fast test may settle the move at once. */
    const bool same = memcmp(&x->q, &p->q, sizeof x->q) == 0;
    noctStatus st = same ? check_position(x->p, err) : noctTransformCheck(x, err);
    if (st != NOCT_OK)
        return st;
    if (same && !noct_bp_tree_owed(&w->bp) &&
        noct_bp_move_fast(&w->bp, s, x->p)) {
        memcpy(w->pos[s], x->p, sizeof w->pos[s]);
        noct_world_sweep_touch(w, s, false);
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
    if (turned && (st = turn_shape(w, s, R, &rotated, err)) != NOCT_OK)
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
            keep_spare(w, s, rotated, false);
        return noct_fail(err, st, (long)s, 0, "moving object %u: out of memory", s);
    }
    if (turned) {
        keep_spare(w, s, p->rotated, true);
        p->rotated = rotated;
        p->q = x->q;
        place_mesh(w, s);
    }
    p->q = x->q;
    memcpy(w->pos[s], x->p, sizeof w->pos[s]);
    noct_world_sweep_touch(w, s, false);
    return NOCT_OK;
}

noctStatus noctWorldGetTransform(const noctWorld *w, noctObjectId id, noctTransform *x)
{
    NOCT_REQUIRE(w != NULL && x != NULL);
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(x->p, w->pos[id.index], sizeof x->p);
    x->q = w->pose[id.index].q;
    return NOCT_OK;
}

noctStatus noctWorldSetVelocity(noctWorld *w, noctObjectId id, const double velocity[3],
                                noctError *err)
{
    NOCT_REQUIRE(w != NULL && velocity != NULL);
    if (noct_world_lookup(w, id) == NULL)
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
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    memcpy(velocity, velocity_of(w, id.index), 3 * sizeof *velocity);
    return NOCT_OK;
}

noctStatus noctWorldSetType(noctWorld *w, noctObjectId id, noctObjectType type,
                            noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (noct_world_lookup(w, id) == NULL)
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
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    *type = (noctObjectType)w->obj[id.index].type;
    return NOCT_OK;
}

noctStatus noctWorldSetFilter(noctWorld *w, noctObjectId id, uint64_t category, uint64_t mask,
                              noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (noct_world_lookup(w, id) == NULL)
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
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    return noctBroadphaseProxy(&w->bp, id, NULL, NULL, NULL, category, mask);
}

noctStatus noctWorldSetSensor(noctWorld *w, noctObjectId id, bool sensor, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    noct_object *o = noct_world_lookup(w, id);
    if (o == NULL)
        return stale(id, err);
    w->nsensors = w->nsensors - o->sensor + sensor;
    o->sensor = sensor;
    ++w->margins.edits;
    return NOCT_OK;
}

noctStatus noctWorldSetMargin(noctWorld *w, noctObjectId id, double margin, noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (noct_world_lookup(w, id) == NULL)
        return stale(id, err);
    const noctStatus st = check_margin(margin, (long)id.index, err);
    if (st != NOCT_OK)
        return st;
    if (margin > 0 && !margins_enable(w))
        return noct_fail(err, NOCT_ERR_NOMEM, (long)id.index, 0, "out of memory");
    set_margin(w, id.index, margin);
    return NOCT_OK;
}

noctStatus noctWorldGetMargin(const noctWorld *w, noctObjectId id, double *margin)
{
    NOCT_REQUIRE(w != NULL && margin != NULL);
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    *margin = noct_world_margin(w, id.index);
    return NOCT_OK;
}

noctStatus noctWorldGetSensor(const noctWorld *w, noctObjectId id, bool *sensor)
{
    NOCT_REQUIRE(w != NULL && sensor != NULL);
    const noct_object *o = noct_world_lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    *sensor = o->sensor;
    return NOCT_OK;
}

noctStatus noctWorldSetMotionQuality(noctWorld *w, noctObjectId id, noctMotionQuality quality,
                                     noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    noct_object *o = noct_world_lookup(w, id);
    if (o == NULL)
        return stale(id, err);
    if (!known_quality(quality))
        return noct_fail(err, NOCT_ERR_INVALID, -1, 0, "unknown motion quality %d",
                         (int)quality);
    if (quality == NOCT_QUALITY_CONTINUOUS && !noct_world_sweeps_enable(w))
        return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
    const bool was = w->sweeps.on && noct_world_continuous(w, id.index);
    o->quality = (uint8_t)quality;
    if (w->sweeps.on && noct_world_continuous(w, id.index) != was) {
        /* its next step starts where it is; its growth follows */
        noct_world_sweep_touch(w, id.index, true);
    }
    return NOCT_OK;
}

noctStatus noctWorldGetMotionQuality(const noctWorld *w, noctObjectId id,
                                     noctMotionQuality *quality)
{
    NOCT_REQUIRE(w != NULL && quality != NULL);
    const noct_object *o = noct_world_lookup(w, id);
    if (o == NULL)
        return NOCT_ERR_INVALID;
    *quality = (noctMotionQuality)o->quality;
    return NOCT_OK;
}

noctStatus noctWorldSetAngularVelocity(noctWorld *w, noctObjectId id, const noctQuat *q,
                                       noctError *err)
{
    NOCT_REQUIRE(w != NULL && q != NULL);
    if (noct_world_lookup(w, id) == NULL)
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
    if (noct_world_lookup(w, id) == NULL)
        return NOCT_ERR_INVALID;
    *q = w->spin.w != NULL ? w->spin.w[id.index] : (noctQuat){0, 0, 0, 1};
    return NOCT_OK;
}

noctStatus noctWorldSetUserData(noctWorld *w, noctObjectId id, void *user_data,
                                noctError *err)
{
    NOCT_REQUIRE(w != NULL);
    if (noct_world_lookup(w, id) == NULL)
        return stale(id, err);
    noct_bp_proxy(&w->bp, id.index)->user = user_data;
    return NOCT_OK;
}

void *noctWorldGetUserData(const noctWorld *w, noctObjectId id)
{
    NOCT_REQUIRE(w != NULL);
    return noct_world_lookup(w, id) != NULL ? noct_bp_proxy(&w->bp, id.index)->user : NULL;
}

const noctMesh *noctWorldGetMesh(const noctWorld *w, noctObjectId id)
{
    NOCT_REQUIRE(w != NULL);
    return noct_world_lookup(w, id) != NULL ? noct_world_shape_of(w, id.index) : NULL;
}

noctStatus noctWorldGetHalfExtents(const noctWorld *w, noctObjectId id, double half[3])
{
    NOCT_REQUIRE(w != NULL && half != NULL);
    if (noct_world_lookup(w, id) == NULL || !w->obj[id.index].box)
        return NOCT_ERR_INVALID;
    memcpy(half, w->pose[id.index].shape.half, sizeof w->pose[id.index].shape.half);
    return NOCT_OK;
}

/* ---- placements before the motion (spin, tracks) ------------------------------------ */

bool noct_world_reserve_placed(noctWorld *w, uint32_t n)
{
    w->nplaced = 0;
    if (n <= w->capplaced)
        return true;
    if (!resize_placed(&w->placed, n))
        return false;
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
    if (!same && (st = turn_shape(w, s, R, &rotated, err)) != NOCT_OK)
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
            keep_spare(w, s, rotated, false);
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
    noct_world_sweep_touch(w, s, false);
    return NOCT_OK;
}

void noct_world_unplace(noctWorld *w)
{
    for (uint32_t k = w->nplaced; k-- > 0;) {
        const noct_placed *r = &w->placed[k];
        const uint32_t s = r->s;
        noct_pose *p = &w->pose[s];
        if (r->new_mesh) {
            keep_spare(w, s, p->rotated, false);
            p->rotated = r->mesh;
        }
        p->q = r->q;
        memcpy(w->pos[s], r->p, sizeof w->pos[s]);
        place_mesh(w, s);
        noct_proxy *o = noct_bp_proxy(&w->bp, s);
        memcpy(o->mlo, w->obj[s].mlo, sizeof o->mlo);
        memcpy(o->mhi, w->obj[s].mhi, sizeof o->mhi);
        noct_place_box(o->mlo, o->mhi, w->pos[s], noct_bp_box(&w->bp, s));
        noct_forget_home(&w->bp, s);
    }
    if (w->nplaced > 0 && noct_bp_root(&w->bp) != NULL)
        noct_bp_drop_tree(&w->bp);
    w->nplaced = 0;
}

void noct_world_placements_done(noctWorld *w)
{
    for (uint32_t k = 0; k < w->nplaced; ++k)
        if (w->placed[k].new_mesh) /* the next turn's target */
            keep_spare(w, w->placed[k].s, w->placed[k].mesh, true);
    w->nplaced = 0;
}


noctStatus noct_world_check_turned(const noctWorld *w, uint32_t s, noctError *err)
{
    const noct_pose *p = &w->pose[s];
    if (w->obj[s].box || p->rotated == NULL)
        return NOCT_OK;
    double R[9];
    noctQuatToMatrix(&p->q, R, NULL);
    noctMesh *fresh;
    const noctStatus st = noct_mesh_rotated(p->shape.mesh, R, &fresh, NULL);
    if (st == NOCT_ERR_NOMEM)
        return noct_fail(err, st, (long)s, 0, "out of memory");
    const bool same = st == NOCT_OK && noct_mesh_same(p->rotated, fresh);
    noctMeshDestroy(fresh);
    if (!same)
        return noct_fail(err, NOCT_ERR_INVARIANT, (long)s, 0,
                         "object %u's turned mesh is not its shape turned anew", s);
    return NOCT_OK;
}
