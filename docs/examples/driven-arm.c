/* SPDX-License-Identifier: MIT */
/*
 * driven-arm: a program that drives its own objects. A two-link arm,
 * turning at its shoulder and elbow, is placed every frame with
 * noctWorldSetTransform() (rotation and translation); a crate stands on
 * the floor of its bay with a sensor box around it that tells when the
 * arm comes near, and a static wall closes the bay. The world has no
 * motion effect: it only detects. The demo prints every contact and
 * sensor event by frame. Build it with
 *   cc driven-arm.c $(pkg-config --cflags --libs noctree) -lm
 */
#include <math.h>
#include <stdio.h>

#include <noctree/world.h>

#define PI 3.14159265358979323846

static const char *const NAMES[] = {"upper arm", "forearm", "crate", "near the crate",
                                    "wall"};

/* The rotation by deg degrees about z. */
static noctQuat about_z(double deg)
{
    const double z[3] = {0, 0, 1};
    noctQuat q;
    noctQuatFromAxisAngle(z, deg, &q);
    return q;
}

static void print_events(const char *what, const noctPair *p, size_t n, int frame)
{
    for (size_t i = 0; i < n; ++i)
        printf("frame %2d: %s %s - %s\n", frame, what, NAMES[p[i].a.index],
               NAMES[p[i].b.index]);
}

int main(void)
{
    noctMesh *upper, *fore, *crate, *zone, *wall;
    if (noctMeshCreateBox(1, 0.1, 0.1, &upper, NULL) != NOCT_OK ||
        noctMeshCreateBox(0.75, 0.08, 0.08, &fore, NULL) != NOCT_OK ||
        noctMeshCreateBox(0.25, 0.25, 0.25, &crate, NULL) != NOCT_OK ||
        noctMeshCreateBox(0.6, 0.6, 0.6, &zone, NULL) != NOCT_OK ||
        noctMeshCreateBox(0.1, 3, 1, &wall, NULL) != NOCT_OK)
        return 1;
    noctWorldDef wd = noctDefaultWorldDef();
    wd.effects = NOCT_EFFECT_EVENTS; /* detection only: the program moves things */
    noctWorld *w;
    noctError err;
    if (noctWorldCreate(&wd, &w, &err) != NOCT_OK) {
        fprintf(stderr, "driven-arm: %s\n", err.message);
        return 1;
    }
    /* the objects, in the order of NAMES: their indices are 0 to 4 */
    noctObjectDef d = noctDefaultObjectDef();
    noctObjectId link[2], id;
    /* filters: the links (category 1) do not pair with each other; the
     * sensor (4) pairs only with them; crate and wall are category 2 */
    d.type = NOCT_OBJECT_KINEMATIC;
    d.category = 1;
    d.mask = ~(uint64_t)1;
    d.mesh = upper;
    noctWorldCreateObject(w, &d, &link[0], &err);
    d.mesh = fore;
    noctWorldCreateObject(w, &d, &link[1], &err);
    d.type = NOCT_OBJECT_STATIC;
    d.category = 2;
    d.mask = NOCT_FILTER_ALL;
    d.mesh = crate;
    d.transform.p[0] = 2.25;
    d.transform.p[1] = 1.5;
    noctWorldCreateObject(w, &d, &id, &err);
    d.mesh = zone;
    d.sensor = true;
    d.category = 4;
    d.mask = 1;
    noctWorldCreateObject(w, &d, &id, &err);
    d.mesh = wall;
    d.sensor = false;
    d.category = 2;
    d.mask = NOCT_FILTER_ALL;
    d.transform = noctIdentityTransform();
    d.transform.p[0] = 3.3;
    if (noctWorldCreateObject(w, &d, &id, &err) != NOCT_OK) {
        fprintf(stderr, "driven-arm: %s\n", err.message);
        return 1;
    }
    for (int frame = 0; frame <= 60; ++frame) {
        /* the shoulder swings from -30 to 60 degrees, the elbow bends */
        const double shoulder = 15 + 45 * sin(frame / 10.0);
        const double elbow = -40 + 30 * cos(frame / 7.0);
        const double r = shoulder * (PI / 180), e = (shoulder + elbow) * (PI / 180);
        noctTransform x = {{cos(r), sin(r), 0}, about_z(shoulder)};
        noctWorldSetTransform(w, link[0], &x, &err);
        x.p[0] = 2 * cos(r) + 0.75 * cos(e);
        x.p[1] = 2 * sin(r) + 0.75 * sin(e);
        x.q = about_z(shoulder + elbow);
        noctWorldSetTransform(w, link[1], &x, &err);
        if (noctWorldStep(w, &err) != NOCT_OK) {
            fprintf(stderr, "driven-arm: %s\n", err.message);
            return 1;
        }
        const noctPair *p;
        size_t n = noctWorldBegan(w, &p);
        print_events("contact", p, n, frame);
        n = noctWorldEnded(w, &p);
        print_events("apart", p, n, frame);
        n = noctWorldSensorBegan(w, &p);
        print_events("near", p, n, frame);
        n = noctWorldSensorEnded(w, &p);
        print_events("away", p, n, frame);
    }
    noctWorldDestroy(w);
    noctMeshDestroy(upper);
    noctMeshDestroy(fore);
    noctMeshDestroy(crate);
    noctMeshDestroy(zone);
    noctMeshDestroy(wall);
    return 0;
}
