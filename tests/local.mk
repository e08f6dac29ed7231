# SPDX-License-Identifier: MIT
# make check: the Check suites against both libraries, the export list and
# the in-lining check. make check-valgrind: the suites under valgrind.

# Each Check suite is built twice, against the defensive library and (its
# -efficient twin, with NOCT_EFFICIENT, so the accessors are inline)
# against the efficient one; check-predicates only against the first.
suites = tests/check-octree tests/check-octree-efficient \
	tests/check-neighbor tests/check-neighbor-efficient \
	tests/check-narrowphase tests/check-narrowphase-efficient \
	tests/check-predicates tests/check-world tests/check-world-efficient \
	tests/check-alloc tests/check-alloc-efficient \
	tests/check-zero-alloc tests/check-zero-alloc-efficient \
	tests/check-broadphase tests/check-broadphase-efficient \
	tests/check-objects tests/check-objects-efficient \
	tests/check-queries tests/check-queries-efficient \
	tests/check-tracks tests/check-tracks-efficient \
	tests/check-ignore tests/check-ignore-efficient \
	tests/check-near tests/check-near-efficient \
	tests/check-families tests/check-families-efficient \
	tests/check-readers tests/check-readers-efficient \
	tests/check-continuous tests/check-continuous-efficient \
	tests/check-swept tests/check-swept-efficient \
	tests/check-turning tests/check-turning-efficient \
	tests/check-contacts tests/check-contacts-efficient \
	tests/check-distance-world tests/check-distance-world-efficient \
	tests/check-meshio tests/check-meshio-efficient \
	tests/check-distance-paths tests/check-distance-paths-efficient \
	tests/check-distance tests/check-distance-efficient \
	tests/check-surface-paths tests/check-surface-paths-efficient \
	tests/check-surfaces tests/check-surfaces-efficient

# The suites' kit, built once per flavour: the RNG, the tree validation
# walk and mirror model, the L mesh (testutil), the ideal geometry of
# random rotated scenes (testgeom) and the short direction names. And the
# tests' allocator (testalloc: counts allocations and fails them on
# demand), for the four suites that replace malloc.
if HAVE_CHECK
check_PROGRAMS += $(suites)
TESTS += $(suites)
check_LTLIBRARIES = tests/libtestkit.la tests/libtestkit-efficient.la \
	tests/libtestalloc.la
endif
tests_libtestkit_la_SOURCES = tests/testutil.c tests/testutil.h tests/testgeom.c \
	tests/testgeom.h tests/short_names.c
tests_libtestkit_la_CFLAGS = $(check_cflags)
tests_libtestkit_efficient_la_SOURCES = $(tests_libtestkit_la_SOURCES)
tests_libtestkit_efficient_la_CPPFLAGS = $(efficient_cppflags)
tests_libtestkit_efficient_la_CFLAGS = $(check_cflags)
tests_libtestalloc_la_SOURCES = tests/testalloc.c tests/testalloc.h

check_cflags = $(AM_CFLAGS) $(CHECK_CFLAGS)
efficient_cppflags = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
check_ldadd = tests/libtestkit.la lib/libnoctree.la $(CHECK_LIBS)
efficient_ldadd = tests/libtestkit-efficient.la lib/libnoctree-efficient.la $(CHECK_LIBS)

# Per suite, what it tests; then its defensive build and its twin.

# check-octree: the octree ADT (octree.h), each operation's ensures clauses
# on real trees, random operation sequences against a mirror model.
tests_check_octree_SOURCES = tests/check_octree.c
tests_check_octree_CFLAGS = $(check_cflags)
tests_check_octree_LDADD = $(check_ldadd)
tests_check_octree_efficient_SOURCES = tests/check_octree.c
tests_check_octree_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_octree_efficient_CFLAGS = $(check_cflags)
tests_check_octree_efficient_LDADD = $(efficient_ldadd)

# check-neighbor: neighbor finding (neighbor.h) against the geometry of
# the cells and against walks of the tree.
tests_check_neighbor_SOURCES = tests/check_neighbor.c
tests_check_neighbor_CFLAGS = $(check_cflags)
tests_check_neighbor_LDADD = $(check_ldadd)
tests_check_neighbor_efficient_SOURCES = tests/check_neighbor.c
tests_check_neighbor_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_neighbor_efficient_CFLAGS = $(check_cflags)
tests_check_neighbor_efficient_LDADD = $(efficient_ldadd)

# check-narrowphase: meshes and the narrowphase (mesh.h, narrowphase.h) on
# hard cases of known answer and against exact and brute-force oracles.
tests_check_narrowphase_SOURCES = tests/check_narrowphase.c
tests_check_narrowphase_CFLAGS = $(check_cflags)
tests_check_narrowphase_LDADD = $(check_ldadd)
tests_check_narrowphase_efficient_SOURCES = tests/check_narrowphase.c
tests_check_narrowphase_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_narrowphase_efficient_CFLAGS = $(check_cflags)
tests_check_narrowphase_efficient_LDADD = $(efficient_ldadd)

# check-swept: continuous detection (noctCollideSwept(), narrowphase.h)
# against the test's own oracle in GMP rationals: every feature pair's
# first contact as a tiny linear program, the start and end poses by
# exact edge-triangle tests and ray parity.
tests_check_swept_SOURCES = tests/check_swept.c tests/testgmp.h
tests_check_swept_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_swept_LDADD = $(check_ldadd) $(GMP_LIBS)
tests_check_swept_efficient_SOURCES = tests/check_swept.c tests/testgmp.h
tests_check_swept_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_swept_efficient_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_swept_efficient_LDADD = $(efficient_ldadd) $(GMP_LIBS)

# check-surfaces: surfaces (noctMeshCreateSurface(), mesh.h) in every
# collision level, noctDistance(), the world and the readers, against the
# test's own exact triangle-triangle and point-in-solid oracle in GMP
# rationals on soups, open boxes, Moebius strips, fans and touching cases.
tests_check_surfaces_SOURCES = tests/check_surfaces.c tests/testgmp.h
tests_check_surfaces_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_surfaces_LDADD = $(check_ldadd) $(GMP_LIBS)
tests_check_surfaces_efficient_SOURCES = tests/check_surfaces.c tests/testgmp.h
tests_check_surfaces_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_surfaces_efficient_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_surfaces_efficient_LDADD = $(efficient_ldadd) $(GMP_LIBS)

# check-distance: noctDistance() (narrowphase.h) against the test's own
# oracle in GMP rationals: the exact squared distance between every pair of
# placed triangles (vertex-triangle and edge-edge, edges crossing
# triangles), the exact level's verdict for meeting solids.
tests_check_distance_SOURCES = tests/check_distance.c tests/testgmp.h
tests_check_distance_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_distance_LDADD = $(check_ldadd) $(GMP_LIBS)
tests_check_distance_efficient_SOURCES = tests/check_distance.c tests/testgmp.h
tests_check_distance_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_distance_efficient_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_distance_efficient_LDADD = $(efficient_ldadd) $(GMP_LIBS)

# check-predicates: the private exact predicates, through a test-only build
# of lib/predicates.c, against integer and GMP arithmetic (no twin).
tests_check_predicates_SOURCES = tests/check_predicates.c lib/predicates.c \
	lib/predicates.h
tests_check_predicates_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_predicates_LDADD = $(check_ldadd) $(GMP_LIBS)

# check-world: the collision world (world.h) against the planes scenes'
# closed-form event counts, brute force, and across N and maintenance.
tests_check_world_SOURCES = tests/check_world.c
tests_check_world_CFLAGS = $(check_cflags)
tests_check_world_LDADD = $(check_ldadd)
tests_check_world_efficient_SOURCES = tests/check_world.c
tests_check_world_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_world_efficient_CFLAGS = $(check_cflags)
tests_check_world_efficient_LDADD = $(efficient_ldadd)

# check-alloc: every allocation of a workload fails in turn, and nothing
# aborts or leaks (replaces malloc, so it exits 77, SKIP, under
# AddressSanitizer or valgrind).
tests_check_alloc_SOURCES = tests/check_alloc.c
tests_check_alloc_CFLAGS = $(check_cflags)
tests_check_alloc_LDADD = tests/libtestalloc.la $(check_ldadd)
tests_check_alloc_efficient_SOURCES = tests/check_alloc.c
tests_check_alloc_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_alloc_efficient_CFLAGS = $(check_cflags)
tests_check_alloc_efficient_LDADD = tests/libtestalloc.la $(efficient_ldadd)

# check-objects: a world that programs drive (world.h, transform.h):
# quaternions, rotated scenes and object kinds against the test's model.
tests_check_objects_SOURCES = tests/check_objects.c
tests_check_objects_CFLAGS = $(check_cflags)
tests_check_objects_LDADD = $(check_ldadd)
tests_check_objects_efficient_SOURCES = tests/check_objects.c
tests_check_objects_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_objects_efficient_CFLAGS = $(check_cflags)
tests_check_objects_efficient_LDADD = $(efficient_ldadd)

# check-queries: the world's queries (query.h) against a brute force over
# the ideal geometry (testgeom), also from several threads.
tests_check_queries_SOURCES = tests/check_queries.c
tests_check_queries_CFLAGS = $(check_cflags) -pthread
tests_check_queries_LDADD = $(check_ldadd) -lpthread
tests_check_queries_efficient_SOURCES = tests/check_queries.c
tests_check_queries_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_queries_efficient_CFLAGS = $(check_cflags) -pthread
tests_check_queries_efficient_LDADD = $(efficient_ldadd) -lpthread

# check-tracks: tracks (NOCT_EFFECT_TRACK) against the test's own
# interpolation, and the events of worlds that follow them.
tests_check_tracks_SOURCES = tests/check_tracks.c
tests_check_tracks_CFLAGS = $(check_cflags)
tests_check_tracks_LDADD = $(check_ldadd)
tests_check_tracks_efficient_SOURCES = tests/check_tracks.c
tests_check_tracks_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_tracks_efficient_CFLAGS = $(check_cflags)
tests_check_tracks_efficient_LDADD = $(efficient_ldadd)

# check-ignore: ignored pairs, and the pairs touching at the start against
# a brute force of the narrowphase and of the boxes; scene files' ignore
# lines.
tests_check_ignore_SOURCES = tests/check_ignore.c
tests_check_ignore_CFLAGS = $(check_cflags)
tests_check_ignore_LDADD = $(check_ldadd)
tests_check_ignore_efficient_SOURCES = tests/check_ignore.c
tests_check_ignore_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_ignore_efficient_CFLAGS = $(check_cflags)
tests_check_ignore_efficient_LDADD = $(efficient_ldadd)

# check-near: the margin and the near queries against the test's own
# distances between the ideal solids (testgeom).
tests_check_near_SOURCES = tests/check_near.c
tests_check_near_CFLAGS = $(check_cflags)
tests_check_near_LDADD = $(check_ldadd)
tests_check_near_efficient_SOURCES = tests/check_near.c
tests_check_near_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_near_efficient_CFLAGS = $(check_cflags)
tests_check_near_efficient_LDADD = $(efficient_ldadd)

# check-families: the scene families arms:K and keyframes:N against the
# test's own long double geometry (forward kinematics, interpolation,
# oriented boxes).
tests_check_families_SOURCES = tests/check_families.c
tests_check_families_CFLAGS = $(check_cflags)
tests_check_families_LDADD = $(check_ldadd)
tests_check_families_efficient_SOURCES = tests/check_families.c
tests_check_families_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_families_efficient_CFLAGS = $(check_cflags)
tests_check_families_efficient_LDADD = $(efficient_ldadd)

# check-turning: the conservative level for turning motions
# (noctCollideSweptTransformed(), continuous worlds whose objects turn)
# against the test's own slerp, dense exact sampling and long double
# distances.
tests_check_turning_SOURCES = tests/check_turning.c
tests_check_turning_CFLAGS = $(check_cflags)
tests_check_turning_LDADD = $(check_ldadd)
tests_check_turning_efficient_SOURCES = tests/check_turning.c
tests_check_turning_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_turning_efficient_CFLAGS = $(check_cflags)
tests_check_turning_efficient_LDADD = $(efficient_ldadd)

# check-broadphase: the broadphase on its own (broadphase.h) against an
# all-pairs test of random boxes, with its queries and filters.
tests_check_broadphase_SOURCES = tests/check_broadphase.c
tests_check_broadphase_CFLAGS = $(check_cflags)
tests_check_broadphase_LDADD = $(check_ldadd)
tests_check_broadphase_efficient_SOURCES = tests/check_broadphase.c
tests_check_broadphase_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_broadphase_efficient_CFLAGS = $(check_cflags)
tests_check_broadphase_efficient_LDADD = $(efficient_ldadd)

# check-zero-alloc: no allocation in the step once sizes settle (counts
# them with the tests' allocator, so it skips under AddressSanitizer and
# valgrind).
tests_check_zero_alloc_SOURCES = tests/check_zero_alloc.c
tests_check_zero_alloc_CFLAGS = $(check_cflags)
tests_check_zero_alloc_LDADD = tests/libtestalloc.la $(check_ldadd)
tests_check_zero_alloc_efficient_SOURCES = tests/check_zero_alloc.c
tests_check_zero_alloc_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_zero_alloc_efficient_CFLAGS = $(check_cflags)
tests_check_zero_alloc_efficient_LDADD = tests/libtestalloc.la $(efficient_ldadd)

# check-readers: the scene, OFF and OBJ readers on NUL bytes, read errors,
# read-time checks, and allocations failing while reading (the tests'
# allocator; those tests skip, saying so, where it is not in force).
tests_check_readers_SOURCES = tests/check_readers.c
tests_check_readers_CFLAGS = $(check_cflags)
tests_check_readers_LDADD = tests/libtestalloc.la $(check_ldadd)
tests_check_readers_efficient_SOURCES = tests/check_readers.c
tests_check_readers_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_readers_efficient_CFLAGS = $(check_cflags)
tests_check_readers_efficient_LDADD = tests/libtestalloc.la $(efficient_ldadd)

# check-meshio: mesh files and mesh data (mesh.h): soups of the test's
# own closed meshes in every format read back as the same solid; welds,
# malformed files, inspection and repair on counted cases; glTF through
# assimp in builds with it.
if HAVE_ASSIMP
meshio_cppflags = -DNOCT_TEST_ASSIMP=1 $(ASSIMP_CFLAGS)
meshio_libs = $(ASSIMP_LIBS)
endif
tests_check_meshio_SOURCES = tests/check_meshio.c
tests_check_meshio_CPPFLAGS = $(AM_CPPFLAGS) $(meshio_cppflags)
tests_check_meshio_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_meshio_LDADD = $(check_ldadd) $(GMP_LIBS) $(meshio_libs)
tests_check_meshio_efficient_SOURCES = tests/check_meshio.c
tests_check_meshio_efficient_CPPFLAGS = $(efficient_cppflags) $(meshio_cppflags)
tests_check_meshio_efficient_CFLAGS = $(check_cflags) $(GMP_CFLAGS)
tests_check_meshio_efficient_LDADD = $(efficient_ldadd) $(GMP_LIBS) $(meshio_libs)

# check-continuous: the world's continuous level against the all-pairs
# brute force of noctCollideSwept() on random worlds (fast movers,
# teleports, tracks, churn), tunnelling cases of known time, the exact
# level's lists without motion, and allocations failing in its steps (the
# tests' allocator; that test skips, saying so, where it is not in force).
tests_check_continuous_SOURCES = tests/check_continuous.c
tests_check_continuous_CFLAGS = $(check_cflags)
tests_check_continuous_LDADD = tests/libtestalloc.la $(check_ldadd)
tests_check_continuous_efficient_SOURCES = tests/check_continuous.c
tests_check_continuous_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_continuous_efficient_CFLAGS = $(check_cflags)
tests_check_continuous_efficient_LDADD = tests/libtestalloc.la $(efficient_ldadd)

# check-contacts: the contacts (noctCollideContact(), noctWorldContacts())
# against closed forms (boxes face on face, edge across edge, a corner in a
# face, containment), a brute-force minimum translation of convex meshes,
# the points' tolerance in both solids or on both boundaries, and the
# world's contacts against the pairwise calls.
tests_check_contacts_SOURCES = tests/check_contacts.c
tests_check_contacts_CFLAGS = $(check_cflags)
tests_check_contacts_LDADD = $(check_ldadd)
tests_check_contacts_efficient_SOURCES = tests/check_contacts.c
tests_check_contacts_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_contacts_efficient_CFLAGS = $(check_cflags)
tests_check_contacts_efficient_LDADD = $(efficient_ldadd)

# check-distance-world: the world's distance queries (noctWorldDistance(),
# noctWorldQueryNearest(), noctWorldQueryWithin(), noctWorldNearDistances())
# against brute forces over every object: noctDistance() on the test's
# meshes, and the ideal solids of random rotated scenes.
tests_check_distance_world_SOURCES = tests/check_distance_world.c
tests_check_distance_world_CFLAGS = $(check_cflags)
tests_check_distance_world_LDADD = $(check_ldadd)
tests_check_distance_world_efficient_SOURCES = tests/check_distance_world.c
tests_check_distance_world_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_distance_world_efficient_CFLAGS = $(check_cflags)
tests_check_distance_world_efficient_LDADD = $(efficient_ldadd)

# check-distance-paths: noctDistance()'s fast paths: the convex path
# (GJK, proved by its direction) against the general path on the same
# solid, the general search against a brute force over every triangle
# pair, at sizes 1e-100 to 1e98 and offsets to 2^40, swapped arguments bit
# for bit, max_distance's beyond, and touching solids' exact 0.
tests_check_distance_paths_SOURCES = tests/check_distance_paths.c
tests_check_distance_paths_CFLAGS = $(check_cflags)
tests_check_distance_paths_LDADD = $(check_ldadd)
tests_check_distance_paths_efficient_SOURCES = tests/check_distance_paths.c
tests_check_distance_paths_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_distance_paths_efficient_CFLAGS = $(check_cflags)
tests_check_distance_paths_efficient_LDADD = $(efficient_ldadd)

# check-surface-paths: surfaces (noctMeshCreateSurface()) through every
# path: open and closed-surface boxes against solids (containment), random
# soups at dyadic coordinates against the test's own integer
# separating-axis decision, the levels conservative, a world against the
# pairwise call, distances against a brute force, sweeps against sampled
# exact tests, contacts, rays, point queries, and the errors.
tests_check_surface_paths_SOURCES = tests/check_surface_paths.c
tests_check_surface_paths_CFLAGS = $(check_cflags)
tests_check_surface_paths_LDADD = $(check_ldadd)
tests_check_surface_paths_efficient_SOURCES = tests/check_surface_paths.c
tests_check_surface_paths_efficient_CPPFLAGS = $(efficient_cppflags)
tests_check_surface_paths_efficient_CFLAGS = $(check_cflags)
tests_check_surface_paths_efficient_LDADD = $(efficient_ldadd)

# tests/manpages.sh: the man-page lint (tests/manlint.sh) on pages made
# to fail it and on the pages, references between pages, and the
# installed examples the pages name.
TESTS += tests/exports.sh tests/inline.sh tests/headers.sh tests/sim.sh tests/tools.sh \
	tests/examples.sh tests/manpages.sh
EXTRA_DIST += tests/exports.sh tests/inline.sh tests/headers.sh tests/sim.sh tests/tools.sh \
	tests/examples.sh tests/manpages.sh \
	tests/lib.sh \
	tests/inline-client.c

# The libFuzzer targets need clang: tests/fuzz/run.sh builds and runs them
# (CI runs it briefly); make and make check leave them alone. Listed file
# by file (a folder here would also take a build tree's tests/fuzz/).
EXTRA_DIST += tests/fuzz/README.md tests/fuzz/run.sh tests/fuzz/fuzz.h \
	tests/fuzz/fuzz_mesh.h tests/fuzz/fuzz_scene.c tests/fuzz/fuzz_off.c \
	tests/fuzz/fuzz_obj.c tests/fuzz/fuzz_stl.c tests/fuzz/fuzz_ply.c \
	tests/fuzz/fuzz_narrowphase.c \
	tests/fuzz/scene.dict tests/fuzz/off.dict tests/fuzz/obj.dict \
	tests/fuzz/stl.dict tests/fuzz/ply.dict \
	tests/fuzz/corpus/scene/coincident.scene \
	tests/fuzz/corpus/scene/every-statement.scene \
	tests/fuzz/corpus/scene/turn-ignore.scene \
	tests/fuzz/corpus/scene/two-cubes.scene \
	tests/fuzz/corpus/scene/walls-late.scene \
	tests/fuzz/corpus/off/cube.off tests/fuzz/corpus/off/dented.off \
	tests/fuzz/corpus/off/tet.off \
	tests/fuzz/corpus/obj/cube.obj tests/fuzz/corpus/obj/tet.obj \
	tests/fuzz/corpus/stl/cube.stl tests/fuzz/corpus/stl/cube-binary.stl \
	tests/fuzz/corpus/ply/cube.ply tests/fuzz/corpus/ply/cube-be.ply \
	tests/fuzz/corpus/narrowphase/boxes-touching \
	tests/fuzz/corpus/narrowphase/dent-vs-tet \
	tests/fuzz/corpus/narrowphase/flattened-numeric \
	tests/fuzz/corpus/narrowphase/off-vs-box \
	tests/fuzz/corpus/narrowphase/oriented-perm \
	tests/fuzz/corpus/narrowphase/raw-huge \
	tests/fuzz/corpus/narrowphase/tet-vs-rotated

# The peer benchmark's event counts against noctree-families(7)'s known answers, when it is built.
if HAVE_PEERS
TESTS += tests/peers.sh
endif
EXTRA_DIST += tests/peers.sh tests/manlint.sh tests/valgrind-suite.sh

AM_TESTS_ENVIRONMENT = \
	CC='$(CC)'; NM='$(NM)'; srcdir='$(srcdir)/tests'; \
	top_srcdir='$(top_srcdir)'; top_builddir='$(top_builddir)'; \
	export CC NM srcdir top_srcdir top_builddir;

# Valgrind runs the suites in one process (no fork), so the death tests,
# which abort by design, are left out by their tag; so are the "slow" test
# cases (whole benchmark scenes), which the other builds run. check-alloc
# and check-zero-alloc replace malloc (testalloc.c), which valgrind does
# too: they would only skip (exit 77). Of the efficient twins, only those
# whose code differs from the defensive suites' beyond the requires
# clauses run (check-octree-efficient and check-neighbor-efficient: the
# octree's accessors in-lined); the others are the same code without its
# asserts, which the sanitizer build runs in both builds (make
# check-valgrind VALGRIND_TWINS=all runs every twin too).
# The suites run side by side, VALGRIND_JOBS at a time (default: the
# processors), each by tests/valgrind-suite.sh (which also makes the
# heaviest random loops run fewer rounds: NOCT_TEST_ROUNDS_DIVISOR), the
# slowest ones first (valgrind_first, slowest first), so that the last
# suites to start are short and the lanes end together.
VALGRIND = valgrind
VALGRIND_JOBS = `nproc 2>/dev/null || echo 2`
VALGRIND_TWINS = inlined
valgrind_first = tests/check-distance tests/check-distance-efficient \
	tests/check-swept tests/check-swept-efficient \
	tests/check-surfaces tests/check-surfaces-efficient \
	tests/check-near tests/check-near-efficient \
	tests/check-neighbor-efficient tests/check-neighbor \
	tests/check-predicates \
	tests/check-world tests/check-world-efficient \
	tests/check-distance-paths tests/check-distance-paths-efficient \
	tests/check-distance-world tests/check-distance-world-efficient \
	tests/check-narrowphase tests/check-narrowphase-efficient
check-valgrind: $(check_PROGRAMS)
	@{ for t in $(valgrind_first); do echo $$t$(EXEEXT); done; \
	  for t in $(check_PROGRAMS); do \
	    case " $(valgrind_first) " in *" $${t%$(EXEEXT)} "*) continue ;; esac; \
	    case $$t in tests/check-alloc*|tests/check-zero-alloc*) ;; *) echo $$t ;; esac; \
	  done; } | if test '$(VALGRIND_TWINS)' = all; then cat; else \
	    $(AWK) '!/-efficient/ || /check-(octree|neighbor)-efficient/'; fi | \
	  xargs -P $(VALGRIND_JOBS) -n 1 \
	  $(SHELL) $(srcdir)/tests/valgrind-suite.sh '$(LIBTOOL)' '$(VALGRIND)'
.PHONY: check-valgrind

# Run from make installcheck (and so from make distcheck) after make install:
# build the installed examples with their own Makefile against the
# installed copy through pkg-config, in both flavours, run them and check
# their output (tests/examples.sh, keyframe-check against the installed
# noctree-sim), that every installed section 3 page that points at
# another (.so) points at one installed, and the installed libraries'
# exports.
installcheck-local:
	@set -e; pcdir='$(DESTDIR)$(pkgconfigdir)'; \
	tmp=`mktemp -d`; trap 'rm -rf "$$tmp"' EXIT; \
	for mod in noctree noctree-efficient; do \
	  echo "make -C examples PKG=$$mod (installed: $(examplesdir))"; \
	  rm -rf "$$tmp/$$mod" && cp -R '$(DESTDIR)$(examplesdir)' "$$tmp/$$mod"; \
	  PKG_CONFIG_PATH="$$pcdir" PKG_CONFIG_SYSROOT_DIR='$(DESTDIR)' \
	    $(MAKE) -s -C "$$tmp/$$mod" CC='$(CC)' PKG=$$mod \
	      CFLAGS='-std=c11 -O2 -Wall -Wextra -Werror'; \
	  LD_LIBRARY_PATH='$(DESTDIR)$(libdir)' EXAMPLES="$$tmp/$$mod" \
	    EXAMPLE_SCENES="$$tmp/$$mod" TOOL_SCENES='$(DESTDIR)$(examplescenesdir)' \
	    NOCTREE_SIM='$(DESTDIR)$(bindir)/noctree-sim' srcdir='$(srcdir)/tests' \
	    top_srcdir='$(top_srcdir)' top_builddir='$(top_builddir)' \
	    $(SHELL) $(srcdir)/tests/examples.sh; \
	done; \
	if test -d '$(DESTDIR)$(mandir)/man3'; then \
	  cd '$(DESTDIR)$(mandir)/man3' && for f in *.3; do \
	    test -f "$$f" || continue; \
	    t=`sed -n '1s|^\.so man3/||p' "$$f"`; \
	    if test -n "$$t" && test ! -f "$$t"; then \
	      echo "installed $$f points at $$t, not installed"; exit 1; fi; \
	  done; cd '$(abs_builddir)'; \
	fi; \
	NM='$(NM)' top_srcdir='$(top_srcdir)' top_builddir='$(top_builddir)' \
	  $(SHELL) $(srcdir)/tests/exports.sh '$(DESTDIR)$(libdir)'
