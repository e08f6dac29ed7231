# SPDX-License-Identifier: MIT
# Command-line tools and benchmark programs.

# The tools' kit, built once: toolutil (usage errors, parsing, scene
# arguments, the progress bar) and benchutil (the clock, the RNG, the
# statistics of timings, CSV files). A program links only the parts it
# uses: benchutil needs no libnoctree, so bench-ab (which dlopens the
# library) and the defensive bench-octree take it alone.
noinst_LTLIBRARIES += tools/libtoolkit.la
tools_libtoolkit_la_SOURCES = tools/toolutil.c tools/toolutil.h tools/benchutil.c \
	tools/benchutil.h
tools_libtoolkit_la_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_efficient_ldadd = tools/libtoolkit.la lib/libnoctree-efficient.la

# Installed tools, each with its section 1 man page.
bin_PROGRAMS = tools/noctree-sim tools/noctree-bench tools/octprint tools/noctree-mesh
tools_noctree_sim_SOURCES = tools/noctree-sim.c
tools_noctree_sim_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_noctree_sim_LDADD = $(tools_efficient_ldadd)
tools_noctree_bench_SOURCES = tools/noctree-bench.c
tools_noctree_bench_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_noctree_bench_LDADD = $(tools_efficient_ldadd)
tools_octprint_SOURCES = tools/octprint.c
tools_octprint_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_octprint_LDADD = $(tools_efficient_ldadd)
tools_noctree_mesh_SOURCES = tools/noctree-mesh.c
tools_noctree_mesh_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_noctree_mesh_LDADD = $(tools_efficient_ldadd)
dist_man_MANS = docs/man/noctree-sim.1 docs/man/noctree-bench.1 docs/man/octprint.1 \
	docs/man/noctree-mesh.1 \
	docs/man/noctree-scene.5

# The octree ADT benchmark, once per build (make bench runs both).
noinst_PROGRAMS += tools/bench-octree-defensive tools/bench-octree-efficient
tools_bench_octree_defensive_SOURCES = tools/bench-octree.c
tools_bench_octree_defensive_LDADD = tools/libtoolkit.la lib/libnoctree.la
tools_bench_octree_efficient_SOURCES = tools/bench-octree.c
tools_bench_octree_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_bench_octree_efficient_LDADD = $(tools_efficient_ldadd)
EXTRA_DIST += tools/bench-octree.sh

# What accuracy costs: the narrowphase levels, against the efficient build.
noinst_PROGRAMS += tools/bench-narrowphase
tools_bench_narrowphase_SOURCES = tools/bench-narrowphase.c
tools_bench_narrowphase_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_bench_narrowphase_LDADD = $(tools_efficient_ldadd)

# The collision world on the built-in families (noctree-families(7)).
noinst_PROGRAMS += tools/bench-world
tools_bench_world_SOURCES = tools/bench-world.c
tools_bench_world_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_bench_world_LDADD = $(tools_efficient_ldadd)

# Two builds of the library in one process, step for step (dlopen).
noinst_PROGRAMS += tools/bench-ab
tools_bench_ab_SOURCES = tools/bench-ab.c
tools_bench_ab_LDADD = tools/libtoolkit.la -ldl

# libnoctree against FCL's and ODE's broadphases, when both are installed.
if HAVE_PEERS
noinst_PROGRAMS += tools/bench-peers
endif
tools_bench_peers_SOURCES = tools/bench-peers.cc
tools_bench_peers_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT \
	-DNOCT_ODE_VERSION='"$(ODE_VERSION)"' $(PEERS_CFLAGS)
tools_bench_peers_CXXFLAGS = $(NOCT_CXXFLAGS)
tools_bench_peers_LDADD = $(tools_efficient_ldadd) $(PEERS_LIBS) -lgmpxx $(GMP_LIBS)

bench: tools/bench-octree-defensive tools/bench-octree-efficient \
		tools/bench-narrowphase tools/bench-world
	BENCH_BINDIR=tools $(SHELL) $(srcdir)/tools/bench-octree.sh
	tools/bench-narrowphase
	tools/bench-world
.PHONY: bench
CLEANFILES += bench-octree.csv bench-narrowphase.csv bench-world.csv
