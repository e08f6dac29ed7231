#!/bin/sh
# SPDX-License-Identifier: MIT
# The programs under docs/examples, built by make, run: their output against
# what the scenes they build must give. driven-arm's events are checked
# where geometry settles them by hand: at frame 0 the shoulder is at 15
# degrees and the elbow at -10, so the forearm, 1.5 long from (2 cos 15,
# 2 sin 15), reaches x = 3.43 past the wall's face at 3.2; by frame 4 the
# shoulder is at 32.5 degrees and the forearm lies over the crate.
set -u
. "${srcdir:-.}/lib.sh"
ex="$top_builddir/docs/examples"

expect_prog "$ex/octree-demo" 0 '^OMEGA 0'
expect_prog "$ex/broadphase-demo" 0 '^pairs total 31$'
expect_prog "$ex/broadphase-demo" 0 '^ray: first crate A$'
expect_prog "$ex/driven-arm" 0 '^frame  0: contact forearm - wall$'
expect_prog "$ex/driven-arm" 0 '^frame  4: contact forearm - crate$'
expect_prog "$ex/driven-arm" 0 '^frame  4: apart forearm - wall$'
expect_prog "$ex/driven-arm" 0 '^frame  1: near forearm - near the crate$'
# the links never pair (filters), nor the sensor with the crate it holds
"$ex/driven-arm" > "$tmp/arm" 2>&1
check "driven-arm: no link-link or sensor-crate pair" \
    sh -c "! grep -q -e 'upper arm - forearm' -e 'crate - near the crate' '$tmp/arm'"
check "driven-arm: 14 events" [ "$(wc -l < "$tmp/arm")" -eq 14 ]
finish examples
