/* SPDX-License-Identifier: MIT */
/*
 * queries: the questions a program asks a world between steps (query.h).
 *
 * Three objects, none moving: crate A, a cube of edge 1 at the origin;
 * crate B, a box 2 x 1 x 1 centred at (5, 0, 0), so from x = 4 to 6; and
 * a pillar, a mesh box 1 x 1 x 4 centred at (0, 5, 0). The program asks
 * which objects contain a point, meet a box, would collide with a gripper
 * (a box primitive) at two poses, where a ray first hits and everything it
 * hits, which object is nearest a point and which are within a distance of
 * it, where a moving gripper would first touch, and how far the crates are
 * apart. Every answer can be checked by hand from the numbers above.
 * Build it with
 *   cc queries.c $(pkg-config --cflags --libs noctree)
 */
#include <math.h>
#include <stdio.h>

#include <noctree/query.h>
#include <noctree/world.h>

static int fail(const char *what, const noctError *err)
{
    fprintf(stderr, "queries: %s: %s\n", what, err->message);
    return 1;
}

/* A noctObjectFcn: print the object's name (its user data). */
static bool print_name(void *context, noctObjectId id, void *user_data)
{
    (void)id;
    ++*(int *)context;
    printf(" %s", (const char *)user_data);
    return true;
}

/* A noctRayHitFcn: print each object the segment meets, and where. */
static bool print_hit(void *context, const noctRayHit *hit)
{
    (void)context;
    printf(" %s at %g", (const char *)hit->user_data, hit->fraction);
    return true;
}

/* A noctDistanceHitFcn: print each object within the distance, and how far. */
static bool print_distance(void *context, const noctDistanceHit *hit)
{
    (void)context;
    printf(" %s %g", (const char *)hit->user_data, hit->result.distance);
    return true;
}

static void end_line(int found)
{
    printf(found ? "\n" : " none\n");
}

int main(void)
{
    static char crate_a[] = "A", crate_b[] = "B", pillar_name[] = "pillar";
    noctError err;
    noctMesh *pillar;
    if (noctMeshCreateBox(0.5, 0.5, 2, &pillar, &err) != NOCT_OK)
        return fail("mesh", &err);
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS;
    noctWorld *w;
    if (noctWorldCreate(&wd, &w, &err) != NOCT_OK)
        return fail("create", &err);
    noctObjectDef d = noctDefaultObjectDef();
    d.type = NOCT_OBJECT_STATIC;
    noctObjectId a, b, p;
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 0.5;
    d.user_data = crate_a;
    if (noctWorldCreateObject(w, &d, &a, &err) != NOCT_OK)
        return fail("crate A", &err);
    d.half_extents[0] = 1;
    d.transform.p[0] = 5;
    d.user_data = crate_b;
    if (noctWorldCreateObject(w, &d, &b, &err) != NOCT_OK)
        return fail("crate B", &err);
    d.mesh = pillar;
    d.transform.p[0] = 0;
    d.transform.p[1] = 5;
    d.user_data = pillar_name;
    if (noctWorldCreateObject(w, &d, &p, &err) != NOCT_OK)
        return fail("pillar", &err);
    const noctQueryFilter all = noctDefaultQueryFilter();
    int found;

    /* a point on A's face is in A: closed solids */
    const double point[3] = {0.5, 0.2, 0.1};
    found = 0;
    printf("point (0.5, 0.2, 0.1):");
    if (noctWorldQueryPoint(w, point, all, print_name, &found, &err) != NOCT_OK)
        return fail("point", &err);
    end_line(found);

    /* a box from x = -1 to 4 meets A, and B at its face x = 4 */
    const double lo[3] = {-1, -1, -1}, hi[3] = {4, 1, 1};
    found = 0;
    printf("box (-1, -1, -1) (4, 1, 1):");
    if (noctWorldQueryBox(w, lo, hi, all, print_name, &found, &err) != NOCT_OK)
        return fail("box", &err);
    end_line(found);

    /* a gripper, a cube of edge 0.5 turned 45 degrees about z: it reaches
     * 0.25 sqrt 2 = 0.354 along x from its centre */
    const double half[3] = {0.25, 0.25, 0.25}, z[3] = {0, 0, 1};
    noctTransform pose = noctIdentityTransform();
    noctQuatFromAxisAngle(z, 45, &pose.q);
    for (int i = 0; i < 2; ++i) {
        pose.p[0] = i == 0 ? 2.5 : 3.7;
        found = 0;
        printf("gripper at x = %g:", pose.p[0]);
        if (noctWorldQueryShape(w, NULL, half, &pose, all, print_name, &found, &err) !=
            NOCT_OK)
            return fail("shape", &err);
        end_line(found);
    }

    /* a segment from (-5, 0.1, 0.2), 20 long along x: it enters A at
     * x = -0.5 and B at x = 4 */
    const double origin[3] = {-5, 0.1, 0.2}, along[3] = {20, 0, 0};
    noctRayHit hit;
    bool any;
    if (noctWorldRayCastClosest(w, origin, along, all, &hit, &any, &err) != NOCT_OK)
        return fail("ray", &err);
    if (any)
        printf("ray: first %s at %g, point (%g, %g, %g), normal (%g, %g, %g)\n",
               (const char *)hit.user_data, hit.fraction, hit.point[0], hit.point[1],
               hit.point[2], hit.normal[0], hit.normal[1], hit.normal[2]);
    printf("ray, every hit:");
    if (noctWorldRayCast(w, origin, along, all, print_hit, NULL, &err) != NOCT_OK)
        return fail("ray", &err);
    printf("\n");

    /* distances from the point (2.5, 0, 0): B's face x = 4 is 1.5 away,
     * A's x = 0.5 is 2, the pillar's corner (0.5, 4.5) is sqrt(4 + 20.25) */
    noctTransform at = noctIdentityTransform();
    at.p[0] = 2.5;
    noctDistanceHit near;
    if (noctWorldQueryNearest(w, NULL, NULL, &at, INFINITY, all, &near, &any, &err) != NOCT_OK)
        return fail("nearest", &err);
    if (any)
        printf("nearest to (2.5, 0, 0): %s at %g\n", (const char *)near.user_data,
               near.result.distance);
    printf("within 2.2 of (2.5, 0, 0):");
    if (noctWorldQueryWithin(w, NULL, NULL, &at, 2.2, all, print_distance, NULL, &err) !=
        NOCT_OK)
        return fail("within", &err);
    printf("\n");

    /* the gripper, not turned, moving from (2, 0, 0) by 4 along x: its face
     * at x = 2.25 reaches B at x = 4 after 1.75 of the 4 */
    noctTransform start = noctIdentityTransform();
    start.p[0] = 2;
    const double move[3] = {4, 0, 0};
    noctShapeHit touch;
    if (noctWorldCastShape(w, NULL, half, &start, move, all, &touch, &any, &err) != NOCT_OK)
        return fail("cast", &err);
    if (any)
        printf("gripper moving along x: touches %s at %g of the move\n",
               (const char *)touch.user_data, touch.sweep.time);

    noctDistanceResult r;
    if (noctWorldDistance(w, a, b, INFINITY, &r, &err) != NOCT_OK)
        return fail("distance", &err);
    printf("A - B: %g, nearest points (%g, %g, %g) and (%g, %g, %g)\n", r.distance,
           r.point_a[0], r.point_a[1], r.point_a[2], r.point_b[0], r.point_b[1],
           r.point_b[2]);
    noctWorldDestroy(w);
    noctMeshDestroy(pillar);
    return 0;
}
