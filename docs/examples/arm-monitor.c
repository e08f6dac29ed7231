/* SPDX-License-Identifier: MIT */
/*
 * arm-monitor: how far a robot arm is from hitting its bay, frame by frame.
 *
 * A two-link arm (box primitives: an upper arm 2 long from the shoulder at
 * (0, 0, 1), a forearm 1.5 long from the elbow) swings about z in a bay:
 * a floor, a wall whose face is the plane x = 3.3 and a crate. The
 * program places the links every frame from the joint angles with
 * noctWorldSetTransform() and steps a world without the motion effect.
 * The forearm carries a skin of 0.3 (its own margin, noctObjectDef::margin)
 * and the upper arm one of 0.1, the bay none: a pair is "near" when it
 * comes within the sum of its margins. Each frame the monitor prints the
 * near pairs with their distances (noctWorldNearDistances()): a warning
 * when one comes near, a hit when it collides, and when it is apart and
 * clear again. At the end it asks noctWorldDistance() how far the upper
 * arm is from the wall. Filters keep the links from pairing with each
 * other and the bay's parts from pairing among themselves. Build it with
 *   cc arm-monitor.c $(pkg-config --cflags --libs noctree)
 */
#include <math.h>
#include <stdio.h>

#include <noctree/query.h>
#include <noctree/world.h>

#define LINKS 1u /* category of the arm's links */
#define BAY 2u   /* category of the floor, the wall and the crate */

static const char *const NAMES[] = {"upper arm", "forearm", "floor", "wall", "crate"};

/* The rotation by deg degrees about z. */
static noctQuat about_z(double deg)
{
    const double z[3] = {0, 0, 1};
    noctQuat q;
    noctQuatFromAxisAngle(z, deg, &q);
    return q;
}

static int fail(const char *what, const noctError *err)
{
    fprintf(stderr, "arm-monitor: %s: %s\n", what, err->message);
    return 1;
}

static void print_pairs(int frame, const char *what, const noctPair *p, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        printf("frame %2d: %-7s %s - %s\n", frame, what, NAMES[p[i].a.index],
               NAMES[p[i].b.index]);
}

/* Add a box primitive of half-extents h at (x, y, z); index order is NAMES'. */
static noctStatus add_box(noctWorld *w, double hx, double hy, double hz, double x, double y,
                          double z, noctObjectType type, uint64_t category, uint64_t mask,
                          double margin, noctObjectId *id, noctError *err)
{
    noctObjectDef d = noctDefaultObjectDef();
    d.half_extents[0] = hx;
    d.half_extents[1] = hy;
    d.half_extents[2] = hz;
    d.transform.p[0] = x;
    d.transform.p[1] = y;
    d.transform.p[2] = z;
    d.type = type;
    d.category = category;
    d.mask = mask;
    d.margin = margin;
    return noctWorldCreateObject(w, &d, id, err);
}

int main(void)
{
    const double PI = 3.14159265358979323846;
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS; /* detection only: the program moves the arm */
    noctWorld *w;
    noctError err;
    if (noctWorldCreate(&wd, &w, &err) != NOCT_OK)
        return fail("create", &err);
    noctObjectId upper, fore, wall, id;
    if (add_box(w, 1, 0.1, 0.1, 1, 0, 1, NOCT_OBJECT_KINEMATIC, LINKS, BAY, 0.1, &upper,
                &err) != NOCT_OK ||
        add_box(w, 0.75, 0.08, 0.08, 2.75, 0, 1, NOCT_OBJECT_KINEMATIC, LINKS, BAY, 0.3, &fore,
                &err) != NOCT_OK ||
        add_box(w, 4, 5, 0.1, 0, 0, -0.1, NOCT_OBJECT_STATIC, BAY, LINKS, 0, &id, &err) !=
            NOCT_OK ||
        add_box(w, 0.1, 5, 1.5, 3.4, 0, 1, NOCT_OBJECT_STATIC, BAY, LINKS, 0, &wall, &err) !=
            NOCT_OK ||
        add_box(w, 0.25, 0.25, 0.25, 2.2, -1, 0.25, NOCT_OBJECT_STATIC, BAY, LINKS, 0, &id,
                &err) != NOCT_OK)
        return fail("add the bay", &err);

    for (int frame = 0; frame <= 40; ++frame) {
        /* the shoulder turns from 50 to -50 degrees, the elbow stays at -30 */
        const double shoulder = 50 - 2.5 * frame, elbow = -30;
        const double s = shoulder * (PI / 180), a = (shoulder + elbow) * (PI / 180);
        noctTransform x = {{cos(s), sin(s), 1}, about_z(shoulder)};
        if (noctWorldSetTransform(w, upper, &x, &err) != NOCT_OK)
            return fail("place the upper arm", &err);
        x.p[0] = 2 * cos(s) + 0.75 * cos(a);
        x.p[1] = 2 * sin(s) + 0.75 * sin(a);
        x.q = about_z(shoulder + elbow);
        if (noctWorldSetTransform(w, fore, &x, &err) != NOCT_OK)
            return fail("place the forearm", &err);
        if (noctWorldStep(w, &err) != NOCT_OK)
            return fail("step", &err);

        const noctPair *p;
        size_t n = noctWorldNearBegan(w, &p);
        print_pairs(frame, "warning", p, n);
        n = noctWorldBegan(w, &p);
        print_pairs(frame, "HIT", p, n);
        n = noctWorldEnded(w, &p);
        print_pairs(frame, "apart", p, n);
        n = noctWorldNearEnded(w, &p);
        print_pairs(frame, "clear", p, n);
        /* the near pairs, colliding ones included, and how far apart */
        const noctDistanceResult *r;
        if (noctWorldNearDistances(w, &r, &n, &err) != NOCT_OK)
            return fail("near distances", &err);
        noctWorldNear(w, &p);
        for (size_t i = 0; i < n; ++i)
            printf("frame %2d: near    %s - %s %.6f\n", frame, NAMES[p[i].a.index],
                   NAMES[p[i].b.index], r[i].distance);
    }
    noctDistanceResult d;
    if (noctWorldDistance(w, upper, wall, INFINITY, &d, &err) != NOCT_OK)
        return fail("distance", &err);
    printf("at the end: upper arm - wall %.6f (proved between %.6f and %.6f)\n", d.distance,
           d.lower, d.upper);
    noctWorldDestroy(w);
    return 0;
}
