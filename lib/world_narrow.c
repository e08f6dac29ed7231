/* SPDX-License-Identifier: MIT */
/*
 * The world's narrowphase dispatch: the pairs whose boxes the broadphase
 * found overlapping go to the narrowphase at the world's accuracy. It
 * reads the objects' meshes, positions and box slots, and nothing of the
 * tree.
 */
#include "config.h"

#include <string.h>

#include "world_internal.h"

/* The narrowphase on the pairs the search found (whose boxes it tested
 * already). At the exact level a pair of objects with box-form meshes is
 * decided on their slots, two cache lines each, in most cases without
 * reading the meshes; the rest go through the meshes. Slots are scattered
 * by pair, so they and the positions are requested 16 pairs ahead, and 8
 * ahead the first lines of the meshes that are not boxes. */
noctStatus noct_world_narrow(noctWorld *w, const noct_pair_list *tested,
                             noct_pair_list *colliding)
{
    const noctPair *p = tested->p;
    size_t n = tested->n;
    w->c.tested_pairs += n;
    w->c.narrow.box_tests += n; /* the search's, on the same boxes */
    if (n == 0)
        return NOCT_OK;
    /* The pairs' boxes overlap, so the whole loop is the level's time:
     * two clock reads a step rather than two a pair. */
    const noctAccuracy level = w->def.accuracy;
    const double t0 = level != NOCT_ACCURACY_BOX ? noct_seconds() : 0;
    noctStatus st = NOCT_OK;
    const noct_box_slot *slot = w->slot;
    const noct_object *obj = w->obj;
    const noctMesh *const *mesh = w->mesh;
    const bool exact = level == NOCT_ACCURACY_EXACT || level == NOCT_ACCURACY_CONTINUOUS;
    double(*start)[3] = w->sweeps.start; /* continuous: NULL otherwise */
    const bool sensors = w->nsensors > 1; /* two sensors never pair */
    const bool ignoring = w->ignored.n > 0;
    for (size_t i = 0; i < n; ++i) {
        if (i + 16 < n)
            for (int s = 0; s < 2; ++s) {
                uint32_t k = s ? p[i + 16].b.index : p[i + 16].a.index;
                const char *b = (const char *)&slot[k];
                NOCT_PREFETCH(b);
                NOCT_PREFETCH(b + 64);
                NOCT_PREFETCH(w->pos[k]);
            }
        if (i + 8 < n)
            for (int s = 0; s < 2; ++s) {
                uint32_t k = s ? p[i + 8].b.index : p[i + 8].a.index;
                if ((!exact || !slot[k].has_box) && mesh[k] != NULL) {
                    const char *m = (const char *)mesh[k];
                    for (int line = 0; line < 10; ++line)
                        NOCT_PREFETCH(m + 64 * line);
                }
            }
        uint32_t ia = p[i].a.index, ib = p[i].b.index;
        if (sensors && obj[ia].sensor && obj[ib].sensor)
            continue;
        if (ignoring && noct_world_ignored(w, ia, ib))
            continue;
        bool hit;
        int d = 0;
        const double *ta = w->pos[ia], *tb = w->pos[ib];
        if (start != NULL &&
            (noct_world_continuous(w, ia) || noct_world_continuous(w, ib)) &&
            (memcmp(noct_world_from(w, ia), ta, sizeof start[ia]) != 0 ||
             memcmp(noct_world_from(w, ib), tb, sizeof start[ib]) != 0 ||
             noct_world_turned(w, ia) || noct_world_turned(w, ib))) {
            /* Either moved, one of them continuous: the continuous level.
             * Two boxes first on their slots: apart over the motion, or
             * colliding at the end or at the start, as most pairs are
             * decided. */
            const double *fa = noct_world_from(w, ia), *fb = noct_world_from(w, ib);
            hit = false;
            int decided = 0;
            if (slot[ia].has_box && slot[ib].has_box && !noct_world_turned(w, ia) &&
                !noct_world_turned(w, ib)) {
                ++w->c.narrow.exact_tests;
                if (noct_swept_slots_apart(&slot[ia], fa, ta, &slot[ib], fb, tb))
                    decided = -1;
                else if (noct_box_decide(&slot[ia], ta, &slot[ib], tb) > 0 ||
                         noct_box_decide(&slot[ia], fa, &slot[ib], fb) > 0)
                    decided = 1;
                if (decided != 0)
                    ++*(decided < 0 ? &w->c.narrow.sat_rejects : &w->c.narrow.witnesses);
            }
            if (decided != 0)
                hit = decided > 0;
            else if ((st = noct_world_sweep_pair(w, ia, ib, &hit)) != NOCT_OK)
                break;
            if (hit && !noct_pairs_push(colliding, (noctPair){{ia, 0}, {ib, 0}})) {
                st = NOCT_ERR_NOMEM;
                break;
            }
            continue;
        }
        const bool boxes = exact && slot[ia].has_box && slot[ib].has_box;
        if (boxes) {
            d = noct_box_decide(&slot[ia], ta, &slot[ib], tb);
            ++w->c.narrow.exact_tests;
            if (d != 0)
                ++*(d < 0 ? &w->c.narrow.sat_rejects : &w->c.narrow.witnesses);
        }
        const noctMesh *ma = mesh[ia], *mb = mesh[ib];
        if (d == 0 && level != NOCT_ACCURACY_BOX && (ma == NULL || mb == NULL)) {
            /* a box primitive's mesh, made once for the exact triangles */
            ma = noct_world_mesh(w, ia, &st);
            mb = ma != NULL ? noct_world_mesh(w, ib, &st) : NULL;
            if (ma == NULL || mb == NULL)
                break;
        }
        if (d != 0)
            hit = d > 0;
        else if (boxes)
            st = noct_collide_undecided_boxes(ma, ta, mb, tb, &hit, &w->c.narrow);
        else
            st = noct_collide_overlapping(ma, ta, mb, tb, level, &hit, &w->c.narrow);
        if (st != NOCT_OK)
            break;
        if (hit && !noct_pairs_push(colliding, (noctPair){{ia, 0}, {ib, 0}})) {
            st = NOCT_ERR_NOMEM;
            break;
        }
    }
    /* The generations, in a loop of its own: its scattered reads overlap,
     * where in the loop above each would wait behind the box tests. */
    for (size_t i = 0; i < colliding->n; ++i) {
        noctPair *q = &colliding->p[i];
        q->a.generation = noct_bp_generation(&w->bp, q->a.index);
        q->b.generation = noct_bp_generation(&w->bp, q->b.index);
    }
    if (level != NOCT_ACCURACY_BOX)
        *(level == NOCT_ACCURACY_CONVEX ? &w->c.narrow.seconds_convex
                                        : &w->c.narrow.seconds_exact) += noct_seconds() - t0;
    return st;
}
