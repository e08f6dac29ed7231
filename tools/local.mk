# SPDX-License-Identifier: MIT
# Command-line tools and benchmark programs.

# Installed tools, each with its section 1 man page.
bin_PROGRAMS = tools/noctree-sim tools/noctree-bench tools/octprint
tools_noctree_sim_SOURCES = tools/noctree-sim.c tools/toolutil.c tools/toolutil.h
tools_noctree_sim_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_noctree_sim_LDADD = lib/libnoctree-efficient.la
tools_noctree_bench_SOURCES = tools/noctree-bench.c tools/toolutil.c tools/toolutil.h
tools_noctree_bench_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_noctree_bench_LDADD = lib/libnoctree-efficient.la
tools_octprint_SOURCES = tools/octprint.c tools/toolutil.c tools/toolutil.h
tools_octprint_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_octprint_LDADD = lib/libnoctree-efficient.la
dist_man_MANS = docs/man/noctree-sim.1 docs/man/noctree-bench.1 docs/man/octprint.1 \
	docs/man/noctree-scene.5

# The octree ADT benchmark, once per build (make bench runs both).
noinst_PROGRAMS += tools/bench-octree-defensive tools/bench-octree-efficient
tools_bench_octree_defensive_SOURCES = tools/bench-octree.c
tools_bench_octree_defensive_LDADD = lib/libnoctree.la
tools_bench_octree_efficient_SOURCES = tools/bench-octree.c
tools_bench_octree_efficient_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_bench_octree_efficient_LDADD = lib/libnoctree-efficient.la
EXTRA_DIST += tools/bench-octree.sh

# What accuracy costs: the narrowphase levels, against the efficient build.
noinst_PROGRAMS += tools/bench-narrowphase
tools_bench_narrowphase_SOURCES = tools/bench-narrowphase.c
tools_bench_narrowphase_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_bench_narrowphase_LDADD = lib/libnoctree-efficient.la

# The collision world on the SCENES.md families.
noinst_PROGRAMS += tools/bench-world
tools_bench_world_SOURCES = tools/bench-world.c
tools_bench_world_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT
tools_bench_world_LDADD = lib/libnoctree-efficient.la

# Two builds of the library in one process, step for step (dlopen).
noinst_PROGRAMS += tools/bench-ab
tools_bench_ab_SOURCES = tools/bench-ab.c
tools_bench_ab_LDADD = -ldl

# libnoctree against FCL's and ODE's broadphases, when both are installed.
if HAVE_PEERS
noinst_PROGRAMS += tools/bench-peers
endif
tools_bench_peers_SOURCES = tools/bench-peers.cc
tools_bench_peers_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_EFFICIENT \
	-DNOCT_ODE_VERSION='"$(ODE_VERSION)"' $(PEERS_CFLAGS)
tools_bench_peers_CXXFLAGS = $(NOCT_CXXFLAGS)
tools_bench_peers_LDADD = lib/libnoctree-efficient.la $(PEERS_LIBS)

bench: tools/bench-octree-defensive tools/bench-octree-efficient \
		tools/bench-narrowphase tools/bench-world
	BENCH_BINDIR=tools $(SHELL) $(srcdir)/tools/bench-octree.sh
	tools/bench-narrowphase
	tools/bench-world
.PHONY: bench
CLEANFILES += bench-octree.csv bench-narrowphase.csv bench-world.csv
