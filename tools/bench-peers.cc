// SPDX-License-Identifier: MIT
/*
 * bench-peers: libnoctree against the broadphases it means to beat, in one
 * run, on the same scenes.
 *
 * The peers are FCL's dynamic AABB tree and ODE's sweep-and-prune and hash
 * spaces, each with its library's own box-box test (FCL's boxBox2, ODE's
 * dBoxBox), the configurations the issue tracker quotes. Every library runs
 * the same scene, built here from noctree-families(7) for the peers and by
 * noctSceneFamily() for libnoctree, with the same dynamics: move, bounce off
 * the container walls, find the colliding pairs, reverse the objects of the
 * pairs that begin. Their contact-begin counts must agree (the scenes' known
 * answers), and the tool fails when they do not: a peer that found other
 * pairs did other work.
 *
 * Each run is a child process (its peak memory is its own), the libraries
 * take turns in every repeat, and a cell is the median over the repeats of
 * each run's per-step median, with half the range as a percentage. The
 * per-step time covers the whole step in every library: moving the
 * objects, updating the broadphase, the pair search, the box-box tests and
 * the response.
 *
 * A run stops early when its steps have taken more than --budget seconds
 * (default 60); its row then says how many steps it covers, and its events
 * are not compared.
 *
 * With --broadphase the libraries run their bare broadphases instead, on
 * the same axis-aligned boxes (each body's world-space bounding box): the
 * bodies move and bounce, each library updates its broadphase and counts
 * the overlapping pairs, with no narrowphase and no response. Their pair
 * totals must agree. With --broadphase --disputed they run side by side in
 * one process with an exact sweep over the boxes, and every pair that
 * they do not all give is printed with its boxes and the reason (see
 * run_disputed()).
 *
 * With --driven libnoctree runs twice on every scene, its runs taking
 * turns with the others: as always, with the world's built-in motion
 * effect (row libnoctree), and as a detection-only world that the program
 * drives (row noct-driven; also selectable with --libs): a world created
 * with the events effect only, whose objects are made with
 * noctWorldCreateObject() (the same meshes and positions as the family's),
 * while the program keeps every position and velocity itself, moves them
 * each step as the motion effect would (p += v, the container's walls
 * negating velocity components as noctree-families(7) says), teleports every object
 * with noctWorldSetTransform(), calls noctWorldStep(), and reverses the
 * objects of the pairs noctWorldBegan() reports. The positions are the
 * built-in motion's bit for bit, so the contact begins must be the same:
 * a line under the scene's rows gives the driven step time over the
 * built-in one and both counts, and the tool fails if the counts differ.
 * The driven step time covers the program's moves, the teleports, the
 * step and the response, as the built-in one covers the motion and the
 * response.
 *
 * With --queries (gas scenes only) it times queries on the scene as it
 * is set up, no steps: Q random boxes (a cube of twice the largest
 * half-extent), points and segments (a tenth of the container long) in the
 * container, the same for every library. libnoctree answers them exactly
 * on the placed shapes (noctWorldQueryBox(), noctWorldQueryPoint(),
 * noctWorldRayCast() for all hits and noctWorldRayCastClosest()); FCL's
 * dynamic AABB tree answers the boxes (its collide() of a box object
 * against the manager, each candidate through fcl::collide), and has no
 * point or segment query; Bullet's collision world answers the boxes
 * (contactTest()) and the segments (rayTest()), and has no point query.
 * The lines give queries a second and the objects found: FCL's must agree
 * with ours; Bullet's are printed beside them, with a line when they
 * differ (its tolerances decide touching boxes and grazing rays).
 *
 * With --nearest [Q] (gas scenes only, default gas:100000, Q 1000) it
 * times the nearest-object query on the scene as set up: Q random points
 * and Q random turned cubes, libnoctree's noctWorldQueryNearest() against
 * FCL's dynamic AABB tree distance() with a distance callback, per query,
 * with how many answers agree (run_nearest()).
 *
 * With --distance [C] it times the distance between two solids, C calls
 * (default 20000) of each library on each case, the same pairs in one
 * run: two bumpy spheres of 960 triangles each (bench-narrowphase's
 * non-convex "bumpy-960" mesh), turned at random, at gaps of about 1,
 * 0.1 and 0.001 of their radius and overlapping; and two boxes (half-
 * extents 0.5 0.4 0.3 and 0.35 0.45 0.25), turned, at the same gaps.
 * libnoctree answers with noctDistance() (nearest points, a proved
 * interval); FCL with fcl::distance() (nearest points; BVHModel<OBBRSS>
 * for the meshes, fcl::Box for the boxes); Bullet with btGjkPairDetector
 * (closest points of two btBoxShape, margin 0: the boxes themselves) on
 * the boxes; Bullet has no distance between two concave meshes. The
 * lines give microseconds a call, the ratio over libnoctree's, and the
 * largest difference of each peer's distance from libnoctree's interval.
 *
 * With --soups [P] it times the exact collision test of two meshes read
 * as triangle soups (every triangle its own three vertices, as in STL
 * files) and welded exactly: P (default 10 000) random turned poses of
 * two 960-triangle bumpy spheres, and of a small one (half size) against
 * a large one of 4 992 triangles (three times the size), so that one is
 * often inside the other. libnoctree answers with noctCollideTransformed()
 * at the exact level (the solids share a point), FCL with fcl::collide()
 * on BVHModel<OBBRSS> (the triangles intersect). Every pose on which the
 * two differ is checked by the bench's own exact test in GMP rationals on
 * the vertices placed as transform.h says (triangle against triangle,
 * then a point of each inside the other by ray parity); the tool fails if
 * libnoctree's verdict is not the exact one. A third case makes the large
 * one an open surface (noctMeshCreateSurfaceFromData(): the triangles with
 * a corner above a cap left out), whose meaning is FCL's: the triangles
 * meet; the verdicts must then all agree.
 *
 * Usage: bench-peers [--quick] [--broadphase [--disputed] | --driven | --queries [Q]
 *                    | --nearest [Q] | --distance [C] | --soups [P]]
 *                    [--steps S] [--repeats R] [--N N|auto] [--budget SEC] [--libs LIST]
 *                    [--csv FILE] [SCENE...]
 * Exit status: 0, 1 if a run failed or the events differ, 2 for bad usage.
 */
#include <btBulletCollisionCommon.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/distance.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <gmpxx.h>
#include <ode/ode.h>

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <noctree/mesh.h>
#include <noctree/narrowphase.h>
#include <noctree/scene.h>
#include <noctree/transform.h>
#include <noctree/version.h>
#include <noctree/query.h>
#include <noctree/world.h>

#include "benchutil.h"

namespace {

// The clock and the statistics are the benchmark programs' (benchutil.h).
double now()
{
    return tool_now();
}

// ---- the scenes, from noctree-families(7) -------------------------------------------

struct Body {
    double c[3];  // centre
    double r[9];  // rotation, row-major; its columns are the box's axes
    double h[3];  // half-extents
    double v[3];  // velocity: direction times speed
    double q[4];  // the rotation r as noctree-families(7)'s quaternion (x, y, z, w)
};

struct Scene {
    std::vector<Body> body;
    bool walls = false;
    double lb = 0; // the gas container [0, lb]^3
};

uint64_t splitmix64(uint64_t &s)
{
    uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double draw(uint64_t &s)
{
    return static_cast<double>(splitmix64(s) >> 11) * (1.0 / 9007199254740992.0);
}

// planes:K or gas:N, checked; false with a message for anything else.
bool parse_scene(const char *spec, bool *gas, long *size)
{
    char *end;
    if (std::strncmp(spec, "planes:", 7) == 0) {
        *gas = false;
        *size = std::strtol(spec + 7, &end, 10);
        if (end != spec + 7 && *end == '\0' && *size >= 0 && *size <= 1000)
            return true;
    } else if (std::strncmp(spec, "gas:", 4) == 0) {
        *gas = true;
        *size = std::strtol(spec + 4, &end, 10);
        if (end != spec + 4 && *end == '\0' && *size >= 1 && *size <= 10000000)
            return true;
    }
    std::fprintf(stderr,
                 "bench-peers: '%s': a scene is planes:K (K 0 to 1000) or gas:N "
                 "(N 1 to 10000000)\n",
                 spec);
    return false;
}

/* The scene's known contact-begin count in the first steps steps, if
 * noctree-families(7) gives one: on the planes ring r's facing pair begins at step
 * 51 + 2r and never again; gas has answers for 200 steps. */
bool known_begins(bool gas, long size, int steps, size_t *known)
{
    if (!gas) {
        const long rings = steps < 51 ? -1 : std::min(size, static_cast<long>((steps - 51) / 2));
        *known = static_cast<size_t>((2 * rings + 1) * (2 * rings + 1));
        if (rings < 0)
            *known = 0;
        return true;
    }
    *known = size == 1000 ? 6212 : size == 10000 ? 77281 : size == 100000 ? 783455 : 0;
    return steps == 200 && *known != 0;
}

Scene make_scene(bool gas, long size)
{
    Scene s;
    if (!gas) {
        const long k = size;
        for (int side = 0; side < 2; ++side)
            for (long i = -k; i <= k; ++i)
                for (long j = -k; j <= k; ++j) {
                    const long r = std::max(std::labs(i), std::labs(j));
                    const double sign = side == 0 ? -1.0 : 1.0;
                    Body b = {{sign * (3.02 + 0.1 * static_cast<double>(r)),
                               2.0 * static_cast<double>(i), 2.0 * static_cast<double>(j)},
                              {1, 0, 0, 0, 1, 0, 0, 0, 1},
                              {0.5, 0.5, 0.5},
                              {-sign * 0.05, 0, 0},
                              {0, 0, 0, 1}};
                    s.body.push_back(b);
                }
        return s;
    }
    const long n = size;
    const double pi = 3.141592653589793;
    s.walls = true;
    s.lb = std::cbrt(10.0 * static_cast<double>(n));
    uint64_t st = 42;
    for (long i = 0; i < n; ++i) {
        Body b;
        for (int a = 0; a < 3; ++a)
            b.h[a] = 0.25 + 0.5 * draw(st);
        const double u1 = draw(st), u2 = draw(st), u3 = draw(st);
        const double x = std::sqrt(1 - u1) * std::sin(2 * pi * u2);
        const double y = std::sqrt(1 - u1) * std::cos(2 * pi * u2);
        const double z = std::sqrt(u1) * std::sin(2 * pi * u3);
        const double w = std::sqrt(u1) * std::cos(2 * pi * u3);
        const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                             2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                             2 * (x * z - y * w),     2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
        std::memcpy(b.r, r, sizeof r);
        const double q[4] = {x, y, z, w};
        std::memcpy(b.q, q, sizeof q);
        for (int a = 0; a < 3; ++a)
            b.c[a] = s.lb * draw(st);
        const double dz = 2 * draw(st) - 1, phi = 2 * pi * draw(st);
        const double d[3] = {std::sqrt(1 - dz * dz) * std::cos(phi),
                             std::sqrt(1 - dz * dz) * std::sin(phi), dz};
        for (int a = 0; a < 3; ++a)
            b.v[a] = 0.05 * d[a];
        s.body.push_back(b);
    }
    return s;
}

// ---- the dynamics every peer shares -----------------------------------------

// A colliding pair as one sortable key: lower index in the high half.
uint64_t key(uintptr_t a, uintptr_t b)
{
    if (a > b)
        std::swap(a, b);
    return (static_cast<uint64_t>(a) << 32) | static_cast<uint64_t>(b);
}

struct Dynamics {
    std::vector<Body> &body;
    const Scene &scene;
    std::vector<uint64_t> now, before, began;
    std::vector<unsigned char> flip;
    size_t begins = 0;

    Dynamics(std::vector<Body> &b, const Scene &s) : body(b), scene(s), flip(b.size()) {}

    // p += v, then the walls: a centre coordinate outside [0, lb] that
    // still moves outward has that velocity component negated.
    void move()
    {
        for (Body &b : body)
            for (int a = 0; a < 3; ++a) {
                b.c[a] += b.v[a];
                if (scene.walls &&
                    ((b.c[a] < 0 && b.v[a] < 0) || (b.c[a] > scene.lb && b.v[a] > 0)))
                    b.v[a] = -b.v[a];
            }
    }

    // The contact-begin reversal on the pairs in now.
    void respond()
    {
        std::sort(now.begin(), now.end());
        now.erase(std::unique(now.begin(), now.end()), now.end());
        began.clear();
        std::set_difference(now.begin(), now.end(), before.begin(), before.end(),
                            std::back_inserter(began));
        begins += began.size();
        for (uint64_t p : began)
            flip[p >> 32] = flip[p & 0xffffffffu] = 1;
        for (uint64_t p : began)
            for (uint32_t i : {static_cast<uint32_t>(p >> 32), static_cast<uint32_t>(p)})
                if (flip[i]) {
                    flip[i] = 0;
                    for (int a = 0; a < 3; ++a)
                        body[i].v[a] = -body[i].v[a];
                }
        before.swap(now);
        now.clear();
    }
};

// ---- one run of one library ---------------------------------------------------

struct Result {
    double median, p90, setup;
    size_t objects, begins; // begins: overlapping pairs with --broadphase
    int steps; // steps done: fewer than asked when the budget ran out
    int ok;
};

struct Options {
    bool broadphase = false; // pairs of boxes only: --broadphase
    int steps = 200;
    int repeats = 3;
    int N = NOCT_AUTO; // the world's own choice, as users get it
    double budget = 60;
};

// Per-step times into a result.
void summarize(std::vector<double> &t, Result &r)
{
    tool_sort(t.data(), t.size());
    r.steps = static_cast<int>(t.size());
    r.median = t.empty() ? 0 : tool_rank(t.data(), t.size(), 1, 2);
    r.p90 = t.empty() ? 0 : tool_rank(t.data(), t.size(), 9, 10);
    r.ok = !t.empty();
}

Result run_noctree(const char *spec, const Options &o)
{
    Result r = {};
    const double t0 = now();
    noctScene *sc;
    noctWorld *w;
    noctError err;
    if (noctSceneFamily(spec, &sc, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return r;
    }
    noctSceneDef(sc)->N = o.N;
    if (noctSceneBuild(sc, &w, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return r;
    }
    r.setup = now() - t0;
    r.objects = noctWorldObjectCount(w);
    std::vector<double> t;
    const double start = now();
    for (int s = 0; s < o.steps && now() - start < o.budget; ++s) {
        const double a = now();
        if (noctWorldStep(w, &err) != NOCT_OK) {
            std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
            return r;
        }
        t.push_back(now() - a);
        const noctPair *p;
        r.begins += noctWorldBegan(w, &p);
    }
    summarize(t, r);
    noctWorldDestroy(w);
    noctSceneDestroy(sc);
    return r;
}

/*
 * libnoctree's world driven by the program (--driven): a detection-only
 * world (events only: no motion, no walls, no response) with the same
 * objects as noctSceneFamily()'s, each made with noctWorldCreateObject()
 * as a kinematic object: for gas a box primitive of the box's
 * half-extents turned by its quaternion (as noctWorldAddGas() makes it),
 * for the planes the unit cube mesh. The program keeps every position,
 * velocity and rotation itself, as a program that drives its objects
 * would: one compact record an object (Mover, 80 bytes, taken bit for bit
 * from make_scene()'s Body, whose 200 bytes also hold what only the peers
 * read). Each step, in one pass, it moves and bounces each object as
 * Dynamics::move does (as the world's motion effect does) and teleports
 * it with noctWorldSetTransform() (its position and its unchanged
 * rotation); then it steps the world and reverses the objects of the
 * pairs noctWorldBegan() reports: the same trajectories, so the same
 * contact begins, as the built-in motion's. The step time covers all of
 * it, as the built-in motion's covers its motion and response.
 */
Result run_driven(const char *spec, Scene &s, bool gas, const Options &o)
{
    Result r = {};
    const double t0 = now();
    noctError err;
    noctScene *sc;
    // The world's parameters are the family's (depth, accuracy, N as run).
    if (noctSceneFamily(spec, &sc, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return r;
    }
    noctWorldDef def = *noctSceneDef(sc);
    noctSceneDestroy(sc);
    def.N = o.N;
    def.effects = NOCT_EFFECT_EVENTS;
    noctWorld *w;
    if (noctWorldCreate(&def, &w, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return r;
    }
    // The family's shapes: box primitives for the gas, one unit cube
    // mesh for the planes (noctWorldAddPlanes()).
    noctMesh *cube = nullptr;
    std::vector<noctObjectId> id(s.body.size());
    noctStatus st = noctWorldReserve(w, s.body.size(), &err);
    if (st == NOCT_OK && !gas)
        st = noctMeshCreateBox(0.5, 0.5, 0.5, &cube, &err);
    for (size_t i = 0; i < s.body.size() && st == NOCT_OK; ++i) {
        const Body &b = s.body[i];
        noctObjectDef od = noctDefaultObjectDef();
        od.mesh = cube;
        if (gas)
            std::memcpy(od.half_extents, b.h, sizeof od.half_extents);
        std::memcpy(od.transform.p, b.c, sizeof od.transform.p);
        od.transform.q = noctQuat{b.q[0], b.q[1], b.q[2], b.q[3]};
        od.type = NOCT_OBJECT_KINEMATIC;
        st = noctWorldCreateObject(w, &od, &id[i], &err);
    }
    // Began pairs name slots: the body of each slot.
    uint32_t slots = 0;
    for (const noctObjectId &d : id)
        slots = std::max(slots, d.index + 1);
    std::vector<uint32_t> body_of(slots, UINT32_MAX);
    for (size_t i = 0; i < id.size(); ++i)
        body_of[id[i].index] = static_cast<uint32_t>(i);
    // The program's own state: an object's place (the transform it sets),
    // its velocity, and its slot in the world.
    struct Mover {
        noctTransform x;
        double v[3];
        noctObjectId id;
    };
    std::vector<Mover> mover(s.body.size());
    for (size_t i = 0; i < s.body.size(); ++i) {
        const Body &b = s.body[i];
        mover[i].x = {{b.c[0], b.c[1], b.c[2]}, {b.q[0], b.q[1], b.q[2], b.q[3]}};
        std::memcpy(mover[i].v, b.v, sizeof mover[i].v);
        mover[i].id = id[i];
    }
    std::vector<unsigned char> flip(s.body.size());
    r.setup = now() - t0;
    r.objects = s.body.size();
    std::vector<double> t;
    const double start = now();
    for (int step = 0; st == NOCT_OK && step < o.steps && now() - start < o.budget; ++step) {
        const double a = now();
        for (size_t i = 0; i < mover.size() && st == NOCT_OK; ++i) {
            Mover &m = mover[i];
            for (int c = 0; c < 3; ++c) { // as Dynamics::move
                m.x.p[c] += m.v[c];
                if (s.walls && ((m.x.p[c] < 0 && m.v[c] < 0) || (m.x.p[c] > s.lb && m.v[c] > 0)))
                    m.v[c] = -m.v[c];
            }
            st = noctWorldSetTransform(w, m.id, &m.x, &err);
        }
        if (st == NOCT_OK)
            st = noctWorldStep(w, &err);
        if (st != NOCT_OK)
            break;
        // The contact-begin reversal: each object of a begun pair once.
        const noctPair *p;
        const size_t nb = noctWorldBegan(w, &p);
        r.begins += nb;
        for (size_t k = 0; k < nb; ++k)
            flip[body_of[p[k].a.index]] = flip[body_of[p[k].b.index]] = 1;
        for (size_t k = 0; k < nb; ++k)
            for (uint32_t i : {body_of[p[k].a.index], body_of[p[k].b.index]})
                if (flip[i]) {
                    flip[i] = 0;
                    for (int c = 0; c < 3; ++c)
                        mover[i].v[c] = -mover[i].v[c];
                }
        t.push_back(now() - a);
    }
    if (st != NOCT_OK)
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
    else
        summarize(t, r);
    noctWorldDestroy(w);
    noctMeshDestroy(cube);
    return r;
}

struct FclContext {
    std::vector<uint64_t> *pairs;
};

bool fcl_pair(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data)
{
    fcl::CollisionRequestd req;
    fcl::CollisionResultd res;
    fcl::collide(a, b, req, res);
    if (res.isCollision())
        static_cast<FclContext *>(data)->pairs->push_back(
            key(reinterpret_cast<uintptr_t>(a->getUserData()),
                reinterpret_cast<uintptr_t>(b->getUserData())));
    return false; // go on
}

Result run_fcl(Scene &s, const Options &o)
{
    Result r = {};
    const double t0 = now();
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> obj;
    std::vector<fcl::CollisionObjectd *> raw;
    for (size_t i = 0; i < s.body.size(); ++i) {
        const Body &b = s.body[i];
        auto box = std::make_shared<fcl::Boxd>(2 * b.h[0], 2 * b.h[1], 2 * b.h[2]);
        fcl::Matrix3d rot;
        rot << b.r[0], b.r[1], b.r[2], b.r[3], b.r[4], b.r[5], b.r[6], b.r[7], b.r[8];
        obj.emplace_back(new fcl::CollisionObjectd(box, rot, fcl::Vector3d(b.c[0], b.c[1], b.c[2])));
        obj.back()->setUserData(reinterpret_cast<void *>(static_cast<uintptr_t>(i)));
        raw.push_back(obj.back().get());
    }
    fcl::DynamicAABBTreeCollisionManagerd mgr;
    mgr.registerObjects(raw);
    mgr.setup();
    r.setup = now() - t0;
    r.objects = s.body.size();
    Dynamics dyn(s.body, s);
    FclContext ctx = {&dyn.now};
    std::vector<double> t;
    const double start = now();
    for (int step = 0; step < o.steps && now() - start < o.budget; ++step) {
        const double a = now();
        dyn.move();
        for (size_t i = 0; i < raw.size(); ++i) {
            raw[i]->setTranslation(fcl::Vector3d(s.body[i].c[0], s.body[i].c[1], s.body[i].c[2]));
            raw[i]->computeAABB();
        }
        mgr.update();
        mgr.collide(&ctx, fcl_pair);
        dyn.respond();
        t.push_back(now() - a);
    }
    r.begins = dyn.begins;
    summarize(t, r);
    return r;
}

void ode_pair(void *data, dGeomID a, dGeomID b)
{
    dContactGeom c;
    if (dCollide(a, b, 1, &c, sizeof c) > 0)
        static_cast<std::vector<uint64_t> *>(data)->push_back(
            key(reinterpret_cast<uintptr_t>(dGeomGetData(a)),
                reinterpret_cast<uintptr_t>(dGeomGetData(b))));
}

Result run_ode(Scene &s, const Options &o, bool sap, bool gas)
{
    Result r = {};
    const double t0 = now();
    dInitODE2(0);
    // SAP sorts on the first axis: the planes' cubes share their x.
    dSpaceID space = sap ? dSweepAndPruneSpaceCreate(nullptr, gas ? dSAP_AXES_XYZ : dSAP_AXES_YZX)
                         : dHashSpaceCreate(nullptr);
    std::vector<dGeomID> geom;
    for (size_t i = 0; i < s.body.size(); ++i) {
        const Body &b = s.body[i];
        dGeomID g = dCreateBox(space, 2 * b.h[0], 2 * b.h[1], 2 * b.h[2]);
        dMatrix3 rot = {b.r[0], b.r[1], b.r[2], 0, b.r[3], b.r[4], b.r[5], 0,
                        b.r[6], b.r[7], b.r[8], 0};
        dGeomSetRotation(g, rot);
        dGeomSetPosition(g, b.c[0], b.c[1], b.c[2]);
        dGeomSetData(g, reinterpret_cast<void *>(static_cast<uintptr_t>(i)));
        geom.push_back(g);
    }
    r.setup = now() - t0;
    r.objects = s.body.size();
    Dynamics dyn(s.body, s);
    std::vector<double> t;
    const double start = now();
    for (int step = 0; step < o.steps && now() - start < o.budget; ++step) {
        const double a = now();
        dyn.move();
        for (size_t i = 0; i < geom.size(); ++i)
            dGeomSetPosition(geom[i], s.body[i].c[0], s.body[i].c[1], s.body[i].c[2]);
        dSpaceCollide(space, &dyn.now, ode_pair);
        dyn.respond();
        t.push_back(now() - a);
    }
    r.begins = dyn.begins;
    summarize(t, r);
    dSpaceDestroy(space); // destroys the geoms too
    dCloseODE();
    return r;
}

// ---- the bare broadphases (--broadphase) ------------------------------------
//
// The same boxes in every library: each body's world-space bounding box,
// as a centre c and half-extents e (e = |R| h), given to libnoctree as
// [c - e, c + e] and to FCL and ODE as an axis-aligned box of sides 2e at
// c, whose bounding boxes they compute as exactly c -+ e. The bodies move
// and bounce off the walls, with no response: every library sees the same
// boxes at every step and must count the same overlapping pairs (closed
// boxes: touching counts, in all three).

void world_box(const Body &b, double c[3], double e[3])
{
    for (int a = 0; a < 3; ++a) {
        c[a] = b.c[a];
        e[a] = std::fabs(b.r[3 * a]) * b.h[0] + std::fabs(b.r[3 * a + 1]) * b.h[1] +
               std::fabs(b.r[3 * a + 2]) * b.h[2];
    }
}

// p += v and the walls, as Dynamics::move (which the response needs).
void move_bodies(Scene &s)
{
    for (Body &b : s.body)
        for (int a = 0; a < 3; ++a) {
            b.c[a] += b.v[a];
            if (s.walls && ((b.c[a] < 0 && b.v[a] < 0) || (b.c[a] > s.lb && b.v[a] > 0)))
                b.v[a] = -b.v[a];
        }
}

Result run_bp_noctree(Scene &s, const Options &o)
{
    Result r = {};
    const double t0 = now();
    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = o.N;
    noctBroadphase *bp;
    noctError err;
    if (noctBroadphaseCreate(&def, &bp, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s\n", err.message);
        return r;
    }
    std::vector<noctProxyId> id(s.body.size());
    double c[3], e[3];
    for (size_t i = 0; i < s.body.size(); ++i) {
        world_box(s.body[i], c, e);
        const double lo[3] = {c[0] - e[0], c[1] - e[1], c[2] - e[2]};
        const double hi[3] = {c[0] + e[0], c[1] + e[1], c[2] + e[2]};
        if (noctBroadphaseAdd(bp, lo, hi, nullptr, NOCT_FILTER_ALL, NOCT_FILTER_ALL, &id[i],
                              &err) != NOCT_OK) {
            std::fprintf(stderr, "bench-peers: %s\n", err.message);
            return r;
        }
    }
    r.setup = now() - t0;
    r.objects = s.body.size();
    std::vector<double> t;
    const double start = now();
    for (int step = 0; step < o.steps && now() - start < o.budget; ++step) {
        const double a = now();
        move_bodies(s);
        for (size_t i = 0; i < s.body.size(); ++i) {
            world_box(s.body[i], c, e);
            const double lo[3] = {c[0] - e[0], c[1] - e[1], c[2] - e[2]};
            const double hi[3] = {c[0] + e[0], c[1] + e[1], c[2] + e[2]};
            if (noctBroadphaseMove(bp, id[i], lo, hi, &err) != NOCT_OK) {
                std::fprintf(stderr, "bench-peers: %s\n", err.message);
                return r;
            }
        }
        if (noctBroadphaseUpdatePairs(bp, &err) != NOCT_OK) {
            std::fprintf(stderr, "bench-peers: %s\n", err.message);
            return r;
        }
        const noctProxyPair *p;
        r.begins += noctBroadphasePairs(bp, &p);
        t.push_back(now() - a);
    }
    summarize(t, r);
    noctBroadphaseDestroy(bp);
    return r;
}

bool fcl_count(fcl::CollisionObjectd *, fcl::CollisionObjectd *, void *data)
{
    ++*static_cast<size_t *>(data);
    return false; // go on
}

Result run_bp_fcl(Scene &s, const Options &o)
{
    Result r = {};
    const double t0 = now();
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> obj;
    std::vector<fcl::CollisionObjectd *> raw;
    double c[3], e[3];
    for (const Body &b : s.body) {
        world_box(b, c, e);
        auto box = std::make_shared<fcl::Boxd>(2 * e[0], 2 * e[1], 2 * e[2]);
        obj.emplace_back(new fcl::CollisionObjectd(box, fcl::Matrix3d::Identity(),
                                                   fcl::Vector3d(c[0], c[1], c[2])));
        raw.push_back(obj.back().get());
    }
    fcl::DynamicAABBTreeCollisionManagerd mgr;
    mgr.registerObjects(raw);
    mgr.setup();
    r.setup = now() - t0;
    r.objects = s.body.size();
    std::vector<double> t;
    const double start = now();
    for (int step = 0; step < o.steps && now() - start < o.budget; ++step) {
        const double a = now();
        move_bodies(s);
        for (size_t i = 0; i < raw.size(); ++i) {
            world_box(s.body[i], c, e);
            raw[i]->setTranslation(fcl::Vector3d(c[0], c[1], c[2]));
            raw[i]->computeAABB();
        }
        mgr.update();
        size_t n = 0;
        mgr.collide(&n, fcl_count);
        r.begins += n;
        t.push_back(now() - a);
    }
    summarize(t, r);
    return r;
}

void ode_count(void *data, dGeomID, dGeomID)
{
    ++*static_cast<size_t *>(data);
}

Result run_bp_ode(Scene &s, const Options &o, bool sap, bool gas)
{
    Result r = {};
    const double t0 = now();
    dInitODE2(0);
    dSpaceID space = sap ? dSweepAndPruneSpaceCreate(nullptr, gas ? dSAP_AXES_XYZ : dSAP_AXES_YZX)
                         : dHashSpaceCreate(nullptr);
    std::vector<dGeomID> geom;
    double c[3], e[3];
    for (const Body &b : s.body) {
        world_box(b, c, e);
        dGeomID g = dCreateBox(space, 2 * e[0], 2 * e[1], 2 * e[2]);
        dGeomSetPosition(g, c[0], c[1], c[2]);
        geom.push_back(g);
    }
    r.setup = now() - t0;
    r.objects = s.body.size();
    std::vector<double> t;
    const double start = now();
    for (int step = 0; step < o.steps && now() - start < o.budget; ++step) {
        const double a = now();
        move_bodies(s);
        for (size_t i = 0; i < geom.size(); ++i)
            dGeomSetPosition(geom[i], s.body[i].c[0], s.body[i].c[1], s.body[i].c[2]);
        size_t n = 0;
        dSpaceCollide(space, &n, ode_count);
        r.begins += n;
        t.push_back(now() - a);
    }
    summarize(t, r);
    dSpaceDestroy(space);
    dCloseODE();
    return r;
}

// ---- the disputed pairs (--broadphase --disputed) ---------------------------
//
// Why the bare broadphases' pair totals differ: one process runs
// libnoctree's broadphase, FCL's dynamic AABB tree and ODE's sweep and
// prune on the same moving boxes as --broadphase does, and also finds the
// overlapping pairs exactly: a sweep over the boxes sorted by their low x
// that tests lo_a <= hi_b && lo_b <= hi_a on every axis, in the boxes' own
// doubles (closed boxes: touching counts). Every pair that the four do not
// all give is printed with both boxes, each library's answer and the
// reason; at the end, each library's total and how many of its pairs were
// wrong or missing, and whether FCL's and ODE's boxes (fcl::AABB,
// dGeomGetAABB()) were bit for bit the boxes given to libnoctree.
//
// ODE's sweep and prune (0.16, collision_sapspace.cpp, BoxPruning) keeps
// its sort axis (the first of dSAP_AXES_XYZ, x, for gas; y for the
// planes) in single precision: each box's low end is stored as a float to
// be radix-sorted, and the sweep compares it with the other box's high end
// rounded to float too, so two boxes whose ends on that axis round to the
// same float count as touching there. The other two axes it compares in
// doubles. ode_sap_test() replays that test.

// A box as its library holds it: lo[3], hi[3].
struct Box6 {
    double lo[3], hi[3];
};

Box6 body_box(const Body &b)
{
    double c[3], e[3];
    world_box(b, c, e);
    return {{c[0] - e[0], c[1] - e[1], c[2] - e[2]}, {c[0] + e[0], c[1] + e[1], c[2] + e[2]}};
}

bool boxes_overlap(const Box6 &a, const Box6 &b)
{
    for (int k = 0; k < 3; ++k)
        if (!(a.lo[k] <= b.hi[k] && b.lo[k] <= a.hi[k]))
            return false;
    return true;
}

// ODE's test as its sweep and prune makes it: the sort axis in floats.
bool ode_sap_test(const Box6 &a, const Box6 &b, int sort_axis)
{
    for (int k = 0; k < 3; ++k) {
        const float alo = static_cast<float>(a.lo[k]), ahi = static_cast<float>(a.hi[k]);
        const float blo = static_cast<float>(b.lo[k]), bhi = static_cast<float>(b.hi[k]);
        const bool o = k == sort_axis ? alo <= bhi && blo <= ahi
                                      : a.lo[k] <= b.hi[k] && b.lo[k] <= a.hi[k];
        if (!o)
            return false;
    }
    return true;
}

// The exact pairs: boxes sorted by low x (copied in that order, so that
// the sweep reads memory in order), each against those after it whose low
// x is within its high x, tested on every axis; sorted keys out.
struct Sorted {
    Box6 box;
    uint32_t index;
};

void exact_pairs(const std::vector<Box6> &box, std::vector<Sorted> &sorted,
                 std::vector<uint64_t> &out)
{
    out.clear();
    sorted.resize(box.size());
    for (size_t i = 0; i < box.size(); ++i)
        sorted[i] = {box[i], static_cast<uint32_t>(i)};
    std::sort(sorted.begin(), sorted.end(),
              [](const Sorted &x, const Sorted &y) { return x.box.lo[0] < y.box.lo[0]; });
    for (size_t i = 0; i < sorted.size(); ++i) {
        const Box6 &a = sorted[i].box;
        for (size_t j = i + 1; j < sorted.size() && sorted[j].box.lo[0] <= a.hi[0]; ++j)
            if (boxes_overlap(a, sorted[j].box))
                out.push_back(key(sorted[i].index, sorted[j].index));
    }
    std::sort(out.begin(), out.end());
}

bool noct_collect(void *context, noctProxyId, void *user_a, noctProxyId, void *user_b)
{
    static_cast<std::vector<uint64_t> *>(context)->push_back(
        key(reinterpret_cast<uintptr_t>(user_a), reinterpret_cast<uintptr_t>(user_b)));
    return true;
}

bool fcl_collect(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data)
{
    static_cast<std::vector<uint64_t> *>(data)->push_back(
        key(reinterpret_cast<uintptr_t>(a->getUserData()),
            reinterpret_cast<uintptr_t>(b->getUserData())));
    return false; // go on
}

void ode_collect(void *data, dGeomID a, dGeomID b)
{
    static_cast<std::vector<uint64_t> *>(data)->push_back(
        key(reinterpret_cast<uintptr_t>(dGeomGetData(a)),
            reinterpret_cast<uintptr_t>(dGeomGetData(b))));
}

// Why the libraries disagree on a pair: each axis's gap, and ODE's floats.
void print_dispute(const char *spec, int step, uint64_t p, const Box6 &a, const Box6 &b,
                   const bool has[4], int sort_axis)
{
    static const char *const name[4] = {"exact", "libnoctree", "fcl-dtree", "ode-sap"};
    static const char axis[3] = {'x', 'y', 'z'};
    const unsigned ia = static_cast<unsigned>(p >> 32), ib = static_cast<unsigned>(p);
    std::printf("%s step %d: boxes %u and %u %s; given by", spec, step, ia, ib,
                has[0] ? "overlap" : "are disjoint");
    for (int l = 1; l < 4; ++l)
        if (has[l])
            std::printf(" %s", name[l]);
    std::printf("; not by");
    for (int l = 1; l < 4; ++l)
        if (!has[l])
            std::printf(" %s", name[l]);
    std::putchar('\n');
    for (const Box6 *q : {&a, &b})
        std::printf("  box %u: lo %.17g %.17g %.17g  hi %.17g %.17g %.17g\n",
                    q == &a ? ia : ib, q->lo[0], q->lo[1], q->lo[2], q->hi[0], q->hi[1],
                    q->hi[2]);
    for (int k = 0; k < 3; ++k) {
        // The gap between the facing ends, the larger of the two: > 0
        // apart, 0 touching, < 0 overlapping.
        const double ga = b.lo[k] - a.hi[k], gb = a.lo[k] - b.hi[k];
        const bool a_first = ga >= gb;
        const double hi = a_first ? a.hi[k] : b.hi[k], lo = a_first ? b.lo[k] : a.lo[k];
        const double gap = a_first ? ga : gb;
        std::printf("  %c: hi of %u %.17g, lo of %u %.17g: %s %.3g", axis[k], a_first ? ia : ib,
                    hi, a_first ? ib : ia, lo,
                    gap > 0 ? "apart by" : gap == 0 ? "touching," : "overlapping by",
                    gap > 0 ? gap : -gap);
        if (k == sort_axis)
            std::printf("; ODE's sort axis, in floats: %.9g and %.9g%s",
                        static_cast<double>(static_cast<float>(hi)),
                        static_cast<double>(static_cast<float>(lo)),
                        gap > 0 && static_cast<float>(lo) <= static_cast<float>(hi)
                            ? ", the same float: ODE calls them touching"
                            : "");
        std::putchar('\n');
    }
}

bool run_disputed(const char *spec, const Options &o)
{
    bool gas;
    long size;
    if (!parse_scene(spec, &gas, &size))
        return false;
    Scene s = make_scene(gas, size);
    const size_t n = s.body.size();
    const int sort_axis = gas ? 0 : 1; // dSAP_AXES_XYZ or dSAP_AXES_YZX, as run_bp_ode()
    std::vector<Box6> box(n);
    for (size_t i = 0; i < n; ++i)
        box[i] = body_box(s.body[i]);

    noctBroadphaseDef def = noctDefaultBroadphaseDef();
    def.N = o.N;
    noctBroadphase *bp;
    noctError err;
    if (noctBroadphaseCreate(&def, &bp, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s\n", err.message);
        return false;
    }
    std::vector<noctProxyId> id(n);
    for (size_t i = 0; i < n; ++i)
        if (noctBroadphaseAdd(bp, box[i].lo, box[i].hi, reinterpret_cast<void *>(i),
                              NOCT_FILTER_ALL, NOCT_FILTER_ALL, &id[i], &err) != NOCT_OK) {
            std::fprintf(stderr, "bench-peers: %s\n", err.message);
            noctBroadphaseDestroy(bp);
            return false;
        }

    std::vector<std::unique_ptr<fcl::CollisionObjectd>> obj;
    std::vector<fcl::CollisionObjectd *> raw;
    double c[3], e[3];
    for (size_t i = 0; i < n; ++i) {
        world_box(s.body[i], c, e);
        auto shape = std::make_shared<fcl::Boxd>(2 * e[0], 2 * e[1], 2 * e[2]);
        obj.emplace_back(new fcl::CollisionObjectd(shape, fcl::Matrix3d::Identity(),
                                                   fcl::Vector3d(c[0], c[1], c[2])));
        obj.back()->setUserData(reinterpret_cast<void *>(i));
        raw.push_back(obj.back().get());
    }
    fcl::DynamicAABBTreeCollisionManagerd mgr;
    mgr.registerObjects(raw);
    mgr.setup();

    dInitODE2(0);
    dSpaceID space = dSweepAndPruneSpaceCreate(nullptr, gas ? dSAP_AXES_XYZ : dSAP_AXES_YZX);
    std::vector<dGeomID> geom;
    for (size_t i = 0; i < n; ++i) {
        world_box(s.body[i], c, e);
        dGeomID g = dCreateBox(space, 2 * e[0], 2 * e[1], 2 * e[2]);
        dGeomSetPosition(g, c[0], c[1], c[2]);
        dGeomSetData(g, reinterpret_cast<void *>(i));
        geom.push_back(g);
    }

    std::printf("bench-peers --broadphase --disputed: %s, %d steps: the pairs that libnoctree "
                "(N = %s), FCL and\nODE's sweep and prune do not all give, against the exact "
                "pairs (closed boxes in doubles)\n",
                spec, o.steps, o.N == NOCT_AUTO ? "auto" : std::to_string(o.N).c_str());
    // pairs[0] exact, then libnoctree, FCL, ODE.
    std::vector<uint64_t> pairs[4];
    std::vector<Sorted> sorted;
    size_t total[4] = {}, extra[4] = {}, missed[4] = {}, replay_wrong = 0;
    size_t fcl_box_differs = 0, ode_box_differs = 0, shown = 0;
    const size_t show_max = 100;
    bool ok = true;
    for (int step = 1; step <= o.steps && ok; ++step) {
        move_bodies(s);
        for (size_t i = 0; i < n; ++i) {
            box[i] = body_box(s.body[i]);
            world_box(s.body[i], c, e);
            if (noctBroadphaseMove(bp, id[i], box[i].lo, box[i].hi, &err) != NOCT_OK) {
                std::fprintf(stderr, "bench-peers: %s\n", err.message);
                ok = false;
                break;
            }
            raw[i]->setTranslation(fcl::Vector3d(c[0], c[1], c[2]));
            raw[i]->computeAABB();
            dGeomSetPosition(geom[i], c[0], c[1], c[2]);
        }
        if (!ok || noctBroadphaseUpdatePairs(bp, &err) != NOCT_OK) {
            std::fprintf(stderr, "bench-peers: %s\n", err.message);
            ok = false;
            break;
        }
        for (std::vector<uint64_t> &v : pairs)
            v.clear();
        exact_pairs(box, sorted, pairs[0]);
        noctBroadphaseForEachPair(bp, noct_collect, &pairs[1]);
        mgr.update();
        mgr.collide(&pairs[2], fcl_collect);
        dSpaceCollide(space, &pairs[3], ode_collect);
        for (int l = 0; l < 4; ++l)
            total[l] += pairs[l].size(); // as --broadphase counts them
        for (int l = 1; l < 4; ++l) {
            std::sort(pairs[l].begin(), pairs[l].end());
            // A pair given twice would be a wrong pair too.
            const size_t before = pairs[l].size();
            pairs[l].erase(std::unique(pairs[l].begin(), pairs[l].end()), pairs[l].end());
            extra[l] += before - pairs[l].size();
        }
        // The boxes the peers hold, against ours, bit for bit.
        for (size_t i = 0; i < n; ++i) {
            const fcl::AABBd &fb = raw[i]->getAABB();
            dReal ob[6];
            dGeomGetAABB(geom[i], ob);
            bool fd = false, od = false;
            for (int k = 0; k < 3; ++k) {
                fd = fd || fb.min_[k] != box[i].lo[k] || fb.max_[k] != box[i].hi[k];
                od = od || ob[2 * k] != box[i].lo[k] || ob[2 * k + 1] != box[i].hi[k];
            }
            fcl_box_differs += fd;
            ode_box_differs += od;
        }
        // Every pair that one of the four gives and another does not.
        std::vector<uint64_t> all;
        for (const std::vector<uint64_t> &v : pairs)
            all.insert(all.end(), v.begin(), v.end());
        std::sort(all.begin(), all.end());
        for (size_t i = 0; i < all.size();) {
            size_t j = i;
            while (j < all.size() && all[j] == all[i])
                ++j;
            if (j - i < 4) { // not in all four lists
                const uint64_t p = all[i];
                const Box6 &a = box[p >> 32], &b = box[p & 0xffffffffu];
                bool has[4];
                for (int l = 0; l < 4; ++l)
                    has[l] = std::binary_search(pairs[l].begin(), pairs[l].end(), p);
                for (int l = 1; l < 4; ++l) {
                    extra[l] += has[l] && !has[0];
                    missed[l] += !has[l] && has[0];
                }
                replay_wrong += ode_sap_test(a, b, sort_axis) != has[3];
                if (shown++ < show_max)
                    print_dispute(spec, step, p, a, b, has, sort_axis);
            }
            i = j;
        }
    }
    if (shown > show_max)
        std::printf("(%zu more disputed pairs not shown)\n", shown - show_max);
    static const char *const name[4] = {"exact", "libnoctree", "fcl-dtree", "ode-sap"};
    std::printf("%s, %d steps: %zu disputed pairs; exact pairs %zu", spec, o.steps, shown,
                total[0]);
    for (int l = 1; l < 4; ++l)
        std::printf("; %s %zu (%zu wrong, %zu missing)", name[l], total[l], extra[l], missed[l]);
    std::printf("\n%s: ODE's test replayed (sort axis in floats, the others in doubles) "
                "disagrees with ODE on %zu of the %zu disputed pairs\n",
                spec, replay_wrong, shown);
    std::printf("%s: boxes different from libnoctree's: FCL %zu, ODE %zu of %zu (%zu boxes, "
                "%d steps)\n",
                spec, fcl_box_differs, ode_box_differs, n * static_cast<size_t>(o.steps), n,
                o.steps);
    dSpaceDestroy(space);
    dCloseODE();
    noctBroadphaseDestroy(bp);
    return ok && extra[1] == 0 && missed[1] == 0;
}

// The runs, in the order they take turns and are printed: libnoctree's
// built-in motion first (every x is over it), the driven world next to it.
enum { NOCTREE, DRIVEN, FCL_DTREE, ODE_SAP, ODE_HASH, NLIBS };
const char *const LIBS[NLIBS] = {"libnoctree", "noct-driven", "fcl-dtree", "ode-sap",
                                 "ode-hash"};

Result run_one(const char *spec, int lib, const Options &o)
{
    bool gas;
    long size;
    if (!parse_scene(spec, &gas, &size))
        return Result{};
    if (o.broadphase) {
        Scene s = make_scene(gas, size);
        if (lib == NOCTREE)
            return run_bp_noctree(s, o);
        if (lib == FCL_DTREE)
            return run_bp_fcl(s, o);
        return run_bp_ode(s, o, lib == ODE_SAP, gas);
    }
    if (lib == NOCTREE)
        return run_noctree(spec, o);
    Scene s = make_scene(gas, size);
    if (lib == DRIVEN)
        return run_driven(spec, s, gas, o);
    if (lib == FCL_DTREE)
        return run_fcl(s, o);
    return run_ode(s, o, lib == ODE_SAP, gas);
}

// Runs one configuration in a child process; peak is its peak memory in KiB.
bool run_child(const char *spec, int lib, const Options &o, Result &r, long &peak)
{
    int fds[2];
    if (pipe(fds) != 0) {
        std::perror("bench-peers: pipe");
        return false;
    }
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) {
        std::perror("bench-peers: fork");
        return false;
    }
    if (pid == 0) {
        close(fds[0]);
        Result res = run_one(spec, lib, o);
        ssize_t wr = write(fds[1], &res, sizeof res);
        _exit(wr == static_cast<ssize_t>(sizeof res) ? 0 : 1);
    }
    close(fds[1]);
    ssize_t got = read(fds[0], &r, sizeof r);
    close(fds[0]);
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) < 0)
        return false;
    peak = ru.ru_maxrss;
    return got == static_cast<ssize_t>(sizeof r) && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0 && r.ok;
}

double median_of(std::vector<double> v)
{
    return tool_median(v.data(), v.size());
}

bool parse_int(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = std::strtol(s, &end, 10);
    if (errno != 0 || end == s || *end != '\0' || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

void usage(FILE *f)
{
    std::fputs("usage: bench-peers [--quick] [--broadphase [--disputed] | --driven |\n"
               "                   --queries [Q] | --nearest [Q] | --distance [C]] [--steps S]\n"
               "                   [--repeats R] [--N N|auto] [--budget SEC] [--libs LIST]\n"
               "                   [--csv FILE] [SCENE...]\n"
               "SCENE is planes:K or gas:N (default planes:10 planes:100 planes:300\n"
               "gas:10000 gas:100000); LIST is a comma-separated subset of\n"
               "libnoctree,noct-driven,fcl-dtree,ode-sap,ode-hash (default\n"
               "libnoctree,fcl-dtree,ode-sap: ode-hash takes seconds a step on the\n"
               "large planes).\n"
               "--quick: planes:3 gas:1000, 1 repeat, 200 steps.\n"
               "--broadphase: the bare broadphases on the scenes' boxes, pairs of\n"
               "overlapping boxes only (no narrowphase, no response); the pairs\n"
               "column is their total over the steps, and must agree.\n"
               "--broadphase --disputed: on each scene (default gas:100000), runs\n"
               "libnoctree, fcl-dtree and ode-sap side by side in one process with\n"
               "the exact pairs (closed boxes in doubles) and prints every pair they\n"
               "do not all give, with both boxes and the reason; exit status 1 if\n"
               "libnoctree's pairs are not the exact ones.\n"
               "--driven: also run noct-driven, libnoctree's world without its motion\n"
               "effect, driven by the program: it moves every object each step with\n"
               "noctWorldSetTransform() to the positions the built-in motion gives,\n"
               "steps the world and reverses the objects of the pairs noctWorldBegan()\n"
               "reports; a line per scene gives its step time over the built-in\n"
               "motion's (row libnoctree) and both contact-begin counts, which must be\n"
               "the same.\n"
               "--queries [Q]: no steps; Q (default 10000) random box, point and\n"
               "segment queries on each gas scene (default gas:10000 gas:100000) as\n"
               "set up, queries a second; FCL answers the boxes, and the objects both\n"
               "find must agree.\n"
               "--nearest [Q]: no steps; the nearest object to Q (default 1000) random\n"
               "points and boxes on each gas scene (default gas:100000), libnoctree's\n"
               "noctWorldQueryNearest() against FCL's distance(): microseconds a query,\n"
               "their ratio, and how many answers agree.\n"
               "--distance [C]: no scenes; C (default 20000) distance calls of each\n"
               "library on each case: two 960-triangle bumpy spheres and two boxes,\n"
               "turned, at gaps 1, 0.1, 0.001 and overlapping; microseconds a call,\n"
               "ratios, and the largest disagreement with libnoctree's interval.\n"
               "--soups [P]: no scenes; P (default 10000) random poses of meshes read\n"
               "as triangle soups and welded: libnoctree's exact collision test against\n"
               "FCL's collide() (BVHModel<OBBRSS>), microseconds a pose, the ratio, and\n"
               "every differing verdict checked exactly.\n",
               f);
}

// ---- queries (--queries) --------------------------------------------------------

struct QuerySet {
    std::vector<std::array<double, 6>> box; // lo, hi
    std::vector<std::array<double, 3>> point;
    std::vector<std::array<double, 6>> ray; // origin, translation
};

QuerySet make_queries(const Scene &s, long q)
{
    QuerySet qs;
    uint64_t st = 7;
    const double side = 2 * 0.75, len = s.lb / 10;
    for (long i = 0; i < q; ++i) {
        std::array<double, 6> b, r;
        std::array<double, 3> p;
        for (int a = 0; a < 3; ++a) {
            b[a] = s.lb * draw(st);
            b[a + 3] = b[a] + side;
            p[a] = s.lb * draw(st);
            r[a] = s.lb * draw(st);
        }
        const double dz = 2 * draw(st) - 1, phi = 2 * 3.141592653589793 * draw(st);
        r[3] = len * std::sqrt(1 - dz * dz) * std::cos(phi);
        r[4] = len * std::sqrt(1 - dz * dz) * std::sin(phi);
        r[5] = len * dz;
        qs.box.push_back(b);
        qs.point.push_back(p);
        qs.ray.push_back(r);
    }
    return qs;
}

bool count_object(void *context, noctObjectId, void *)
{
    ++*static_cast<size_t *>(context);
    return true;
}

// Hits, and (second) those at fraction 0: segments that start in a solid.
bool count_hit(void *context, const noctRayHit *h)
{
    size_t *n = static_cast<size_t *>(context);
    ++n[0];
    n[1] += h->fraction == 0;
    return true;
}

struct FclQuery {
    fcl::CollisionObjectd *q;
    size_t found;
};

bool fcl_query(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data)
{
    FclQuery *c = static_cast<FclQuery *>(data);
    fcl::CollisionRequestd req;
    fcl::CollisionResultd res;
    fcl::collide(a, b, req, res);
    c->found += res.isCollision();
    return false;
}

void print_query_row(const char *scene, const char *lib, const char *kind, long q, double sec,
                     size_t found)
{
    std::printf("%-12s %-12s %-16s %8ld %12.0f %10.2f %10zu\n", scene, lib, kind, q,
                static_cast<double>(q) / sec, 1e6 * sec / static_cast<double>(q), found);
}

// Bullet's collision world (btDbvtBroadphase, its dynamic AABB trees) on
// the same boxes, margins 0 so that its boxes are the scene's: the boxes
// through contactTest() with a box object (the objects it reports contact
// points with), the segments through rayTest() with its all-hits and
// closest-hit callbacks. Bullet has no point query. Its answers are
// printed beside ours; they may differ on touching boxes (a contact at
// distance 0) and grazing rays, where its tolerances decide.
struct BulletObjects : btCollisionWorld::ContactResultCallback {
    std::vector<const btCollisionObject *> hit;
    btScalar addSingleResult(btManifoldPoint &p, const btCollisionObjectWrapper *a, int, int,
                             const btCollisionObjectWrapper *b, int, int) override
    {
        if (p.getDistance() <= 0) { /* touching or overlapping, not merely near */
            hit.push_back(a->getCollisionObject());
            hit.push_back(b->getCollisionObject());
        }
        return 0;
    }
};

bool bullet_queries(const char *spec, const Scene &s, const QuerySet &qs, long q, size_t boxes,
                    const size_t rays[2], size_t closest, size_t closest_inside)
{
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btCollisionWorld world(&dispatcher, &broadphase, &config);
    std::vector<std::unique_ptr<btBoxShape>> shape;
    std::vector<std::unique_ptr<btCollisionObject>> obj;
    for (const Body &b : s.body) {
        shape.emplace_back(new btBoxShape(btVector3(b.h[0], b.h[1], b.h[2])));
        shape.back()->setMargin(0);
        obj.emplace_back(new btCollisionObject());
        btTransform x(btMatrix3x3(b.r[0], b.r[1], b.r[2], b.r[3], b.r[4], b.r[5], b.r[6], b.r[7],
                                  b.r[8]),
                      btVector3(b.c[0], b.c[1], b.c[2]));
        obj.back()->setWorldTransform(x);
        obj.back()->setCollisionShape(shape.back().get());
        world.addCollisionObject(obj.back().get());
    }
    world.updateAabbs();
    size_t found_boxes = 0, found_rays = 0, found_closest = 0;
    double t = now();
    for (const auto &b : qs.box) {
        btBoxShape box(btVector3((b[3] - b[0]) / 2, (b[4] - b[1]) / 2, (b[5] - b[2]) / 2));
        box.setMargin(0);
        btCollisionObject qo;
        qo.setCollisionShape(&box);
        btTransform x;
        x.setIdentity();
        x.setOrigin(btVector3((b[0] + b[3]) / 2, (b[1] + b[4]) / 2, (b[2] + b[5]) / 2));
        qo.setWorldTransform(x);
        BulletObjects r;
        world.contactTest(&qo, r);
        std::sort(r.hit.begin(), r.hit.end());
        r.hit.erase(std::unique(r.hit.begin(), r.hit.end()), r.hit.end());
        found_boxes += r.hit.size() - (std::find(r.hit.begin(), r.hit.end(), &qo) != r.hit.end());
    }
    print_query_row(spec, "bullet", "box", q, now() - t, found_boxes);
    t = now();
    for (const auto &r : qs.ray) {
        const btVector3 from(r[0], r[1], r[2]), to(r[0] + r[3], r[1] + r[4], r[2] + r[5]);
        btCollisionWorld::AllHitsRayResultCallback cb(from, to);
        world.rayTest(from, to, cb);
        std::vector<const btCollisionObject *> o;
        for (int k = 0; k < cb.m_collisionObjects.size(); ++k)
            o.push_back(cb.m_collisionObjects[k]);
        std::sort(o.begin(), o.end());
        found_rays += std::unique(o.begin(), o.end()) - o.begin();
    }
    print_query_row(spec, "bullet", "segment, all", q, now() - t, found_rays);
    t = now();
    for (const auto &r : qs.ray) {
        const btVector3 from(r[0], r[1], r[2]), to(r[0] + r[3], r[1] + r[4], r[2] + r[5]);
        btCollisionWorld::ClosestRayResultCallback cb(from, to);
        world.rayTest(from, to, cb);
        found_closest += cb.hasHit();
    }
    print_query_row(spec, "bullet", "segment, first", q, now() - t, found_closest);
    for (auto &o : obj)
        world.removeCollisionObject(o.get());
    // Where the counts differ, the line says so, with how many of our hits
    // are at fraction 0 (segments that start in a solid, which Bullet's ray
    // test reports only sometimes).
    if (found_boxes != boxes || found_rays != rays[0] || found_closest != closest)
        std::printf("%s: Bullet found %zu, %zu and %zu objects in the boxes, along the segments "
                    "and first on them; libnoctree %zu, %zu and %zu (%zu and %zu of them at "
                    "fraction 0: segments that start in a solid)\n",
                    spec, found_boxes, found_rays, found_closest, boxes, rays[0], closest,
                    rays[1], closest_inside);
    return true;
}

// Returns false when a library failed or the two disagree.
bool run_queries(const char *spec, long q, const Options &o)
{
    bool gas;
    long size;
    if (!parse_scene(spec, &gas, &size) || !gas) {
        std::fprintf(stderr, "bench-peers: --queries runs on gas scenes only: %s\n", spec);
        return false;
    }
    Scene s = make_scene(gas, size);
    QuerySet qs = make_queries(s, q);
    noctError err;
    noctScene *sc;
    noctWorld *w = nullptr;
    if (noctSceneFamily(spec, &sc, &err) != NOCT_OK ||
        (noctSceneDef(sc)->N = o.N, noctSceneBuild(sc, &w, &err)) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return false;
    }
    noctSceneDestroy(sc);
    const noctQueryFilter all = noctDefaultQueryFilter();
    bool ok = true;
    size_t boxes = 0, points = 0, rays[2] = {0, 0}, closest = 0, closest_inside = 0;
    double t = now();
    for (const auto &b : qs.box)
        ok = ok && noctWorldQueryBox(w, &b[0], &b[3], all, count_object, &boxes, &err) == NOCT_OK;
    const double t_box = now() - t;
    t = now();
    for (const auto &p : qs.point)
        ok = ok && noctWorldQueryPoint(w, &p[0], all, count_object, &points, &err) == NOCT_OK;
    const double t_point = now() - t;
    t = now();
    for (const auto &r : qs.ray)
        ok = ok && noctWorldRayCast(w, &r[0], &r[3], all, count_hit, rays, &err) == NOCT_OK;
    const double t_ray = now() - t;
    t = now();
    for (const auto &r : qs.ray) {
        noctRayHit h;
        bool found;
        ok = ok && noctWorldRayCastClosest(w, &r[0], &r[3], all, &h, &found, &err) == NOCT_OK;
        closest += found;
        closest_inside += found && h.fraction == 0;
    }
    const double t_closest = now() - t;
    noctWorldDestroy(w);
    if (!ok) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return false;
    }
    print_query_row(spec, "libnoctree", "box", q, t_box, boxes);
    print_query_row(spec, "libnoctree", "point", q, t_point, points);
    print_query_row(spec, "libnoctree", "segment, all", q, t_ray, rays[0]);
    print_query_row(spec, "libnoctree", "segment, first", q, t_closest, closest);
    // FCL: the same boxes as box objects against its manager.
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> obj;
    std::vector<fcl::CollisionObjectd *> raw;
    for (const Body &b : s.body) {
        auto box = std::make_shared<fcl::Boxd>(2 * b.h[0], 2 * b.h[1], 2 * b.h[2]);
        fcl::Matrix3d rot;
        rot << b.r[0], b.r[1], b.r[2], b.r[3], b.r[4], b.r[5], b.r[6], b.r[7], b.r[8];
        obj.emplace_back(new fcl::CollisionObjectd(box, rot, fcl::Vector3d(b.c[0], b.c[1], b.c[2])));
        raw.push_back(obj.back().get());
    }
    fcl::DynamicAABBTreeCollisionManagerd mgr;
    mgr.registerObjects(raw);
    mgr.setup();
    size_t fcl_boxes = 0;
    t = now();
    for (const auto &b : qs.box) {
        auto shape = std::make_shared<fcl::Boxd>(b[3] - b[0], b[4] - b[1], b[5] - b[2]);
        fcl::CollisionObjectd qo(shape, fcl::Matrix3d::Identity(),
                                 fcl::Vector3d((b[0] + b[3]) / 2, (b[1] + b[4]) / 2,
                                               (b[2] + b[5]) / 2));
        FclQuery c = {&qo, 0};
        mgr.collide(&qo, &c, fcl_query);
        fcl_boxes += c.found;
    }
    print_query_row(spec, "fcl-dtree", "box", q, now() - t, fcl_boxes);
    const bool bullet_ok = bullet_queries(spec, s, qs, q, boxes, rays, closest, closest_inside);
    if (fcl_boxes != boxes) {
        std::printf("%s: box queries found %zu objects in libnoctree and %zu in FCL\n", spec,
                    boxes, fcl_boxes);
        return false;
    }
    return bullet_ok;
}


// ---- distances (--distance) -----------------------------------------------------

// bench-narrowphase's bumpy sphere: a UV sphere of n segments and m rings
// (2 n (m - 1) triangles), its radius times 1 + bump (smooth noise).
void bumpy_sphere(int n, int m, double bump, std::vector<double> &v, std::vector<uint32_t> &t)
{
    const double pi = 3.14159265358979323846, ph = 1.3, pk = 4.1;
    v.clear();
    t.clear();
    for (int r = 0; r <= m; ++r) {
        const double theta = pi * r / m;
        for (int s = 0; s < (r == 0 || r == m ? 1 : n); ++s) {
            const double phi = 2 * pi * s / n;
            const double rad = 1 + bump * (0.5 * std::sin(3 * theta + ph) * std::cos(4 * phi + pk) +
                                           0.5 * std::sin(5 * phi) * std::sin(2 * theta));
            v.push_back(rad * std::sin(theta) * std::cos(phi));
            v.push_back(rad * std::sin(theta) * std::sin(phi));
            v.push_back(rad * std::cos(theta));
        }
    }
    const uint32_t last = static_cast<uint32_t>(v.size() / 3 - 1);
    for (int s = 0; s < n; ++s) {
        const uint32_t a = 1 + s, b = 1 + (s + 1) % n;
        t.insert(t.end(), {0, a, b});
        const uint32_t base = 1 + (m - 2) * n;
        t.insert(t.end(), {last, base + (s + 1) % n, base + s});
    }
    for (int r = 1; r + 1 < m; ++r)
        for (int s = 0; s < n; ++s) {
            const uint32_t a = 1 + (r - 1) * n + s, b = 1 + (r - 1) * n + (s + 1) % n;
            t.insert(t.end(), {a, a + n, b});
            t.insert(t.end(), {b, a + n, b + n});
        }
}

struct DistPair {
    noctTransform xa, xb;
    double lower, upper; // libnoctree's interval
    bool colliding;
};

fcl::Transform3d fcl_transform(const noctTransform &x)
{
    fcl::Transform3d T = fcl::Transform3d::Identity();
    T.linear() = fcl::Quaterniond(x.q.w, x.q.x, x.q.y, x.q.z).toRotationMatrix();
    T.translation() = fcl::Vector3d(x.p[0], x.p[1], x.p[2]);
    return T;
}

btTransform bt_transform(const noctTransform &x)
{
    return btTransform(btQuaternion(x.q.x, x.q.y, x.q.z, x.q.w),
                       btVector3(x.p[0], x.p[1], x.p[2]));
}

// Microseconds a call of f over the pairs, calls in all: the best of
// three rounds.
template <class F> double time_calls(const std::vector<DistPair> &pairs, long calls, F f)
{
    double best = INFINITY;
    for (int round = 0; round < 3; ++round) {
        const double t0 = now();
        for (long c = 0; c < calls; ++c)
            f(pairs[static_cast<size_t>(c) % pairs.size()]);
        best = std::min(best, (now() - t0) / static_cast<double>(calls) * 1e6);
    }
    return best;
}

// Pairs of a and b at random turns and directions, B moved out (or in)
// along the direction until libnoctree's distance is gap (bisection), or
// overlapping (gap < 0: centres overlap_at apart).
bool make_pairs(const noctMesh *a, const noctMesh *b, double gap, double overlap_at,
                uint64_t &rng, std::vector<DistPair> &pairs)
{
    for (int i = 0; i < 16; ++i) {
        DistPair p;
        p.xa = noctIdentityTransform();
        p.xb = noctIdentityTransform();
        double q[4], n = 0;
        do {
            for (double &c : q)
                c = 2 * draw(rng) - 1;
            n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        } while (n < 0.1 || n > 1);
        p.xa.q = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
        do {
            for (double &c : q)
                c = 2 * draw(rng) - 1;
            n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        } while (n < 0.1 || n > 1);
        p.xb.q = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
        double dir[3];
        do {
            for (double &c : dir)
                c = 2 * draw(rng) - 1;
            n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        } while (n < 0.1 || n > 1);
        for (double &c : dir)
            c /= n;
        noctDistanceResult r;
        auto at = [&](double s) {
            for (int k = 0; k < 3; ++k)
                p.xb.p[k] = dir[k] * s;
            return noctDistance(a, &p.xa, b, &p.xb, INFINITY, &r, nullptr, nullptr) == NOCT_OK;
        };
        if (gap < 0) {
            if (!at(overlap_at))
                return false;
        } else {
            double lo = 0, hi = 8;
            for (int it = 0; it < 60; ++it) {
                const double mid = (lo + hi) / 2;
                if (!at(mid))
                    return false;
                (r.colliding || r.distance < gap ? lo : hi) = mid;
            }
            if (!at(hi))
                return false;
        }
        p.lower = r.lower;
        p.upper = r.upper;
        p.colliding = r.colliding;
        pairs.push_back(p);
    }
    return true;
}

// A peer's distance d against libnoctree's interval: how far outside.
double off_interval(const DistPair &p, double d)
{
    if (p.colliding)
        return d > 0 ? d : 0; // peers give 0 or a negative depth
    return d < p.lower ? p.lower - d : (d > p.upper ? d - p.upper : 0);
}

bool run_distance(long calls)
{
    std::printf("bench-peers --distance: libnoctree %s (efficient build) noctDistance() against "
                "FCL %s\n(fcl::distance, nearest points) and Bullet %d.%02d "
                "(btGjkPairDetector, boxes only); %ld calls\nof each on each case, 16 turned "
                "pairs in turn, best of 3 rounds; one thread\n\n",
                NOCT_VERSION_STRING, FCL_VERSION, BT_BULLET_VERSION / 100,
                BT_BULLET_VERSION % 100, calls);
    std::printf("%-14s %-10s %10s %8s %14s %12s\n", "case", "library", "us/call", "x",
                "max off (abs)", "distance");
    std::vector<double> v;
    std::vector<uint32_t> t;
    bumpy_sphere(32, 16, 0.3, v, t);
    std::vector<uint32_t> sizes(t.size() / 3, 3);
    noctMesh *ma = nullptr, *mb = nullptr, *ba = nullptr, *bb = nullptr;
    noctError err;
    if (noctMeshCreate(v.data(), v.size() / 3, sizes.data(), sizes.size(), t.data(), &ma,
                       &err) != NOCT_OK ||
        noctMeshCreate(v.data(), v.size() / 3, sizes.data(), sizes.size(), t.data(), &mb,
                       &err) != NOCT_OK ||
        noctMeshCreateBox(0.5, 0.4, 0.3, &ba, &err) != NOCT_OK ||
        noctMeshCreateBox(0.35, 0.45, 0.25, &bb, &err) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: --distance: %s\n", err.message);
        return false;
    }
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    {
        std::vector<fcl::Vector3d> pts;
        std::vector<fcl::Triangle> tris;
        for (size_t i = 0; i < v.size(); i += 3)
            pts.emplace_back(v[i], v[i + 1], v[i + 2]);
        for (size_t i = 0; i < t.size(); i += 3)
            tris.emplace_back(t[i], t[i + 1], t[i + 2]);
        model->beginModel();
        model->addSubModel(pts, tris);
        model->endModel();
    }
    auto fbox_a = std::make_shared<fcl::Boxd>(1.0, 0.8, 0.6);
    auto fbox_b = std::make_shared<fcl::Boxd>(0.7, 0.9, 0.5);
    btBoxShape bt_a(btVector3(0.5, 0.4, 0.3)), bt_b(btVector3(0.35, 0.45, 0.25));
    bt_a.setMargin(0);
    bt_b.setMargin(0);
    uint64_t rng = 2026;
    const double gaps[4] = {1, 0.1, 0.001, -1};
    const char *gap_names[4] = {"1", "0.1", "0.001", "overlap"};
    bool ok = true;
    for (int kind = 0; kind < 2 && ok; ++kind)
        for (int g = 0; g < 4 && ok; ++g) {
            const bool meshes = kind == 0;
            const noctMesh *a = meshes ? ma : ba, *b = meshes ? mb : bb;
            std::vector<DistPair> pairs;
            if (!make_pairs(a, b, meshes ? gaps[g] : gaps[g] / 2, meshes ? 1.2 : 0.3, rng,
                            pairs)) {
                std::fprintf(stderr, "bench-peers: --distance: noctDistance failed\n");
                ok = false;
                break;
            }
            const std::string name = std::string(meshes ? "bumpy-960 " : "boxes ") +
                                     (meshes ? gap_names[g] : (g == 3 ? "overlap" :
                                      g == 0 ? "0.5" : g == 1 ? "0.05" : "0.0005"));
            double sink = 0;
            const double ours = time_calls(pairs, calls, [&](const DistPair &p) {
                noctDistanceResult r;
                noctDistance(a, &p.xa, b, &p.xb, INFINITY, &r, nullptr, nullptr);
                sink += r.distance;
            });
            double mean = 0;
            for (const DistPair &p : pairs)
                mean += (p.lower + p.upper) / 2 / static_cast<double>(pairs.size());
            std::printf("%-14s %-10s %10.3f %8s %14s %12.6g\n", name.c_str(), "libnoctree", ours,
                        "1.00", "-", mean);
            // FCL
            std::shared_ptr<fcl::CollisionGeometryd> ga, gb;
            if (meshes) {
                ga = model;
                gb = model;
            } else {
                ga = fbox_a;
                gb = fbox_b;
            }
            fcl::CollisionObjectd oa(ga), ob(gb);
            double off = 0;
            for (const DistPair &p : pairs) {
                oa.setTransform(fcl_transform(p.xa));
                ob.setTransform(fcl_transform(p.xb));
                fcl::DistanceRequestd req(true);
                fcl::DistanceResultd res;
                fcl::distance(&oa, &ob, req, res);
                off = std::max(off, off_interval(p, res.min_distance));
            }
            const double tf = time_calls(pairs, calls, [&](const DistPair &p) {
                oa.setTransform(fcl_transform(p.xa));
                ob.setTransform(fcl_transform(p.xb));
                fcl::DistanceRequestd req(true);
                fcl::DistanceResultd res;
                fcl::distance(&oa, &ob, req, res);
                sink += res.min_distance;
            });
            std::printf("%-14s %-10s %10.3f %8.2f %14.3g\n", name.c_str(), "fcl", tf, tf / ours,
                        off);
            if (meshes) {
                std::printf("%-14s %-10s %10s\n", name.c_str(), "bullet",
                            "n/a (no concave-concave distance)");
            } else {
                btVoronoiSimplexSolver simplex;
                btGjkEpaPenetrationDepthSolver epa;
                off = 0;
                auto bullet = [&](const DistPair &p) {
                    btGjkPairDetector gjk(&bt_a, &bt_b, &simplex, &epa);
                    btDiscreteCollisionDetectorInterface::ClosestPointInput in;
                    in.m_transformA = bt_transform(p.xa);
                    in.m_transformB = bt_transform(p.xb);
                    btPointCollector out;
                    gjk.getClosestPoints(in, out, nullptr);
                    return out.m_hasResult ? static_cast<double>(out.m_distance) : 0.0;
                };
                for (const DistPair &p : pairs)
                    off = std::max(off, off_interval(p, bullet(p)));
                const double tb = time_calls(pairs, calls, [&](const DistPair &p) {
                    sink += bullet(p);
                });
                std::printf("%-14s %-10s %10.3f %8.2f %14.3g\n", name.c_str(), "bullet", tb,
                            tb / ours, off);
            }
            if (sink == 42.0)
                std::printf(" ");
        }
    noctMeshDestroy(ma);
    noctMeshDestroy(mb);
    noctMeshDestroy(ba);
    noctMeshDestroy(bb);
    return ok;
}

// ---- the nearest object (--nearest) ------------------------------------------------

// FCL's broadphase distance: each candidate pair through fcl::distance, the
// best so far kept here and handed back as the manager's bound (so that it
// prunes the boxes farther than it), stopping at a contact.
struct FclNearest {
    fcl::CollisionObjectd *q;
    double best;
    long object;
};

bool fcl_nearest(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data, double &dist)
{
    FclNearest *c = static_cast<FclNearest *>(data);
    fcl::DistanceRequestd req;
    fcl::DistanceResultd res;
    fcl::distance(a, b, req, res);
    const double d = std::max(0.0, res.min_distance);
    fcl::CollisionObjectd *o = a == c->q ? b : a;
    const long i = static_cast<long>(reinterpret_cast<intptr_t>(o->getUserData()));
    if (d < c->best || (d == c->best && i < c->object)) {
        c->best = d;
        c->object = i;
    }
    dist = c->best;
    return c->best <= 0;
}

// Q random points and Q random boxes (cubes of side 0.75, turned at random)
// in the container of a gas scene as set up: the nearest object to each,
// libnoctree's noctWorldQueryNearest() against FCL's dynamic AABB tree's
// distance() with a distance callback (fcl::distance on each candidate,
// GJK), in one process, the same queries for both. Prints the time per
// query, their ratio, and how many answers agree: the same object, and
// the same distance within 1e-6 (FCL's GJK is approximate; a point
// inside several objects is at distance 0 from each, and the two may
// name different ones).
bool run_nearest(const char *spec, long q, const Options &o)
{
    bool gas;
    long size;
    if (!parse_scene(spec, &gas, &size) || !gas) {
        std::fprintf(stderr, "bench-peers: --nearest runs on gas scenes only: %s\n", spec);
        return false;
    }
    Scene s = make_scene(gas, size);
    noctError err;
    noctScene *sc;
    noctWorld *w = nullptr;
    if (noctSceneFamily(spec, &sc, &err) != NOCT_OK ||
        (noctSceneDef(sc)->N = o.N, noctSceneBuild(sc, &w, &err)) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: %s: %s\n", spec, err.message);
        return false;
    }
    noctSceneDestroy(sc);
    // the queries: a point, then a box, each at a random place and turn
    struct Query {
        noctTransform x;
        double r[9];
    };
    std::vector<Query> qs;
    uint64_t st = 11;
    const double pi = 3.141592653589793, half = 0.375;
    for (long i = 0; i < 2 * q; ++i) {
        Query k;
        for (int a = 0; a < 3; ++a)
            k.x.p[a] = s.lb * draw(st);
        const double u1 = draw(st), u2 = draw(st), u3 = draw(st);
        const double x = std::sqrt(1 - u1) * std::sin(2 * pi * u2);
        const double y = std::sqrt(1 - u1) * std::cos(2 * pi * u2);
        const double z = std::sqrt(u1) * std::sin(2 * pi * u3);
        const double ww = std::sqrt(u1) * std::cos(2 * pi * u3);
        k.x.q = {x, y, z, ww};
        if (noctQuatToMatrix(&k.x.q, k.r, &err) != NOCT_OK) {
            std::fprintf(stderr, "bench-peers: %s\n", err.message);
            return false;
        }
        qs.push_back(k);
    }
    const double halves[3] = {half, half, half};
    const noctQueryFilter all = noctDefaultQueryFilter();
    std::vector<long> ours(qs.size());
    std::vector<double> ours_d(qs.size());
    double t_ours[2] = {0, 0};
    for (size_t i = 0; i < qs.size(); ++i) {
        const bool box = i % 2 == 1;
        noctDistanceHit h;
        bool found;
        const double t = now();
        const noctStatus stt = noctWorldQueryNearest(w, nullptr, box ? halves : nullptr,
                                                     &qs[i].x, INFINITY, all, &h, &found, &err);
        t_ours[box] += now() - t;
        if (stt != NOCT_OK || !found) {
            std::fprintf(stderr, "bench-peers: %s: nearest: %s\n", spec,
                         stt != NOCT_OK ? err.message : "nothing found");
            noctWorldDestroy(w);
            return false;
        }
        ours[i] = static_cast<long>(h.id.index);
        ours_d[i] = h.result.distance;
    }
    noctWorldDestroy(w);
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> obj;
    std::vector<fcl::CollisionObjectd *> raw;
    for (size_t i = 0; i < s.body.size(); ++i) {
        const Body &b = s.body[i];
        auto shape = std::make_shared<fcl::Boxd>(2 * b.h[0], 2 * b.h[1], 2 * b.h[2]);
        fcl::Matrix3d rot;
        rot << b.r[0], b.r[1], b.r[2], b.r[3], b.r[4], b.r[5], b.r[6], b.r[7], b.r[8];
        obj.emplace_back(new fcl::CollisionObjectd(shape, rot,
                                                   fcl::Vector3d(b.c[0], b.c[1], b.c[2])));
        obj.back()->setUserData(reinterpret_cast<void *>(static_cast<intptr_t>(i)));
        raw.push_back(obj.back().get());
    }
    fcl::DynamicAABBTreeCollisionManagerd mgr;
    mgr.registerObjects(raw);
    mgr.setup();
    auto point = std::make_shared<fcl::Sphered>(0.0);
    auto cube = std::make_shared<fcl::Boxd>(2 * half, 2 * half, 2 * half);
    double t_fcl[2] = {0, 0};
    size_t same[2] = {0, 0}, close[2] = {0, 0};
    double worst[2] = {0, 0};
    for (size_t i = 0; i < qs.size(); ++i) {
        const bool box = i % 2 == 1;
        const double *r = qs[i].r;
        fcl::Matrix3d rot;
        rot << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
        fcl::CollisionObjectd qo(box ? std::static_pointer_cast<fcl::CollisionGeometryd>(cube)
                                     : std::static_pointer_cast<fcl::CollisionGeometryd>(point),
                                 rot, fcl::Vector3d(qs[i].x.p[0], qs[i].x.p[1], qs[i].x.p[2]));
        FclNearest c = {&qo, INFINITY, -1};
        const double t = now();
        mgr.distance(&qo, &c, fcl_nearest);
        t_fcl[box] += now() - t;
        same[box] += c.object == ours[i];
        const double diff = std::fabs(c.best - ours_d[i]);
        close[box] += diff <= 1e-6;
        worst[box] = std::max(worst[box], diff);
    }
    static const char *const kind[2] = {"point", "box"};
    for (int b = 0; b < 2; ++b) {
        const double n = static_cast<double>(q);
        std::printf("%-12s %-6s %8ld %12.2f %12.2f %8.2f %10zu %10zu %10.1e\n", spec, kind[b], q,
                    1e6 * t_ours[b] / n, 1e6 * t_fcl[b] / n, t_fcl[b] / t_ours[b], same[b],
                    close[b], worst[b]);
    }
    return true;
}

// ---- triangle soups (--soups) -----------------------------------------------------

// A soup: a mesh written as a triangle soup (every triangle its own three
// vertices, as STL files hold them), welded exactly and made a solid, and
// FCL's BVHModel<OBBRSS> of the same welded triangles.
struct Soup {
    std::string name;
    bool surface = false; // made by noctMeshCreateSurfaceFromData()
    noctMesh *mesh = nullptr;
    std::vector<double> v;  // welded vertices
    std::vector<uint32_t> t; // triangles
    std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl;
};

// With cap > 0: an open surface, the triangles with a corner above z = cap
// (before scaling) left out.
bool make_soup(const char *name, int n, int m, double scale, Soup &s, double cap = 0)
{
    std::vector<double> v;
    std::vector<uint32_t> t;
    bumpy_sphere(n, m, 0.3, v, t);
    std::vector<double> soup;
    std::vector<uint32_t> kept;
    for (size_t i = 0; i < t.size(); i += 3) {
        bool above = false;
        for (int c = 0; c < 3; ++c)
            above = above || v[3 * t[i + c] + 2] > cap;
        if (cap <= 0 || !above)
            kept.insert(kept.end(), {t[i], t[i + 1], t[i + 2]});
    }
    t = kept;
    s.surface = cap > 0;
    for (uint32_t i : t)
        for (int k = 0; k < 3; ++k)
            soup.push_back(v[3 * i + k] * scale);
    std::vector<uint32_t> sizes(t.size() / 3, 3), idx(t.size());
    for (size_t i = 0; i < idx.size(); ++i)
        idx[i] = static_cast<uint32_t>(i);
    noctMeshData *data = nullptr;
    noctMeshWeldReport weld;
    noctError err;
    s.name = name;
    if (noctMeshDataCreate(soup.data(), soup.size() / 3, sizes.data(), sizes.size(), idx.data(),
                           &data, &err) != NOCT_OK ||
        noctMeshDataWeld(data, 0, &weld, &err) != NOCT_OK ||
        (s.surface ? noctMeshCreateSurfaceFromData(data, &s.mesh, &err)
                   : noctMeshCreateFromData(data, &s.mesh, &err)) != NOCT_OK) {
        std::fprintf(stderr, "bench-peers: --soups: %s: %s\n", name, err.message);
        noctMeshDataDestroy(data);
        return false;
    }
    const double *wv = noctMeshDataVertices(data);
    const uint32_t *wi = noctMeshDataIndices(data);
    s.v.assign(wv, wv + 3 * noctMeshDataVertexCount(data));
    s.t.assign(wi, wi + 3 * noctMeshDataPolygonCount(data));
    noctMeshDataDestroy(data);
    if (!s.surface && s.v.size() != v.size()) {
        std::fprintf(stderr, "bench-peers: --soups: %s: welded to %zu vertices, not %zu\n", name,
                     s.v.size() / 3, v.size() / 3);
        return false;
    }
    std::vector<fcl::Vector3d> pts;
    std::vector<fcl::Triangle> tris;
    for (size_t i = 0; i < s.v.size(); i += 3)
        pts.emplace_back(s.v[i], s.v[i + 1], s.v[i + 2]);
    for (size_t i = 0; i < s.t.size(); i += 3)
        tris.emplace_back(s.t[i], s.t[i + 1], s.t[i + 2]);
    s.fcl = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    s.fcl->beginModel();
    s.fcl->addSubModel(pts, tris);
    s.fcl->endModel();
    return true;
}

// The test's own exact check, in rationals (GMP), on the vertices placed
// as transform.h says libnoctree places them: do two placed triangle sets
// meet (a triangle of each sharing a point), and is a point inside a
// closed triangle set (ray parity)?
using Pt = std::array<double, 3>;

int orient3(const Pt &a, const Pt &b, const Pt &c, const Pt &d)
{
    const mpq_class ax = mpq_class(a[0]) - d[0], ay = mpq_class(a[1]) - d[1],
                    az = mpq_class(a[2]) - d[2], bx = mpq_class(b[0]) - d[0],
                    by = mpq_class(b[1]) - d[1], bz = mpq_class(b[2]) - d[2],
                    cx = mpq_class(c[0]) - d[0], cy = mpq_class(c[1]) - d[1],
                    cz = mpq_class(c[2]) - d[2];
    const mpq_class det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) +
                          az * (bx * cy - by * cx);
    return sgn(det);
}

// Orientation of a, b, c projected on the plane of the axes other than k.
int orient2(const Pt &a, const Pt &b, const Pt &c, int k)
{
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const mpq_class det = (mpq_class(b[i]) - a[i]) * (mpq_class(c[j]) - a[j]) -
                          (mpq_class(b[j]) - a[j]) * (mpq_class(c[i]) - a[i]);
    return sgn(det);
}

bool between2(const Pt &p, const Pt &q, const Pt &r, int k) // r on segment pq, collinear
{
    for (int a = 0; a < 3; ++a)
        if (a != k && (r[a] < std::min(p[a], q[a]) || r[a] > std::max(p[a], q[a])))
            return false;
    return true;
}

bool segments2(const Pt &p, const Pt &q, const Pt &a, const Pt &b, int k)
{
    const int d1 = orient2(p, q, a, k), d2 = orient2(p, q, b, k), d3 = orient2(a, b, p, k),
              d4 = orient2(a, b, q, k);
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return (d1 == 0 && between2(p, q, a, k)) || (d2 == 0 && between2(p, q, b, k)) ||
           (d3 == 0 && between2(a, b, p, k)) || (d4 == 0 && between2(a, b, q, k));
}

bool in_triangle2(const Pt &p, const Pt &a, const Pt &b, const Pt &c, int k)
{
    const int o1 = orient2(a, b, p, k), o2 = orient2(b, c, p, k), o3 = orient2(c, a, p, k);
    return !((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0));
}

// The closed segment pq against the closed triangle abc (with an area).
bool segment_triangle(const Pt &p, const Pt &q, const Pt &a, const Pt &b, const Pt &c)
{
    const int s1 = orient3(a, b, c, p), s2 = orient3(a, b, c, q);
    if (s1 * s2 > 0)
        return false;
    if (s1 == 0 && s2 == 0) {
        // Coplanar: project along an axis the plane is not parallel to.
        int k = 0;
        for (; k < 3; ++k) {
            Pt up = a;
            up[k] += 1;
            if (orient3(a, b, c, up) != 0)
                break;
        }
        return in_triangle2(p, a, b, c, k) || in_triangle2(q, a, b, c, k) ||
               segments2(p, q, a, b, k) || segments2(p, q, b, c, k) || segments2(p, q, c, a, k);
    }
    const int o1 = orient3(p, q, a, b), o2 = orient3(p, q, b, c), o3 = orient3(p, q, c, a);
    return !((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0));
}

// Two closed triangles meet iff an edge of one meets the other.
bool triangles_meet(const Pt *x, const Pt *y)
{
    for (int e = 0; e < 3; ++e)
        if (segment_triangle(x[e], x[(e + 1) % 3], y[0], y[1], y[2]) ||
            segment_triangle(y[e], y[(e + 1) % 3], x[0], x[1], x[2]))
            return true;
    return false;
}

struct Placed {
    std::vector<Pt> v;
    std::vector<std::array<double, 6>> box; // each triangle's lo, hi
    const std::vector<uint32_t> *t;
    Pt lo, hi;
};

bool place(const Soup &s, const noctTransform &x, Placed &out)
{
    double R[9];
    if (noctQuatToMatrix(&x.q, R, nullptr) != NOCT_OK)
        return false;
    out.v.resize(s.v.size() / 3);
    out.t = &s.t;
    for (size_t i = 0; i < out.v.size(); ++i)
        for (int r = 0; r < 3; ++r) {
            const double *w = &s.v[3 * i];
            const double rot = (R[3 * r] * w[0] + R[3 * r + 1] * w[1]) + R[3 * r + 2] * w[2];
            out.v[i][r] = rot + x.p[r];
        }
    out.box.clear();
    out.lo = out.v[0];
    out.hi = out.v[0];
    for (size_t i = 0; i < s.t.size(); i += 3) {
        std::array<double, 6> b;
        for (int k = 0; k < 3; ++k) {
            b[k] = std::min({out.v[s.t[i]][k], out.v[s.t[i + 1]][k], out.v[s.t[i + 2]][k]});
            b[k + 3] = std::max({out.v[s.t[i]][k], out.v[s.t[i + 1]][k], out.v[s.t[i + 2]][k]});
            out.lo[k] = std::min(out.lo[k], b[k]);
            out.hi[k] = std::max(out.hi[k], b[k + 3]);
        }
        out.box.push_back(b);
    }
    return true;
}

bool surfaces_meet(const Placed &a, const Placed &b)
{
    for (size_t i = 0; i < a.box.size(); ++i)
        for (size_t j = 0; j < b.box.size(); ++j) {
            const auto &p = a.box[i], &q = b.box[j];
            if (p[0] > q[3] || q[0] > p[3] || p[1] > q[4] || q[1] > p[4] || p[2] > q[5] ||
                q[2] > p[5])
                continue;
            const Pt x[3] = {a.v[(*a.t)[3 * i]], a.v[(*a.t)[3 * i + 1]], a.v[(*a.t)[3 * i + 2]]};
            const Pt y[3] = {b.v[(*b.t)[3 * j]], b.v[(*b.t)[3 * j + 1]], b.v[(*b.t)[3 * j + 2]]};
            if (triangles_meet(x, y))
                return true;
        }
    return false;
}

// Is p inside the closed surface s (which p's set does not touch)? Ray
// parity along a random segment out of s's box; a ray through an edge or
// a vertex is drawn again.
bool inside(const Pt &p, const Placed &s, uint64_t &rng)
{
    for (;;) {
        Pt d, q;
        double len = 0;
        for (int k = 0; k < 3; ++k) {
            d[k] = 2 * draw(rng) - 1;
            len += d[k] * d[k];
        }
        const double reach = 4 * (std::fabs(s.hi[0] - s.lo[0]) + std::fabs(s.hi[1] - s.lo[1]) +
                                  std::fabs(s.hi[2] - s.lo[2]) + std::fabs(p[0] - s.lo[0]) +
                                  std::fabs(p[1] - s.lo[1]) + std::fabs(p[2] - s.lo[2]));
        for (int k = 0; k < 3; ++k)
            q[k] = p[k] + d[k] / std::sqrt(len) * reach;
        int crossings = 0;
        bool degenerate = false;
        for (size_t i = 0; i < s.box.size() && !degenerate; ++i) {
            const auto &b = s.box[i];
            bool apart = false;
            for (int k = 0; k < 3; ++k)
                apart = apart || std::max(p[k], q[k]) < b[k] || std::min(p[k], q[k]) > b[k + 3];
            if (apart)
                continue;
            const Pt &a = s.v[(*s.t)[3 * i]], &bb = s.v[(*s.t)[3 * i + 1]],
                     &c = s.v[(*s.t)[3 * i + 2]];
            const int s1 = orient3(a, bb, c, p), s2 = orient3(a, bb, c, q);
            if (s1 * s2 > 0)
                continue;
            const int o1 = orient3(p, q, a, bb), o2 = orient3(p, q, bb, c),
                      o3 = orient3(p, q, c, a);
            if (s1 == 0 || s2 == 0 || o1 == 0 || o2 == 0 || o3 == 0) {
                if ((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0))
                    degenerate = true;
                continue;
            }
            if ((o1 > 0) == (o2 > 0) && (o2 > 0) == (o3 > 0))
                ++crossings;
        }
        if (!degenerate)
            return crossings % 2 == 1;
    }
}

struct SoupPose {
    noctTransform xa, xb;
};

// noctree's answer and FCL's on every pose; each difference checked
// exactly. Returns false if a run failed or libnoctree's answer differs
// from the exact check.
bool run_soup_case(const Soup &a, const Soup &b, double spread, long poses, uint64_t &rng)
{
    std::vector<SoupPose> pose(static_cast<size_t>(poses));
    for (SoupPose &p : pose) {
        for (noctTransform *x : {&p.xa, &p.xb}) {
            double q[4], n;
            do {
                for (double &c : q)
                    c = 2 * draw(rng) - 1;
                n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            } while (n < 0.1 || n > 1);
            x->q = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
            for (double &c : x->p)
                c = 0;
        }
        for (double &c : p.xb.p)
            c = spread * (2 * draw(rng) - 1);
    }
    std::vector<char> ours(pose.size()), theirs(pose.size());
    bool ok = true;
    double best_ours = INFINITY, best_fcl = INFINITY;
    fcl::CollisionObjectd oa(a.fcl), ob(b.fcl);
    for (int round = 0; round < 3 && ok; ++round) {
        double t0 = now();
        for (size_t i = 0; i < pose.size(); ++i) {
            bool hit = false;
            noctError err;
            if (noctCollideTransformed(a.mesh, &pose[i].xa, b.mesh, &pose[i].xb,
                                       NOCT_ACCURACY_EXACT, &hit, nullptr, &err) != NOCT_OK) {
                std::fprintf(stderr, "bench-peers: --soups: %s\n", err.message);
                ok = false;
                break;
            }
            ours[i] = hit;
        }
        best_ours = std::min(best_ours, (now() - t0) / static_cast<double>(pose.size()) * 1e6);
        t0 = now();
        for (size_t i = 0; i < pose.size(); ++i) {
            oa.setTransform(fcl_transform(pose[i].xa));
            ob.setTransform(fcl_transform(pose[i].xb));
            fcl::CollisionRequestd req;
            fcl::CollisionResultd res;
            fcl::collide(&oa, &ob, req, res);
            theirs[i] = res.isCollision();
        }
        best_fcl = std::min(best_fcl, (now() - t0) / static_cast<double>(pose.size()) * 1e6);
    }
    if (!ok)
        return false;
    long hits = 0, differ = 0, fcl_missed_inside = 0, fcl_other = 0, ours_wrong = 0;
    const std::string name = a.name + " / " + b.name;
    for (size_t i = 0; i < pose.size(); ++i) {
        hits += ours[i];
        if (ours[i] == theirs[i])
            continue;
        ++differ;
        Placed pa, pb;
        if (!place(a, pose[i].xa, pa) || !place(b, pose[i].xb, pb))
            return false;
        // a surface encloses nothing: only a solid can hold the other
        const bool meet = surfaces_meet(pa, pb);
        const bool contained = !meet && ((!b.surface && inside(pa.v[0], pb, rng)) ||
                                         (!a.surface && inside(pb.v[0], pa, rng)));
        const bool exact = meet || contained;
        if (static_cast<bool>(ours[i]) != exact)
            ++ours_wrong;
        if (!theirs[i] && contained)
            ++fcl_missed_inside;
        else
            ++fcl_other;
        if (differ <= 5 || static_cast<bool>(ours[i]) != exact)
            std::printf("  %s pose %zu: libnoctree %s, FCL %s; exact: %s\n", name.c_str(), i,
                        ours[i] ? "meet" : "apart", theirs[i] ? "meet" : "apart",
                        meet ? "the surfaces meet" : contained ? "one solid inside the other"
                                                               : "apart");
    }
    std::printf("%-26s %6zu %6ld %10.2f %10.2f %8.2f %7ld %9ld %7ld %7ld\n", name.c_str(),
                pose.size(), hits, best_ours, best_fcl, best_fcl / best_ours, differ,
                fcl_missed_inside, fcl_other, ours_wrong);
    return ours_wrong == 0;
}

bool run_soups(long poses)
{
    std::printf("bench-peers --soups: libnoctree %s (efficient build) noctCollideTransformed() "
                "at the exact level\nagainst FCL %s fcl::collide() (BVHModel<OBBRSS>, first "
                "contact) on meshes read as\ntriangle soups and welded, %ld random turned poses "
                "each, best of 3 rounds; one thread.\nEvery verdict that differs is checked "
                "exactly (GMP) on the vertices as libnoctree places them.\n\n",
                NOCT_VERSION_STRING, FCL_VERSION, poses);
    Soup link, link_small, bay, open_bay;
    bool ok = make_soup("bumpy-960", 32, 16, 1, link) &&
              make_soup("bumpy-960 x0.5", 32, 16, 0.5, link_small) &&
              make_soup("bumpy-4992 x3", 64, 40, 3, bay) &&
              make_soup("open-4992 x3", 64, 40, 3, open_bay, 0.6);
    if (ok) {
        std::printf("%-26s %6s %6s %10s %10s %8s %7s %9s %7s %7s\n", "case", "poses", "meet",
                    "ours us", "fcl us", "x", "differ", "fcl:inside", "other", "ours bad");
        uint64_t rng = 2027;
        ok = run_soup_case(link, link, 2.6, poses, rng) &&
             run_soup_case(bay, link_small, 4.5, poses, rng) &&
             run_soup_case(open_bay, link_small, 4.5, poses, rng);
    }
    for (Soup *s : {&link, &link_small, &bay, &open_bay})
        noctMeshDestroy(s->mesh);
    return ok;
}

} // namespace

int main(int argc, char **argv)
{
    Options o;
    std::vector<const char *> scenes;
    bool use[NLIBS] = {true, false, true, true, false};
    bool quick = false, driven = false, disputed = false;
    long queries = 0, nearest = 0, distance_calls = 0, soup_poses = 0;
    const char *csv_path = nullptr;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        long v;
        const bool has = i + 1 < argc;
        if (std::strcmp(a, "--quick") == 0) {
            quick = true;
        } else if (std::strcmp(a, "--broadphase") == 0) {
            o.broadphase = true;
        } else if (std::strcmp(a, "--disputed") == 0) {
            disputed = true;
        } else if (std::strcmp(a, "--driven") == 0) {
            driven = true;
        } else if (std::strcmp(a, "--queries") == 0) {
            queries = 10000;
            if (has && parse_int(argv[i + 1], 1, 100000000, &v)) {
                queries = v;
                ++i;
            }
        } else if (std::strcmp(a, "--soups") == 0) {
            soup_poses = 10000;
            if (has && parse_int(argv[i + 1], 1, 100000000, &v))
                soup_poses = v, ++i;
        } else if (std::strcmp(a, "--distance") == 0) {
            distance_calls = 20000;
            if (has && parse_int(argv[i + 1], 1, 100000000, &v)) {
                distance_calls = v;
                ++i;
            }
        } else if (std::strcmp(a, "--nearest") == 0) {
            nearest = 1000;
            if (has && parse_int(argv[i + 1], 1, 100000000, &v))
                nearest = v, ++i;
        } else if (std::strcmp(a, "--help") == 0) {
            usage(stdout);
            return 0;
        } else if (std::strcmp(a, "--steps") == 0 && has && parse_int(argv[i + 1], 1, 100000, &v)) {
            o.steps = static_cast<int>(v);
            ++i;
        } else if (std::strcmp(a, "--repeats") == 0 && has && parse_int(argv[i + 1], 1, 100, &v)) {
            o.repeats = static_cast<int>(v);
            ++i;
        } else if (std::strcmp(a, "--N") == 0 && has &&
                   (std::strcmp(argv[i + 1], "auto") == 0 ||
                    parse_int(argv[i + 1], 1, 100000, &v))) {
            o.N = std::strcmp(argv[i + 1], "auto") == 0 ? NOCT_AUTO : static_cast<int>(v);
            ++i;
        } else if (std::strcmp(a, "--budget") == 0 && has && parse_int(argv[i + 1], 1, 86400, &v)) {
            o.budget = static_cast<double>(v);
            ++i;
        } else if (std::strcmp(a, "--csv") == 0 && has) {
            csv_path = argv[++i];
        } else if (std::strcmp(a, "--libs") == 0 && has) {
            std::string list = argv[++i];
            for (bool &u : use)
                u = false;
            size_t pos = 0;
            while (pos <= list.size()) {
                size_t comma = list.find(',', pos);
                std::string name = list.substr(pos, comma == std::string::npos ? comma : comma - pos);
                int found = -1;
                for (int l = 0; l < NLIBS; ++l)
                    if (name == LIBS[l])
                        found = l;
                if (found < 0) {
                    std::fprintf(stderr, "bench-peers: --libs: unknown library '%s'\n",
                                 name.c_str());
                    usage(stderr);
                    return 2;
                }
                use[found] = true;
                if (comma == std::string::npos)
                    break;
                pos = comma + 1;
            }
        } else if (a[0] != '-') {
            bool gas;
            long size;
            if (!parse_scene(a, &gas, &size))
                return 2;
            scenes.push_back(a);
        } else {
            std::fprintf(stderr, "bench-peers: bad option or value: %s\n", a);
            usage(stderr);
            return 2;
        }
    }
    if (disputed) {
        if (!o.broadphase || driven || quick || queries > 0) {
            std::fprintf(stderr, "bench-peers: --disputed goes with --broadphase only\n");
            usage(stderr);
            return 2;
        }
        if (scenes.empty())
            scenes = {"gas:100000"};
        bool all = true;
        for (const char *spec : scenes)
            all = run_disputed(spec, o) && all;
        return all ? 0 : 1;
    }
    if (soup_poses > 0)
        return run_soups(soup_poses) ? 0 : 1;
    if (distance_calls > 0)
        return run_distance(distance_calls) ? 0 : 1;
    const std::string n_name = o.N == NOCT_AUTO ? std::string("auto") : std::to_string(o.N);
    if (nearest > 0) {
        if (scenes.empty())
            scenes = {"gas:100000"};
        std::printf("bench-peers --nearest: the nearest object to %ld random points and %ld "
                    "random boxes (cubes of side 0.75, turned) on each gas scene as set up:\n"
                    "libnoctree %s (noctWorldQueryNearest(), efficient build, N = %s) against "
                    "FCL %s (dynamic AABB tree distance(), GJK); one thread\n",
                    nearest, nearest, NOCT_VERSION_STRING, n_name.c_str(), FCL_VERSION);
        std::printf("%-12s %-6s %8s %12s %12s %8s %10s %10s %10s\n", "scene", "query", "queries",
                    "ours us", "fcl us", "ratio", "same obj", "same dist", "max diff");
        bool all = true;
        for (const char *spec : scenes)
            all = run_nearest(spec, nearest, o) && all;
        return all ? 0 : 1;
    }
    if (queries > 0) {
        if (scenes.empty())
            scenes = {"gas:10000", "gas:100000"};
        std::printf("bench-peers --queries: libnoctree %s (efficient build, N = %s, exact) "
                    "against FCL %s (dynamic AABB tree) and Bullet %d.%02d (btDbvtBroadphase), "
                    "%ld queries of each kind on each scene as set up; one thread\n",
                    NOCT_VERSION_STRING, n_name.c_str(), FCL_VERSION, BT_BULLET_VERSION / 100,
                    BT_BULLET_VERSION % 100, queries);
        std::printf("%-12s %-12s %-16s %8s %12s %10s %10s\n", "scene", "library", "query",
                    "queries", "per second", "us each", "found");
        bool all = true;
        for (const char *spec : scenes)
            all = run_queries(spec, queries, o) && all;
        return all ? 0 : 1;
    }
    if (driven)
        use[DRIVEN] = true;
    if (o.broadphase && use[DRIVEN]) {
        std::fprintf(stderr, "bench-peers: --broadphase runs no world, so no "
                             "noct-driven (--driven)\n");
        usage(stderr);
        return 2;
    }
    if (quick) {
        o.repeats = 1;
        if (scenes.empty())
            scenes = {"planes:3", "gas:1000"};
    }
    if (scenes.empty())
        scenes = {"planes:10", "planes:100", "planes:300", "gas:10000", "gas:100000"};
    FILE *csv = nullptr;
    if (csv_path != nullptr) {
        csv = std::fopen(csv_path, "w");
        if (csv == nullptr) {
            std::fprintf(stderr, "bench-peers: %s: %s\n", csv_path, std::strerror(errno));
            return 2;
        }
        std::fputs("scene,objects,library,repeat,steps,median_s,p90_s,setup_s,begins,peak_kib\n",
                   csv);
    }
    if (o.broadphase)
        std::printf("bench-peers --broadphase: libnoctree %s's broadphase (efficient build, "
                    "N = %s) against\nFCL %s (dynamic AABB tree) and ODE %s (sweep and prune; "
                    "hash) on the same axis-aligned\nboxes: move, update, find the overlapping "
                    "pairs; no narrowphase; one thread\n",
                    NOCT_VERSION_STRING, n_name.c_str(), FCL_VERSION, NOCT_ODE_VERSION);
    else
        std::printf("bench-peers: libnoctree %s (efficient build, N = %s, exact) against FCL %s "
                    "(dynamic AABB tree)\nand ODE %s (sweep and prune; hash), each with its own "
                    "box-box test; one thread\n",
                    NOCT_VERSION_STRING, n_name.c_str(), FCL_VERSION, NOCT_ODE_VERSION);
    if (use[DRIVEN])
        std::printf("noct-driven: libnoctree's world without its motion effect, every object "
                    "moved by the program\nwith noctWorldSetTransform() each step, the response "
                    "from noctWorldBegan() (x: over the\nbuilt-in motion's time)\n");
    std::printf("per-step wall time of the whole step, %d steps: median over %d interleaved "
                "runs of each run's\nmedian (+-: half the range, %% of the median); x: this "
                "library's median over libnoctree's\n\n",
                o.steps, o.repeats);
    std::printf("%-11s %8s  %-11s %10s %6s %10s %9s %7s %8s %8s %7s\n", "scene", "objects",
                "library", "median ms", "+-", "p90 ms", "ns/obj", "setup s",
                o.broadphase ? "pairs" : "begins",
                "peak MiB", "x");
    bool all_ok = true;
    for (const char *spec : scenes) {
        std::vector<Result> res[NLIBS];
        std::vector<long> peak[NLIBS];
        for (int rep = 0; rep < o.repeats; ++rep)
            for (int l = 0; l < NLIBS; ++l) {
                if (!use[l])
                    continue;
                Result r;
                long pk;
                if (!run_child(spec, l, o, r, pk)) {
                    std::fprintf(stderr, "bench-peers: %s: %s failed\n", spec, LIBS[l]);
                    all_ok = false;
                    continue;
                }
                res[l].push_back(r);
                peak[l].push_back(pk);
                if (csv != nullptr)
                    std::fprintf(csv, "%s,%zu,%s,%d,%d,%.6g,%.6g,%.4g,%zu,%ld\n", spec,
                                 r.objects, LIBS[l], rep, r.steps, r.median, r.p90, r.setup,
                                 r.begins, pk);
            }
        bool gas;
        long size;
        parse_scene(spec, &gas, &size);
        size_t known = 0;
        const bool has_known = !o.broadphase && known_begins(gas, size, o.steps, &known);
        // Every run that did all its steps must find the same events.
        size_t first = SIZE_MAX;
        for (int l = 0; l < NLIBS; ++l)
            for (const Result &r : res[l])
                if (r.steps == o.steps) {
                    if (first == SIZE_MAX)
                        first = r.begins;
                    if (r.begins != first || (has_known && r.begins != known)) {
                        std::printf("%-11s %8zu  %-11s %s %zu, but %s %zu\n", spec,
                                    r.objects, LIBS[l],
                                    o.broadphase ? "overlapping pairs" : "contact begins",
                                    r.begins,
                                    has_known ? "noctree-families(7) says" : "another run found",
                                    has_known ? known : first);
                        all_ok = false;
                    }
                }
        double base = 0;
        for (int l = 0; l < NLIBS; ++l) {
            if (res[l].empty())
                continue;
            std::vector<double> med, p90, setup;
            long pk = 0;
            int steps = o.steps;
            for (size_t i = 0; i < res[l].size(); ++i) {
                med.push_back(res[l][i].median);
                p90.push_back(res[l][i].p90);
                setup.push_back(res[l][i].setup);
                pk = std::max(pk, peak[l][i]);
                steps = std::min(steps, res[l][i].steps);
            }
            const double m = median_of(med);
            const double lo = *std::min_element(med.begin(), med.end());
            const double hi = *std::max_element(med.begin(), med.end());
            if (l == 0)
                base = m;
            char x[16] = "-";
            if (l > 0 && base > 0)
                std::snprintf(x, sizeof x, "%.2f", m / base);
            const Result &r0 = res[l][0];
            std::printf("%-11s %8zu  %-11s %10.4g %5.0f%% %10.4g %9.0f %7.2f %8zu %8.1f %7s", spec,
                        r0.objects, LIBS[l], 1e3 * m, m > 0 ? 50 * (hi - lo) / m : 0.0,
                        1e3 * median_of(p90), 1e9 * m / static_cast<double>(r0.objects),
                        median_of(setup), r0.begins, static_cast<double>(pk) / 1024, x);
            if (steps < o.steps)
                std::printf("  (budget: first %d steps)", steps);
            std::putchar('\n');
        }
        // The driven world against the built-in motion: the same events in
        // every repeat where both did the same steps, and their times.
        if (!res[NOCTREE].empty() && !res[DRIVEN].empty()) {
            bool same = true;
            for (size_t i = 0; i < std::min(res[NOCTREE].size(), res[DRIVEN].size()); ++i)
                if (res[NOCTREE][i].steps == res[DRIVEN][i].steps &&
                    res[NOCTREE][i].begins != res[DRIVEN][i].begins)
                    same = false;
            std::vector<double> mb, md;
            for (const Result &r : res[NOCTREE])
                mb.push_back(r.median);
            for (const Result &r : res[DRIVEN])
                md.push_back(r.median);
            const double b = median_of(mb), d = median_of(md);
            std::printf("driven/built-in %s: %.4g ms / %.4g ms = %.2f; contact begins %zu and "
                        "%zu, %s\n",
                        spec, 1e3 * d, 1e3 * b, b > 0 ? d / b : 0.0, res[DRIVEN][0].begins,
                        res[NOCTREE][0].begins, same ? "the same" : "DIFFERENT");
            if (!same)
                all_ok = false;
        }
    }
    if (csv != nullptr)
        std::fclose(csv);
    return all_ok ? 0 : 1;
}
