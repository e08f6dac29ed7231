#!/bin/sh
# SPDX-License-Identifier: MIT
# The example programs of docs/examples run, their output checked against
# what the scenes they build must give, worked out here independently
# (closed forms in awk, or by hand in the comments). make check runs the
# programs make built; make installcheck and the autopkgtest run the ones
# built from the installed examples folder with its Makefile, through
# these variables:
#   EXAMPLES        the folder of the built programs (docs/examples of the build)
#   EXAMPLE_SCENES  the folder of animation.scene (docs/examples of the source)
#   TOOL_SCENES     the folder of arms-3.scene and keyframes-20.scene
#   NOCTREE_SIM     noctree-sim, whose --first keyframe-check must match
#                   (empty: not compared)
set -u
. "${srcdir:-.}/lib.sh"
src=${top_srcdir:-..}
ex=${EXAMPLES:-$top_builddir/docs/examples}
scenes=${EXAMPLE_SCENES:-$src/docs/examples}
tool_scenes=${TOOL_SCENES:-$src/docs/examples/scenes}
sim=${NOCTREE_SIM-$top_builddir/tools/noctree-sim}

# check_output DESCRIPTION FILE EXPECTED: FILE holds exactly the lines of
# EXPECTED, numbers (any token that parses as one) equal within 2e-6.
check_output() {
    if awk -v want="$3" '
        function same(x, y) { return x == y || (x ~ /^-?[0-9.]+$/ && y ~ /^-?[0-9.]+$/ &&
                                                (x - y) ^ 2 < 4e-12) }
        { got[NR] = $0 }
        END {
            n = split(want, w, "\n")
            if (n != NR) { printf "  %d lines, want %d\n", NR, n; exit 1 }
            for (i = 1; i <= n; ++i) {
                a = split(got[i], g, " "); b = split(w[i], e, " ")
                ok = a == b
                for (k = 1; ok && k <= a; ++k) ok = same(g[k], e[k])
                if (!ok) { printf "  line %d: %s\n  want:    %s\n", i, got[i], w[i]; exit 1 }
            }
        }' "$2"; then ok; else fail "$1"; fi
}

expect_prog "$ex/octree-demo" 0 '^OMEGA 0'
expect_prog "$ex/broadphase-demo" 0 '^pairs total 31$'
expect_prog "$ex/broadphase-demo" 0 '^ray: first crate A$'

# driven-arm's events where geometry settles them by hand: at frame 0 the
# shoulder is at 15 degrees and the elbow at -10, so the forearm, 1.5 long
# from (2 cos 15, 2 sin 15), reaches x = 3.43 past the wall's face at 3.2;
# by frame 4 the shoulder is at 32.5 degrees and the forearm lies over the
# crate.
expect_prog "$ex/driven-arm" 0 '^frame  0: contact forearm - wall$'
expect_prog "$ex/driven-arm" 0 '^frame  4: contact forearm - crate$'
expect_prog "$ex/driven-arm" 0 '^frame  4: apart forearm - wall$'
expect_prog "$ex/driven-arm" 0 '^frame  1: near forearm - near the crate$'
# the links never pair (filters), nor the sensor with the crate it holds
"$ex/driven-arm" > "$tmp/arm" 2>&1
check "driven-arm: no link-link or sensor-crate pair" \
    sh -c "! grep -q -e 'upper arm - forearm' -e 'crate - near the crate' '$tmp/arm'"
check "driven-arm: 14 events" [ "$(wc -l < "$tmp/arm")" -eq 14 ]

# arm-monitor: the forearm (half-extents 0.75, 0.08, 0.08) turned by
# a = s - 30 degrees about z, its centre at 2 (cos s, sin s) + 0.75 (cos a,
# sin a), reaches x = 2 cos s + 0.75 cos a + 0.75 |cos a| + 0.08 |sin a|;
# the wall's face is the plane x = 3.3 and covers every y and z the arm
# takes, so the forearm is 3.3 - that from it (0 past it). Near within
# the forearm's margin 0.3; the upper arm (half 1, 0.1, 0.1, centre
# (cos s, sin s)) never comes within its 0.1, nor anything within reach
# of the floor or the crate. The shoulder s = 50 - 2.5 f at frame f.
want=$(awk 'BEGIN {
    pi = atan2(0, -1); near = 0; hit = 0
    for (f = 0; f <= 40; ++f) {
        s = (50 - 2.5 * f) * pi / 180; a = s - 30 * pi / 180
        x = 2 * cos(s) + 0.75 * cos(a) + 0.75 * abs(cos(a)) + 0.08 * abs(sin(a))
        d = 3.3 - x
        if (d <= 0.3 && !near) printf "frame %2d: warning forearm - wall\n", f
        if (d <= 0 && !hit) printf "frame %2d: HIT forearm - wall\n", f
        if (d > 0 && hit) printf "frame %2d: apart forearm - wall\n", f
        if (d > 0.3 && near) printf "frame %2d: clear forearm - wall\n", f
        near = d <= 0.3; hit = d <= 0
        if (near) printf "frame %2d: near forearm - wall %.6f\n", f, hit ? 0 : d
    }
    x = cos(s) + abs(cos(s)) + 0.1 * abs(sin(s))
    printf "at the end: upper arm - wall %.6f (proved between %.6f and %.6f)", 3.3 - x,
           3.3 - x, 3.3 - x
}
function abs(v) { return v < 0 ? -v : v }')
"$ex/arm-monitor" > "$tmp/monitor" 2>&1
check "arm-monitor: exit 0" [ $? -eq 0 ]
check_output "arm-monitor: near, hit, apart and clear frames, distances in closed form" \
    "$tmp/monitor" "$want"

# queries: the answers worked out in queries.c's comments: A is the cube
# [-0.5, 0.5]^3, B is [4, 6] x [-0.5, 0.5]^2, the pillar [-0.5, 0.5] x
# [4.5, 5.5] x [-2, 2]; the gripper reaches 0.25 sqrt 2 = 0.354 along x
# turned, so from 3.7 it passes x = 4 and from 2.5 it reaches nothing; the
# segment from x = -5, 20 long, enters A at -0.5 (4.5 / 20) and B at 4
# (9 / 20); from (2.5, 0, 0) B is 1.5 away, A 2 and the pillar
# sqrt(2^2 + 4.5^2) = 4.92; the gripper's face at 2.25 moving 4 along x
# meets B at 4 after 1.75 / 4; the crates are 4 - 0.5 apart.
"$ex/queries" > "$tmp/queries" 2>&1
check "queries: exit 0" [ $? -eq 0 ]
check_output "queries: every answer as worked out by hand" "$tmp/queries" \
"point (0.5, 0.2, 0.1): A
box (-1, -1, -1) (4, 1, 1): A B
gripper at x = 2.5: none
gripper at x = 3.7: B
ray: first A at 0.225, point (-0.5, 0.1, 0.2), normal (-1, 0, 0)
ray, every hit: A at 0.225 B at 0.45
nearest to (2.5, 0, 0): B at 1.5
within 2.2 of (2.5, 0, 0): A 2 B 1.5
gripper moving along x: touches B at 0.4375 of the move
A - B: 3.5, nearest points (0.5, -0.5, -0.5) and (4, -0.5, -0.5)"

# keyframe-check on animation.scene: the ball, from (0, 3, 0) at tick 50
# to (2, 0, 0) at 100, half-extents 0.25, first overlaps the post (x 1.5
# to 2.5, y -0.5 to 0.5) when 2.75 - 3 s <= 0.5 (s = (tick - 50) / 50):
# tick 87.5, so after step 88, where its box is x 1.27 to 1.77 and y 0.47
# to 0.97 (s = 0.76).
"$ex/keyframe-check" "$scenes/animation.scene" > "$tmp/first" 2>&1
check "keyframe-check: exit 0" [ $? -eq 0 ]
check_output "keyframe-check: the ball meets the post after step 88, where" "$tmp/first" \
    "first collision at step 88: objects post and ball, contact box \
(1.5, 0.47, -0.25) (1.77, 0.5, 0.25)"
# a scene with an error: the file and line, exit 1
printf 'mesh cube box 1 1 1\nobject cube 0 0 0 name 7up\n' > "$tmp/bad.scene"
expect_prog "$ex/keyframe-check" 1 "bad.scene:2:" "$tmp/bad.scene"
# what noctree-sim --first says, character for character
if [ -n "$sim" ]; then
    for scene in "$scenes/animation.scene" "$tool_scenes/arms-3.scene" \
                 "$tool_scenes/keyframes-20.scene"; do
        "$ex/keyframe-check" "$scene" > "$tmp/example" 2>&1
        "$sim" --first --quiet "$scene" > "$tmp/sim" 2>&1
        check "keyframe-check ${scene##*/}: as noctree-sim --first" cmp -s "$tmp/example" "$tmp/sim"
        check "keyframe-check ${scene##*/}: a first collision" \
            grep -q '^first collision at step [0-9]' "$tmp/example"
    done
fi
finish examples
