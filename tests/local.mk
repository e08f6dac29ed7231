# SPDX-License-Identifier: MIT
# make check: the Check suites against both libraries, the export list and
# the in-lining check. make check-valgrind: the suites under valgrind.

test_common = tests/testutil.c tests/testutil.h tests/short_names.c

if HAVE_CHECK
check_PROGRAMS += tests/check-octree tests/check-octree-efficient \
	tests/check-neighbor tests/check-neighbor-efficient \
	tests/check-narrowphase tests/check-narrowphase-efficient \
	tests/check-predicates tests/check-world tests/check-world-efficient \
	tests/check-alloc tests/check-alloc-efficient \
	tests/check-zero-alloc tests/check-zero-alloc-efficient \
	tests/check-broadphase tests/check-broadphase-efficient \
	tests/check-objects tests/check-objects-efficient \
	tests/check-queries tests/check-queries-efficient \
	tests/check-tracks tests/check-tracks-efficient \
	tests/check-near tests/check-near-efficient \
	tests/check-families tests/check-families-efficient \
	tests/check-readers tests/check-readers-efficient
TESTS += tests/check-octree tests/check-octree-efficient \
	tests/check-neighbor tests/check-neighbor-efficient \
	tests/check-narrowphase tests/check-narrowphase-efficient \
	tests/check-predicates tests/check-world tests/check-world-efficient \
	tests/check-alloc tests/check-alloc-efficient \
	tests/check-zero-alloc tests/check-zero-alloc-efficient \
	tests/check-broadphase tests/check-broadphase-efficient \
	tests/check-objects tests/check-objects-efficient \
	tests/check-queries tests/check-queries-efficient \
	tests/check-tracks tests/check-tracks-efficient \
	tests/check-near tests/check-near-efficient \
	tests/check-families tests/check-families-efficient \
	tests/check-readers tests/check-readers-efficient
endif

tests_check_octree_SOURCES = tests/check_octree.c $(test_common)
tests_check_octree_CFLAGS = $(AM_CFLAGS) $(CHECK_CFLAGS)
tests_check_octree_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_octree_efficient_SOURCES = $(tests_check_octree_SOURCES)
tests_check_octree_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_octree_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_octree_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

tests_check_neighbor_SOURCES = tests/check_neighbor.c $(test_common)
tests_check_neighbor_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_neighbor_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_neighbor_efficient_SOURCES = $(tests_check_neighbor_SOURCES)
tests_check_neighbor_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_neighbor_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_neighbor_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

tests_check_narrowphase_SOURCES = tests/check_narrowphase.c $(test_common)
tests_check_narrowphase_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_narrowphase_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_narrowphase_efficient_SOURCES = $(tests_check_narrowphase_SOURCES)
tests_check_narrowphase_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_narrowphase_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_narrowphase_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

# The private predicates, tested through a test-only build of their source.
tests_check_predicates_SOURCES = tests/check_predicates.c lib/predicates.c \
	lib/predicates.h $(test_common)
tests_check_predicates_CFLAGS = $(tests_check_octree_CFLAGS) $(GMP_CFLAGS)
tests_check_predicates_LDADD = lib/libnoctree.la $(GMP_LIBS) $(CHECK_LIBS)

tests_check_world_SOURCES = tests/check_world.c $(test_common)
tests_check_world_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_world_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_world_efficient_SOURCES = $(tests_check_world_SOURCES)
tests_check_world_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_world_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_world_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

# Every allocation of a workload fails in turn: the program replaces malloc
# (so it exits 77, SKIP, under AddressSanitizer or valgrind).
tests_check_alloc_SOURCES = tests/check_alloc.c tests/testalloc.c tests/testalloc.h \
	$(test_common)
tests_check_alloc_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_alloc_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_alloc_efficient_SOURCES = $(tests_check_alloc_SOURCES)
tests_check_alloc_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_alloc_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_alloc_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

tests_check_objects_SOURCES = tests/check_objects.c $(test_common)
tests_check_objects_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_objects_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_objects_efficient_SOURCES = $(tests_check_objects_SOURCES)
tests_check_objects_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_objects_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_objects_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

tests_check_queries_SOURCES = tests/check_queries.c tests/testgeom.c tests/testgeom.h \
	$(test_common)
tests_check_queries_CFLAGS = $(tests_check_octree_CFLAGS) -pthread
tests_check_queries_LDADD = lib/libnoctree.la $(CHECK_LIBS) -lpthread

tests_check_queries_efficient_SOURCES = $(tests_check_queries_SOURCES)
tests_check_queries_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_queries_efficient_CFLAGS = $(tests_check_octree_CFLAGS) -pthread
tests_check_queries_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS) -lpthread

tests_check_tracks_SOURCES = tests/check_tracks.c $(test_common)
tests_check_tracks_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_tracks_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_tracks_efficient_SOURCES = $(tests_check_tracks_SOURCES)
tests_check_tracks_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_tracks_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_tracks_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

tests_check_near_SOURCES = tests/check_near.c tests/testgeom.c tests/testgeom.h \
	$(test_common)
tests_check_near_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_near_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_near_efficient_SOURCES = $(tests_check_near_SOURCES)
tests_check_near_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_near_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_near_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

# The scene families arms:K and keyframes:N against the test's own long
# double geometry (forward kinematics, interpolation, oriented boxes).
tests_check_families_SOURCES = tests/check_families.c $(test_common)
tests_check_families_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_families_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_families_efficient_SOURCES = $(tests_check_families_SOURCES)
tests_check_families_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_families_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_families_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

tests_check_broadphase_SOURCES = tests/check_broadphase.c $(test_common)
tests_check_broadphase_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_broadphase_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_broadphase_efficient_SOURCES = $(tests_check_broadphase_SOURCES)
tests_check_broadphase_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_broadphase_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_broadphase_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

# No allocation in the step once sizes settle: counts them (an
# interposed malloc, so it skips under AddressSanitizer and valgrind).
tests_check_zero_alloc_SOURCES = tests/check_zero_alloc.c tests/testalloc.c tests/testalloc.h \
	$(test_common)
tests_check_zero_alloc_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_zero_alloc_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_zero_alloc_efficient_SOURCES = $(tests_check_zero_alloc_SOURCES)
tests_check_zero_alloc_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_zero_alloc_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_zero_alloc_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

# The readers: NUL bytes, read errors, read-time checks, and allocation
# failures while reading (its own small interposed malloc).
tests_check_readers_SOURCES = tests/check_readers.c tests/testalloc.c tests/testalloc.h \
	$(test_common)
tests_check_readers_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_readers_LDADD = lib/libnoctree.la $(CHECK_LIBS)

tests_check_readers_efficient_SOURCES = $(tests_check_readers_SOURCES)
tests_check_readers_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tests_check_readers_efficient_CFLAGS = $(tests_check_octree_CFLAGS)
tests_check_readers_efficient_LDADD = lib/libnoctree-efficient.la $(CHECK_LIBS)

TESTS += tests/exports.sh tests/inline.sh tests/headers.sh tests/sim.sh tests/tools.sh \
	tests/examples.sh
EXTRA_DIST += tests/exports.sh tests/inline.sh tests/headers.sh tests/sim.sh tests/tools.sh \
	tests/examples.sh \
	tests/lib.sh \
	tests/inline-client.c

# The libFuzzer targets need clang: tests/fuzz/run.sh builds and runs them
# (CI runs it briefly); make and make check leave them alone. Listed file
# by file (a folder here would also take a build tree's tests/fuzz/).
EXTRA_DIST += tests/fuzz/README.md tests/fuzz/run.sh tests/fuzz/fuzz.h \
	tests/fuzz/fuzz_mesh.h tests/fuzz/fuzz_scene.c tests/fuzz/fuzz_off.c \
	tests/fuzz/fuzz_obj.c tests/fuzz/fuzz_narrowphase.c \
	tests/fuzz/scene.dict tests/fuzz/off.dict tests/fuzz/obj.dict \
	tests/fuzz/corpus/scene/coincident.scene \
	tests/fuzz/corpus/scene/every-statement.scene \
	tests/fuzz/corpus/scene/two-cubes.scene \
	tests/fuzz/corpus/scene/walls-late.scene \
	tests/fuzz/corpus/off/cube.off tests/fuzz/corpus/off/dented.off \
	tests/fuzz/corpus/off/tet.off \
	tests/fuzz/corpus/obj/cube.obj tests/fuzz/corpus/obj/tet.obj \
	tests/fuzz/corpus/narrowphase/boxes-touching \
	tests/fuzz/corpus/narrowphase/dent-vs-tet \
	tests/fuzz/corpus/narrowphase/flattened-numeric \
	tests/fuzz/corpus/narrowphase/off-vs-box \
	tests/fuzz/corpus/narrowphase/oriented-perm \
	tests/fuzz/corpus/narrowphase/raw-huge \
	tests/fuzz/corpus/narrowphase/tet-vs-rotated

# The peer benchmark's event counts against SCENES.md, when it is built.
if HAVE_PEERS
TESTS += tests/peers.sh
endif
EXTRA_DIST += tests/peers.sh

AM_TESTS_ENVIRONMENT = \
	CC='$(CC)'; NM='$(NM)'; srcdir='$(srcdir)/tests'; \
	top_srcdir='$(top_srcdir)'; top_builddir='$(top_builddir)'; \
	export CC NM srcdir top_srcdir top_builddir;

# Valgrind runs the suites in one process (no fork), so the death tests,
# which abort by design, are left out by their tag; so are the "slow" test
# cases (whole benchmark scenes), which the other builds run. check-alloc
# and check-zero-alloc replace malloc (testalloc.c), which valgrind does
# too: they would only skip (exit 77).
VALGRIND = valgrind
check-valgrind: $(check_PROGRAMS)
	@set -e; for t in $(check_PROGRAMS); do \
	  case $$t in tests/check-alloc*|tests/check-zero-alloc*) continue ;; esac; \
	  echo "valgrind $$t"; \
	  CK_FORK=no CK_EXCLUDE_TAGS='death slow' $(LIBTOOL) --mode=execute \
	    $(VALGRIND) -q --error-exitcode=1 --leak-check=full \
	    --errors-for-leak-kinds=definite,indirect ./$$t; \
	done
.PHONY: check-valgrind

# Run from make installcheck (and so from make distcheck) after make install:
# build the example against the installed copy through pkg-config, in both
# flavours, run it, and check the installed libraries' exports.
installcheck-local:
	@set -e; pcdir='$(DESTDIR)$(pkgconfigdir)'; \
	tmp=`mktemp -d`; trap 'rm -rf "$$tmp"' EXIT; \
	for mod in noctree noctree-efficient; do \
	  flags=`PKG_CONFIG_PATH="$$pcdir" PKG_CONFIG_SYSROOT_DIR='$(DESTDIR)' \
	    $(PKG_CONFIG) --cflags --libs $$mod`; \
	  echo "cc octree-demo.c $$flags"; \
	  $(CC) -std=c11 $(srcdir)/docs/examples/octree-demo.c $$flags \
	    -o "$$tmp/demo-$$mod"; \
	  LD_LIBRARY_PATH='$(DESTDIR)$(libdir)' "$$tmp/demo-$$mod" > "$$tmp/out"; \
	  grep -q 'OMEGA 0' "$$tmp/out"; \
	  echo "cc broadphase-demo.c $$flags"; \
	  $(CC) -std=c11 $(srcdir)/docs/examples/broadphase-demo.c $$flags \
	    -o "$$tmp/bp-$$mod"; \
	  LD_LIBRARY_PATH='$(DESTDIR)$(libdir)' "$$tmp/bp-$$mod" > "$$tmp/out"; \
	  grep -q '^pairs total 31$$' "$$tmp/out"; \
	  grep -q '^ray: first crate A$$' "$$tmp/out"; \
	  echo "cc driven-arm.c $$flags -lm"; \
	  $(CC) -std=c11 $(srcdir)/docs/examples/driven-arm.c $$flags -lm \
	    -o "$$tmp/arm-$$mod"; \
	  LD_LIBRARY_PATH='$(DESTDIR)$(libdir)' "$$tmp/arm-$$mod" > "$$tmp/out"; \
	  grep -q '^frame  4: contact forearm - crate$$' "$$tmp/out"; \
	done; \
	NM='$(NM)' top_srcdir='$(top_srcdir)' top_builddir='$(top_builddir)' \
	  $(SHELL) $(srcdir)/tests/exports.sh '$(DESTDIR)$(libdir)'
