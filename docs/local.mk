# SPDX-License-Identifier: MIT
# make doc: HTML and section 3 man pages from the headers' Doxygen comments,
# with every Doxygen warning an error.

noinst_PROGRAMS += docs/examples/octree-demo
docs_examples_octree_demo_SOURCES = docs/examples/octree-demo.c
docs_examples_octree_demo_LDADD = lib/libnoctree.la

noinst_PROGRAMS += docs/examples/broadphase-demo
docs_examples_broadphase_demo_SOURCES = docs/examples/broadphase-demo.c
docs_examples_broadphase_demo_LDADD = lib/libnoctree.la

noinst_PROGRAMS += docs/examples/driven-arm
docs_examples_driven_arm_SOURCES = docs/examples/driven-arm.c
docs_examples_driven_arm_LDADD = lib/libnoctree.la -lm

noinst_PROGRAMS += docs/examples/arm-monitor
docs_examples_arm_monitor_SOURCES = docs/examples/arm-monitor.c
docs_examples_arm_monitor_LDADD = lib/libnoctree.la -lm

noinst_PROGRAMS += docs/examples/keyframe-check
docs_examples_keyframe_check_SOURCES = docs/examples/keyframe-check.c
docs_examples_keyframe_check_LDADD = lib/libnoctree.la

noinst_PROGRAMS += docs/examples/queries
docs_examples_queries_SOURCES = docs/examples/queries.c
docs_examples_queries_LDADD = lib/libnoctree.la

# The examples, installed with a Makefile that builds them against the
# installed library with pkg-config (the Debian package libnoctree-dev has
# them in /usr/share/doc/libnoctree-dev/examples); tests/examples.sh checks
# what each prints, here and (make installcheck) built from that folder.
examplesdir = $(docdir)/examples
dist_examples_DATA = docs/examples/Makefile docs/examples/octree-demo.c \
	docs/examples/broadphase-demo.c docs/examples/driven-arm.c \
	docs/examples/arm-monitor.c docs/examples/keyframe-check.c \
	docs/examples/animation.scene docs/examples/queries.c

# The scene files of the arms:K and keyframes:N families (noctree-sim
# --scene arms:3 --write-scene ...; tests/sim.sh checks that they are
# still what the families write), installed with the documentation.
examplescenesdir = $(docdir)/examples/scenes
dist_examplescenes_DATA = docs/examples/scenes/arms-3.scene \
	docs/examples/scenes/keyframes-20.scene \
	docs/examples/scenes/turntable.scene

EXTRA_DIST += docs/Doxyfile.in docs/mainpage.md docs/results.md docs/families.md \
	docs/doxygen-header.html $(docs_results)
docs_results = \
	docs/results/default.txt docs/results/scale.txt docs/results/peers.txt \
	docs/results/overlap.txt docs/results/driven.txt docs/results/queries.txt \
	docs/results/distance.txt \
	docs/results/soups.txt docs/results/surfaces.txt docs/results/weld.txt \
	docs/results/peers.csv docs/results/sweep.txt docs/results/sweep.csv \
	docs/results/sweep.gp docs/results/sweep.svg \
	docs/results/fig9.svg docs/results/fig10.svg docs/results/scaling.svg \
	docs/results/accuracy.svg docs/results/octprint-t3.svg

# The overview page and the families' definitions; the section 1 and 5
# pages are in tools/local.mk.
dist_man_MANS += docs/man/noctree.7 docs/man/noctree-families.7

if HAVE_DOXYGEN
doc: docs/html/index.html
docs/html/index.html: docs/Doxyfile $(noctreeinclude_HEADERS) $(include_HEADERS) \
		docs/mainpage.md docs/results.md docs/families.md docs/families.txt \
		docs/doxygen-header.html $(docs_results)
	$(AM_V_GEN)rm -rf docs/html docs/man/man3 && $(DOXYGEN) docs/Doxyfile

# The families' page of the HTML docs is their manual page, as text.
docs/families.txt: docs/man/noctree-families.7
	$(AM_V_GEN)$(MKDIR_P) docs && LC_ALL=C.UTF-8 groff -man -Tutf8 -rLL=78n -rHY=0 \
	  -P-c -P-b -P-o -P-u $(srcdir)/docs/man/noctree-families.7 > $@.tmp && mv $@.tmp $@
CLEANFILES += docs/families.txt

# make install puts the section 3 pages of the public names (oct*, noct*,
# OCT_*, NOCT_*: not the pages Doxygen makes for struct fields, whose
# names would clash) in man3dir, and the HTML (no scripts) in htmldir.
# The headers' own pages (world.h.3: what a header holds outside its
# module, such as the noctWorld type) go in as noctree_world.h.3 and so
# on (noctree.h.3 as it is), and the pages that point at them (.so
# man3/world.h.3) are pointed at those names.
man3dir = $(mandir)/man3
install-data-local: docs/html/index.html
	$(MKDIR_P) '$(DESTDIR)$(man3dir)' '$(DESTDIR)$(htmldir)/html'
	cd docs/man/man3 && for f in oct*.3 noct*.3 OCT_*.3 NOCT_*.3; do \
	  case $$f in noctree.h.3) ;; *.h.3) continue ;; esac; \
	  if head -n 1 "$$f" | grep -q '^\.so man3/[a-z_]*\.h\.3$$'; then \
	    sed 's|^\.so man3/\([a-z_]*\.h\.3\)$$|.so man3/noctree_\1|' "$$f" > "$$f.tmp" && \
	    $(INSTALL_DATA) "$$f.tmp" '$(DESTDIR)$(man3dir)/'"$$f" && rm -f "$$f.tmp" || exit 1; \
	  else $(INSTALL_DATA) "$$f" '$(DESTDIR)$(man3dir)' || exit 1; fi; done; \
	for f in *.h.3; do case $$f in noctree.h.3) continue ;; esac; \
	  $(INSTALL_DATA) "$$f" '$(DESTDIR)$(man3dir)/noctree_'"$$f" || exit 1; done
	cd docs/html && for f in *.html *.css *.png *.svg; do \
	  $(INSTALL_DATA) "$$f" '$(DESTDIR)$(htmldir)/html' || exit 1; done
uninstall-local:
	cd '$(DESTDIR)$(man3dir)' && rm -f oct*.3 noct*.3 OCT_*.3 NOCT_*.3
	rm -rf '$(DESTDIR)$(htmldir)/html'
else
doc:
	@echo "make doc needs Doxygen: apt-get install doxygen, then re-run configure" >&2
	@exit 1
endif
.PHONY: doc

clean-local: clean-doc
clean-doc:
	-rm -rf docs/html docs/man/man3
.PHONY: clean-doc
