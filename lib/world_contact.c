/* SPDX-License-Identifier: MIT */
/*
 * The colliding pairs' contacts (noctWorldContacts()): made on the first
 * call after a step, from the objects as they are, and kept until the
 * next step; the step itself only marks them stale, so a world whose
 * program never asks pays nothing for them.
 */
#include "config.h"

#include <string.h>

#include "array.h"
#include "world_internal.h"

NOCT_DEFINE_GROW(grow_contacts, noctContact)

/* Object s's shape (see noct_world_shape()) and whether the contact may
 * treat it as convex: a box primitive, or a convex or box-shaped mesh
 * (its rotated copy is that shape turned, its faces bent by rounding). */
static const noctMesh *shape(const noctWorld *w, uint32_t s, noct_shape_view *v, bool *convex)
{
    const noctMesh *src = noct_world_shape_of(w, s);
    *convex = src == NULL || noctMeshIsConvex(src) || src->has_box;
    return noct_world_shape(w, s, v);
}

noctStatus noctWorldContacts(noctWorld *w, const noctContact **contacts, size_t *n,
                             noctError *err)
{
    NOCT_REQUIRE(w != NULL && contacts != NULL && n != NULL);
    const noct_pair_list *now = &w->events.contact.now;
    *contacts = NULL;
    *n = 0;
    if (!w->contacts_made) {
        if (!grow_contacts(&w->contacts, &w->capcontacts, now->n))
            return noct_fail(err, NOCT_ERR_NOMEM, -1, 0, "out of memory");
        for (size_t i = 0; i < now->n; ++i) {
            noctContact *c = &w->contacts[i];
            if (noct_world_lookup(w, now->p[i].a) == NULL ||
                noct_world_lookup(w, now->p[i].b) == NULL) {
                /* removed since the step: no contact to tell */
                memset(c, 0, sizeof *c);
                c->kind = NOCT_CONTACT_NONE;
                continue;
            }
            const uint32_t a = now->p[i].a.index, b = now->p[i].b.index;
            noct_shape_view va, vb;
            bool ca, cb;
            const noctMesh *ma = shape(w, a, &va, &ca), *mb = shape(w, b, &vb, &cb);
            noctStatus st = noct_contact_placed(ma, w->pos[a], ca, mb, w->pos[b], cb, c);
            if (st != NOCT_OK)
                return noct_fail(err, st, (long)a, 0, "the contact of objects %u and %u: %s",
                                 a, b, noctStatusString(st));
        }
        w->contacts_made = true;
    }
    *contacts = now->n > 0 ? w->contacts : NULL;
    *n = now->n;
    return NOCT_OK;
}
