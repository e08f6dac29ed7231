# SPDX-License-Identifier: MIT
# The two shared libraries, built from the same sources: the defensive one
# checks every requires clause with assert(3); the efficient one is built
# with NDEBUG. Both export the same symbols.

noctree_sources = \
	lib/internal.h \
	lib/array.c lib/array.h \
	lib/pool.c lib/pool.h \
	lib/vec3.h \
	lib/broadphase.c \
	lib/broadphase_internal.h \
	lib/broadphase_maintain.c \
	lib/broadphase_pairs.c \
	lib/broadphase_query.c \
	lib/box_form.c \
	lib/box_sweep.h \
	lib/broadphase_tree.c \
	lib/bvh.c lib/bvh.h \
	lib/clock.c \
	lib/direction.c \
	lib/families.c lib/families_internal.h \
	lib/mesh.c \
	lib/mesh_box.c \
	lib/mesh_internal.h \
	lib/meshdata.c \
	lib/meshdata_internal.h \
	lib/meshio.c \
	lib/meshio_assimp.c \
	lib/narrowphase.c \
	lib/narrowphase_contact.c \
	lib/narrowphase_distance.c \
	lib/narrowphase_internal.h \
	lib/narrowphase_point.c \
	lib/narrowphase_query.c \
	lib/narrowphase_swept.c \
	lib/narrowphase_turned.c lib/turned.h \
	lib/narrowphase_turning.c \
	lib/neighbor.c \
	lib/octree.c \
	lib/predicates.c \
	lib/predicates.h \
	lib/scene.c \
	lib/scene_internal.h \
	lib/scene_records.c \
	lib/scene_write.c \
	lib/status.c \
	lib/transform.c \
	lib/world.c \
	lib/world_contact.c \
	lib/world_events.c \
	lib/world_internal.h \
	lib/world_motion.c \
	lib/world_narrow.c \
	lib/world_near.c \
	lib/world_object.c \
	lib/world_distance.c \
	lib/world_query.c \
	lib/world_step.c \
	lib/world_sweep.c \
	lib/world_track.c \
	lib/world_ignore.c
noctree_deps_cflags = $(CCD_CFLAGS) $(QHULL_CFLAGS) $(GMP_CFLAGS) $(ASSIMP_CFLAGS)
noctree_deps_libs = $(CCD_LIBS) $(QHULL_LIBS) $(GMP_LIBS) $(ASSIMP_LIBS) $(LIBS)

noctree_ldflags = -version-info $(NOCT_LT_VERSION) -no-undefined
if HAVE_LD_VERSION_SCRIPT
# -Bsymbolic-functions: the library's calls to its own exported functions
# (the world's to octGtEqNeighbor, say) bind inside it, not through the PLT.
noctree_ldflags += -Wl,--version-script=$(srcdir)/lib/libnoctree.sym \
	-Wl,-Bsymbolic-functions
endif

lib_LTLIBRARIES += lib/libnoctree.la lib/libnoctree-efficient.la

lib_libnoctree_la_SOURCES = $(noctree_sources)
lib_libnoctree_la_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_BUILDING
lib_libnoctree_la_CFLAGS = $(AM_CFLAGS) $(VISIBILITY_CFLAGS) $(noctree_deps_cflags)
lib_libnoctree_la_LDFLAGS = $(noctree_ldflags)
lib_libnoctree_la_LIBADD = $(noctree_deps_libs)
EXTRA_lib_libnoctree_la_DEPENDENCIES = lib/libnoctree.sym

lib_libnoctree_efficient_la_SOURCES = $(noctree_sources)
lib_libnoctree_efficient_la_CPPFLAGS = $(AM_CPPFLAGS) -DNOCT_BUILDING -DNDEBUG
lib_libnoctree_efficient_la_CFLAGS = $(AM_CFLAGS) $(VISIBILITY_CFLAGS) $(noctree_deps_cflags)
lib_libnoctree_efficient_la_LDFLAGS = $(noctree_ldflags)
lib_libnoctree_efficient_la_LIBADD = $(noctree_deps_libs)
EXTRA_lib_libnoctree_efficient_la_DEPENDENCIES = lib/libnoctree.sym

noctreeincludedir = $(includedir)/noctree
noctreeinclude_HEADERS = \
	include/noctree/broadphase.h \
	include/noctree/export.h \
	include/noctree/mesh.h \
	include/noctree/narrowphase.h \
	include/noctree/neighbor.h \
	include/noctree/octree.h \
	include/noctree/octree_inline.h \
	include/noctree/query.h \
	include/noctree/scene.h \
	include/noctree/status.h \
	include/noctree/transform.h \
	include/noctree/world.h
nodist_noctreeinclude_HEADERS = include/noctree/version.h
include_HEADERS = include/noctree.h

pkgconfig_DATA = lib/noctree.pc lib/noctree-efficient.pc

EXTRA_DIST += lib/libnoctree.sym lib/noctree.pc.in lib/noctree-efficient.pc.in \
	include/noctree/version.h.in
