#!/bin/sh
# SPDX-License-Identifier: MIT
# Every public header compiles on its own, as strict C11 in both flavours
# (and with the report's short names), and as C++ where a C++ compiler is
# installed (the headers promise extern "C" guards).
set -eu
: "${CC:=cc}" "${top_srcdir:=..}" "${top_builddir:=..}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
incs="-I$top_srcdir/include -I$top_builddir/include"
headers="noctree.h"
for h in "$top_srcdir"/include/noctree/*.h; do
    case $h in */octree_inline.h) continue ;; esac  # private, via octree.h
    headers="$headers noctree/$(basename "$h")"
done
headers="$headers noctree/version.h"

status=0 count=0
for h in $headers; do
    printf '#include <%s>\n#include <%s>\nint main(void) { return 0; }\n' "$h" "$h" > "$tmp/t.c"
    for mode in "" "-DNOCT_EFFICIENT" "-DNDEBUG" "-DOCT_SHORT_NAMES"; do
        count=$((count + 1))
        if ! $CC -std=c11 -Wall -Wextra -Wpedantic -Werror $mode $incs \
                -c "$tmp/t.c" -o "$tmp/t.o" 2> "$tmp/err"; then
            echo "FAIL: <$h> $mode does not compile on its own:"; cat "$tmp/err"
            status=1
        fi
    done
    if command -v "${CXX:-c++}" >/dev/null 2>&1; then
        cp "$tmp/t.c" "$tmp/t.cc"
        for mode in "" "-DNOCT_EFFICIENT"; do
            count=$((count + 1))
            if ! "${CXX:-c++}" -Wall -Wextra -Werror $mode $incs \
                    -c "$tmp/t.cc" -o "$tmp/t.o" 2> "$tmp/err"; then
                echo "FAIL: <$h> $mode does not compile as C++:"; cat "$tmp/err"
                status=1
            fi
        done
    else
        echo "note: no C++ compiler, C++ inclusion not checked"
    fi
done
[ $status -eq 0 ] && echo "PASS: $count header compilations"
exit $status
