#!/bin/sh
# SPDX-License-Identifier: MIT
# The dynamic symbol table of each library must list exactly the functions
# the public headers declare with NOCT_API or NOCT_ACCESSOR, and the two
# libraries must export the same set. (Doxygen, with warnings as errors,
# separately fails the doc build for any of them left undocumented.)
# Usage: exports.sh [LIBDIR]   (default: the build tree's lib/.libs)
set -eu
: "${NM:=nm}" "${top_srcdir:=..}" "${top_builddir:=..}"
libdir=${1:-$top_builddir/lib/.libs}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

sed -n -E 's/^(NOCT_API|NOCT_ACCESSOR) [^(]*[ *]([A-Za-z_][A-Za-z0-9_]*)\(.*/\2/p' \
    "$top_srcdir"/include/noctree/*.h | sort -u > "$tmp/declared"
[ -s "$tmp/declared" ] || { echo "FAIL: no declarations found"; exit 1; }

status=0
for lib in libnoctree libnoctree-efficient; do
    so="$libdir/$lib.so"
    [ -e "$so" ] || { echo "FAIL: $so not found"; exit 1; }
    $NM -D --defined-only "$so" | awk '$2 ~ /^[TtWiDdBbRr]$/ {print $3}' |
        sed 's/@.*//' | grep -v '^NOCTREE_' | sort -u > "$tmp/$lib"
    if ! cmp -s "$tmp/declared" "$tmp/$lib"; then
        echo "FAIL: $lib exports differ from the headers (< headers, > $lib):"
        diff "$tmp/declared" "$tmp/$lib" || true
        status=1
    fi
done
[ $status -eq 0 ] && echo "PASS: both libraries export exactly the $(wc -l < "$tmp/declared") declared functions"
exit $status
