#!/bin/sh
# SPDX-License-Identifier: MIT
# Show that the efficient flavour's in-lining is real: compile a client with
# the flags of the noctree-efficient pkg-config module and check from its
# object code that the accessors are not called. As a control, the same
# client compiled for the defensive flavour must call every one of them,
# so this check fails if the header stops selecting the inline versions.
set -eu
: "${CC:=cc}" "${NM:=nm}" "${srcdir:=.}" "${top_srcdir:=..}" "${top_builddir:=..}"
accessors="octParent octChild octChildType octIsSplit octGeneration octData octSwapData"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
incs="-I$top_srcdir/include -I$top_builddir/include"

undefined() { $NM -u "$1" | awk '{print $NF}' | sed 's/@.*//'; }

$CC -std=c11 -O2 $incs -DNOCT_EFFICIENT -c "$srcdir/inline-client.c" -o "$tmp/eff.o"
$CC -std=c11 -O2 $incs -DNDEBUG -c "$srcdir/inline-client.c" -o "$tmp/ndebug.o"
$CC -std=c11 -O2 $incs -c "$srcdir/inline-client.c" -o "$tmp/def.o"

status=0
for obj in eff ndebug; do
    calls=$(undefined "$tmp/$obj.o")
    for f in $accessors; do
        if printf '%s\n' "$calls" | grep -qx "$f"; then
            echo "FAIL: $obj client still calls $f"; status=1
        fi
    done
    printf '%s\n' "$calls" | grep -qx octSplit ||
        { echo "FAIL: $obj client does not call octSplit (check is blind)"; status=1; }
done
calls=$(undefined "$tmp/def.o")
for f in $accessors; do
    printf '%s\n' "$calls" | grep -qx "$f" ||
        { echo "FAIL: defensive client does not call $f"; status=1; }
done
[ $status -eq 0 ] && echo "PASS: efficient clients inline: $accessors"
exit $status
