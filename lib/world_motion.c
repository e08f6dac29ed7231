/* SPDX-License-Identifier: MIT */
/*
 * The world's motion stage: each mover advances by its velocity (or a
 * sub-step's fraction of it), the container's walls turn it back, and its
 * box is placed in the broadphase, with the broadphase's fast test run on
 * the new position while it is in registers. Also what a failed step
 * needs to go back: the positions and velocities the step began with.
 */
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__x86_64__) && defined(__SSE2__)
#  include <emmintrin.h> /* _mm_stream_si64 */
#endif

#include "world_internal.h"

NOCT_DEFINE_GROW(grow_u32, uint32_t)
NOCT_DEFINE_RESIZE(resize_u32, uint32_t)
NOCT_DEFINE_RESIZE(resize_bytes, uint8_t)
NOCT_DEFINE_RESIZE(resize_ticks, noct_ticks)
NOCT_DEFINE_RESIZE(resize_vectors, noct_vec3)

/* The live moving objects in slot order, and their greatest speed, after
 * objects came or went; room for as many slow ones. */
bool noct_world_update_movers(noctWorld *w)
{
    if (!w->motion.stale)
        return true;
    const size_t n = w->motion.moving;
    if (!grow_u32(&w->motion.movers, &w->motion.capmovers, n) ||
        !grow_u32(&w->motion.slow, &w->motion.capslow, n))
        return false;
    if (w->motion.capprev < n) {
        const bool walls = (w->def.effects & NOCT_EFFECT_WALLS) != 0;
        const bool sub = (w->def.effects & NOCT_EFFECT_SUBSTEP) != 0;
        if (!resize_ticks(&w->motion.prev, n) ||
            (sub && !resize_vectors(&w->motion.prevvel, n)) ||
            (walls && (!resize_u32(&w->motion.flips, n) ||
                       !resize_bytes(&w->motion.flip_axes, n))))
            return false;
        w->motion.capprev = n;
    }
    w->motion.nmovers = 0;
    w->motion.vmax = 0;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i)
        if (w->obj[i].alive && w->obj[i].speed > 0) {
            w->motion.movers[w->motion.nmovers++] = i;
            w->motion.vmax = noct_max(w->motion.vmax, w->obj[i].speed);
        }
    w->motion.stale = false;
    return true;
}


/*
 * Keep a mover's position before the motion, for roll_back: 24 bytes a
 * mover that are written every step and read only after a failure, so on
 * x86-64 they are streamed past the cache (non-temporal stores) rather
 * than fetched into it to be written (the motion loop is bound by memory
 * in large worlds). The array holds the doubles' bits.
 */
static NOCT_ALWAYS_INLINE void noct_keep_position(int64_t dst[3], const double p[3])
{
    int64_t b[3];
    memcpy(b, p, sizeof b);
#if defined(__x86_64__) && defined(__SSE2__)
    _mm_stream_si64((long long *)&dst[0], b[0]);
    _mm_stream_si64((long long *)&dst[1], b[1]);
    _mm_stream_si64((long long *)&dst[2], b[2]);
#else
    memcpy(dst, b, sizeof b);
#endif
}

/*
 * Motion: each mover's position advances by fraction of its velocity
 * (times 1 is exact, so a whole step adds the velocity itself), walls
 * turn it back, and its box is placed. With incremental maintenance
 * (fast true) the loop also runs maintenance's fast test on the new
 * position while it is in registers: an object that fails it keeps its
 * old box, for maintenance, and joins w->motion.slow. Returns the first mover
 * beyond NOCT_MAX_COORDINATE, or UINT32_MAX. One that passed the fast
 * test is not (home_of() keeps its positions within the limit), so with
 * it only the slow ones are checked, after the loop; without it the check
 * is gathered over the loop. With save (the first sub-step of a step),
 * the old positions and the velocity components the walls turn are kept
 * for roll_back. The loop's other branches are the fast test's, which
 * almost every object passes, and the walls', decided outside it (walls,
 * fast and save are constants where it is inlined).
 */
static NOCT_ALWAYS_INLINE uint32_t move_all(noctWorld *w, double fraction, bool walls, bool fast,
                                        bool save)
{
    const double wlo[3] = {w->def.walls_lo[0], w->def.walls_lo[1], w->def.walls_lo[2]};
    const double whi[3] = {w->def.walls_hi[0], w->def.walls_hi[1], w->def.walls_hi[2]};
    noct_object *obj = w->obj;
    noct_aabb *box = noct_bp_boxes(&w->bp);
    const noct_home *home = noct_bp_homes(&w->bp);
    noct_proxy *proxy = noct_bp_proxies(&w->bp);
    double(*pos)[3] = w->pos;
    int64_t(*prev)[3] = w->motion.prev;
    uint32_t *flips = w->motion.flips;
    uint8_t *flip_axes = w->motion.flip_axes;
    uint32_t nflips = 0;
    const uint32_t *movers = w->motion.movers;
    uint32_t *slow = w->motion.slow;
    const uint32_t nm = w->motion.nmovers;
    uint32_t nslow = 0;
    bool beyond = false;
    for (uint32_t m = 0; m < nm; ++m) {
        const uint32_t i = movers[m];
        noct_object *o = &obj[i];
        double *p = pos[i];
        const double x = p[0] + o->vel[0] * fraction, y = p[1] + o->vel[1] * fraction,
                     z = p[2] + o->vel[2] * fraction;
        if (save)
            noct_keep_position(prev[m], p);
        p[0] = x;
        p[1] = y;
        p[2] = z;
        if (walls) {
            unsigned turned = 0;
            for (int k = 0; k < 3; ++k)
                if ((p[k] < wlo[k] && o->vel[k] < 0) || (p[k] > whi[k] && o->vel[k] > 0)) {
                    o->vel[k] = -o->vel[k];
                    turned |= 1u << k;
                }
            if (save && turned != 0) {
                flips[nflips] = m;
                flip_axes[nflips++] = (uint8_t)turned;
            }
        }
        if (!fast)
            beyond |= (fabs(x) > NOCT_MAX_COORDINATE) | (fabs(y) > NOCT_MAX_COORDINATE) |
                      (fabs(z) > NOCT_MAX_COORDINATE);
        else if (!noct_inside_home(p, &home[i])) {
            proxy[i].old = box[i];
            slow[nslow++] = i;
        }
        noct_place_box(o->mlo, o->mhi, p, &box[i]);
    }
    if (save)
        w->motion.nflips = nflips;
    w->motion.nslow = nslow;
    const uint32_t *check = fast ? slow : movers;
    const uint32_t ncheck = fast ? nslow : beyond ? nm : 0;
    for (uint32_t m = 0; m < ncheck; ++m) {
        const double *p = pos[check[m]];
        if (fabs(p[0]) > NOCT_MAX_COORDINATE || fabs(p[1]) > NOCT_MAX_COORDINATE ||
            fabs(p[2]) > NOCT_MAX_COORDINATE)
            return check[m];
    }
    return UINT32_MAX;
}

/* Has a mover's box left the root? */
bool noct_world_movers_escaped(const noctWorld *w)
{
    const noct_aabb root = noct_bp_root_box(&w->bp);
    for (uint32_t m = 0; m < w->motion.nmovers; ++m)
        if (!noct_box_within(noct_bp_box(&w->bp, w->motion.movers[m]), &root))
            return true;
    return false;
}

/*
 * After a stage of a step failed: the movers go back to where they were
 * before the step (positions, velocities that walls or responses turned,
 * boxes), and a tree that maintenance or the pair search may have changed
 * halfway, or for positions that no longer hold, is torn down, to be
 * built again by the next step. The caller restores the pair lists. So a
 * failed step leaves no object moved and no structure half-changed.
 */
void noct_world_roll_back(noctWorld *w, bool moved, bool tree_touched)
{
    if (moved) {
        /* Velocities: a step of sub-steps kept them whole (responses may
         * have turned them too); a single step turned back what the walls
         * turned. */
        const bool kept = w->substeps > 1;
        for (uint32_t f = 0; f < w->motion.nflips && !kept; ++f) {
            double *v = w->obj[w->motion.movers[w->motion.flips[f]]].vel;
            for (int k = 0; k < 3; ++k)
                if (w->motion.flip_axes[f] & (1u << k))
                    v[k] = -v[k];
        }
        for (uint32_t m = 0; m < w->motion.nmovers; ++m) {
            const uint32_t i = w->motion.movers[m];
            memcpy(w->pos[i], w->motion.prev[m], sizeof w->pos[i]);
            if (kept)
                memcpy(w->obj[i].vel, w->motion.prevvel[m], sizeof w->obj[i].vel);
            noct_place_box(w->obj[i].mlo, w->obj[i].mhi, w->pos[i], noct_bp_box(&w->bp, i));
            noct_forget_home(&w->bp, i);
        }
    }
    if (tree_touched && noct_bp_root(&w->bp) != NULL)
        noct_bp_drop_tree(&w->bp);
}

/* The moving object that moves farthest for its size, and how far:
 * speed over the smallest extent of its mesh's box. */
double noct_world_step_ratio(const noctWorld *w, uint32_t *which)
{
    double worst = 0;
    *which = UINT32_MAX;
    for (uint32_t i = 0; i < noct_bp_slots(&w->bp); ++i) {
        const noct_object *o = &w->obj[i];
        if (!o->alive || o->speed == 0)
            continue;
        double extent = noct_min(noct_min(o->mhi[0] - o->mlo[0], o->mhi[1] - o->mlo[1]),
                                 o->mhi[2] - o->mlo[2]);
        double r = o->speed / extent;
        if (r > worst) {
            worst = r;
            *which = i;
        }
    }
    return worst;
}

uint32_t noct_world_move(noctWorld *w, double fraction, bool first)
{
    /* walls, fast and save are constants in each inlined copy */
    const bool walls = (w->def.effects & NOCT_EFFECT_WALLS) != 0;
    const bool fast = w->def.maintenance != NOCT_MAINTAIN_REBUILD;
    if (!first) /* a later sub-step: roll_back has the step's start */
        return walls ? move_all(w, fraction, true, fast, false)
                     : move_all(w, fraction, false, fast, false);
    if (fast)
        return walls ? move_all(w, fraction, true, true, true)
                     : move_all(w, fraction, false, true, true);
    return walls ? move_all(w, fraction, true, false, true)
                 : move_all(w, fraction, false, false, true);
}
