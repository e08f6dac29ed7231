#!/bin/sh
# SPDX-License-Identifier: MIT
# noctree-sim end to end: known event counts, the event log, a scene file,
# and a precise message with exit status 2 for every kind of bad input.
set -u
. "${srcdir:-.}/lib.sh"
sim="$top_builddir/tools/noctree-sim"

# expect_run STATUS PATTERN ARGS...: noctree-sim's exit status and output.
expect_run() { expect_prog "$sim" "$@"; }

expect_run 0 '^contact begins 49$' --scene planes:3 --quiet
expect_run 0 '^contact begins 49$' --scene planes:3 --N big --maintenance rebuild --quiet
expect_run 0 '^contact begins 9$' --scene planes:1 --accuracy box --quiet
"$sim" --scene planes:2 --events > "$tmp/ev" 2>&1
[ "$(grep -c ' begin ' "$tmp/ev")" -eq 25 ] && grep -q '^51 begin 12 37$' "$tmp/ev" && ok ||
    fail "--events: want 25 begins, the central pair at step 51"
expect_run 0 'Usage\|usage' --help
expect_run 0 '^noctree-sim [0-9]' --version

# A scene file: two cubes on a collision course, a mesh from an OFF file.
cat > "$tmp/tet.off" <<'END_OFF'
OFF
4 4 6
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 1 2 3
3 0 3 2
END_OFF
cat > "$tmp/two.scene" <<'SCENE'
# two cubes meet once; a tetrahedron sits apart
N 2
steps 100
mesh cube box 0.5 0.5 0.5
mesh tet file tet.off
object cube 0 0 0   1 0 0 0.05
object cube 4 0 0  -1 0 0 0.05
object tet 10 10 10
SCENE
expect_run 0 '^contact begins 1$' --quiet "$tmp/two.scene"
expect_run 0 '^objects 3$' --quiet "$tmp/two.scene"

# A cube passing through a sensor: its faces meet the sensor's at step 40
# (0.5 + 0.05 s = 2.5) and part after step 80 (0.05 s - 0.5 = 3.5).
cat > "$tmp/sensor.scene" <<'SCENE'
mesh cube box 0.5 0.5 0.5
object cube 0 0 0 velocity 0.05 0 0
object cube 3 0 0 type static sensor
SCENE
expect_run 0 '^40 sensor-begin 0 1$' --events --quiet --steps 100 "$tmp/sensor.scene"
expect_run 0 '^81 sensor-end 0 1$' --events --quiet --steps 100 "$tmp/sensor.scene"
expect_run 0 '^contact begins 0$' --quiet --steps 100 "$tmp/sensor.scene"
expect_run 0 '^sensor events 2$' --quiet --steps 100 "$tmp/sensor.scene"

# Bad scene files: exit 2 and file:line: problem.
bad_scene() { # NAME LINE-PATTERN CONTENT
    printf '%s\n' "$3" > "$tmp/$1"
    expect_run 2 "$tmp/$1$2" "$tmp/$1"
}
bad_scene unknown.scene ":1: unknown statement 'frobnicate'" 'frobnicate 1'
bad_scene number.scene ":2: not a number: 'x'" 'mesh cube box 1 1 1
object cube 0 0 x'
bad_scene mesh.scene ":1: unknown mesh 'ball'" 'object ball 0 0 0'
bad_scene nan.scene ":1: not a finite number: 'nan'" 'mesh cube box nan 1 1'
bad_scene zero.scene ":1: N must be at least 1" 'N 0'
bad_scene depth.scene ":1: max-depth 99 is out of range" 'max-depth 99'
bad_scene extra.scene ":1: unexpected 'z'" 'steps 10 z'
bad_scene twice.scene ":2: mesh 'a' is defined twice" 'mesh a box 1 1 1
mesh a box 1 1 1'
bad_scene negative.scene ":1: mesh 'a': " 'mesh a box -1 1 1'
bad_scene speed.scene ":2: negative speed" 'mesh a box 1 1 1
object a 0 0 0 1 0 0 -1'
bad_scene nofile.scene ":1: mesh 'a': .*cannot open" 'mesh a file missing.off'
printf 'OFF\n4 4 6\n0 0 0\n' > "$tmp/short.off"
bad_scene badoff.scene ":1: mesh 'a': .*short.off.*file ends" 'mesh a file short.off'
bad_scene empty.scene ": the scene has no objects" '# nothing'
expect_run 2 "cannot open" "$tmp/does-not-exist.scene"

# The fidelity warning, and sub-steps that keep plates from tunnelling.
cat > "$tmp/fast.scene" <<'SCENE'
steps 10
mesh plate box 0.1 2 2
object plate -5 0 0    1 0 0 1
object plate 5.3 0 0 -1 0 0 1
SCENE
expect_run 0 'warning: an object moves 5.00 times' --quiet "$tmp/fast.scene"
expect_run 0 '^contact begins 0$' --quiet "$tmp/fast.scene"
expect_run 0 '^contact begins 1$' --quiet --substep "$tmp/fast.scene"
"$sim" --quiet --substep "$tmp/fast.scene" 2>&1 | grep -q warning &&
    fail "--substep still warns" || ok

# Bad usage: exit 2.
expect_run 2 'give one scene' --quiet
expect_run 2 "unknown scene 'nope:3'" --scene nope:3
expect_run 2 "unknown scene 'planes:-1'" --scene planes:-1
expect_run 2 "unknown scene 'gas:x'" --scene gas:x
expect_run 2 "'--N must be a positive integer\|--N must be" --scene planes:1 --N 0
expect_run 2 '--steps must be' --scene planes:1 --steps abc
expect_run 2 "unknown option" --scene planes:1 --frob
expect_run 2 '--accuracy must be' --scene planes:1 --accuracy perfect

finish sim
