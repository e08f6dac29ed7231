# SPDX-License-Identifier: MIT
# make doc: HTML and section 3 man pages from the headers' Doxygen comments,
# with every Doxygen warning an error.

noinst_PROGRAMS += docs/examples/octree-demo
docs_examples_octree_demo_SOURCES = docs/examples/octree-demo.c
docs_examples_octree_demo_LDADD = lib/libnoctree.la

EXTRA_DIST += docs/Doxyfile.in docs/mainpage.md

if HAVE_DOXYGEN
doc: docs/Doxyfile $(noctreeinclude_HEADERS) $(include_HEADERS) docs/mainpage.md
	$(AM_V_GEN)rm -rf docs/html docs/man/man3 && $(DOXYGEN) docs/Doxyfile
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
