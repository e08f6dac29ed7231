#!/bin/sh
# SPDX-License-Identifier: MIT
# noctree-sim end to end: known event counts, the event log, a scene file,
# the per-step reports and --first against pairs worked out by hand, and a
# precise message with exit status 2 for every kind of bad input.
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

# Surfaces: the closed box [0, 4]^3 as a surface holds two cubes without
# touching them; one moving along x reaches the wall x = 4 (2.5 + 0.05 s =
# 4, step 30 or 31 as the steps' sums round): one contact. As a solid it holds both cubes: two contacts
# from the first step. The box without its top is no solid: read as one,
# the scene fails and says how to read it as a surface.
cat > "$tmp/bay.off" <<'END_OFF'
OFF
8 6 0
0 0 0
0 0 4
0 4 0
0 4 4
4 0 0
4 0 4
4 4 0
4 4 4
4 0 1 3 2
4 4 6 7 5
4 0 4 5 1
4 2 3 7 6
4 0 2 6 4
4 1 5 7 3
END_OFF
head -n 15 "$tmp/bay.off" | sed 's/^8 6 0$/8 5 0/' > "$tmp/open.off"
for shape in surface solid; do
    cat > "$tmp/bay-$shape.scene" <<SCENE
steps 40
mesh bay file bay.off $shape
mesh cube box 0.5 0.5 0.5
object bay 0 0 0 type static
object cube 1 1 1 type static
object cube 2 2 2.5 velocity 0.05 0 0
SCENE
done
expect_run 0 '^contact begins 1$' --quiet "$tmp/bay-surface.scene"
expect_run 0 '^contact begins 2$' --quiet "$tmp/bay-solid.scene"
"$sim" --events --quiet "$tmp/bay-surface.scene" > "$tmp/ev" 2>&1
grep -q '^3[01] begin 0 2$' "$tmp/ev" && ok || fail "bay surface: want the wall met at step 30"
sed 's/bay.off surface/open.off surface/' "$tmp/bay-surface.scene" > "$tmp/open-surface.scene"
expect_run 0 '^contact begins 1$' --quiet "$tmp/open-surface.scene"
sed 's/bay.off solid/open.off/' "$tmp/bay-solid.scene" > "$tmp/open-solid.scene"
expect_run 2 "mesh 'bay': .*open.off: not a closed.*noctMeshReadSurface()" --quiet \
    "$tmp/open-solid.scene"

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

# Continuous detection: a keyframed cube passes through a thin wall between
# steps 1 and 2 (keys 1 and 2 are -3 and 3). The exact level sees nothing;
# the continuous level sees the cube's face reach the wall's at time
# (3 - 0.5 - 0.0625) / 6 = 0.40625 of step 2 (dyadic: exact), and the pair
# end at step 3.
cat > "$tmp/tunnel.scene" <<'SCENE'
steps 4
mesh cube box 0.5 0.5 0.5
mesh wall box 0.0625 2 2
object wall 0 0 0 type static
object cube -3 0 0
key 0 -3 0 0
key 1 -3 0 0
key 2 3 0 0
SCENE
expect_run 0 '^no collision in 4 steps$' --first --quiet "$tmp/tunnel.scene"
expect_run 0 '^contact begins 0$' --quiet "$tmp/tunnel.scene"
expect_run 0 '^first collision at step 2, time 0.40625 of the step: objects 0 and 1, touching at (-0.0625, ' \
    --first --quiet --accuracy continuous "$tmp/tunnel.scene"
"$sim" --events --quiet --accuracy continuous "$tmp/tunnel.scene" > "$tmp/out" 2>&1
check "continuous --events: the begin at step 2 with its time, the end at step 3" \
    [ "$(grep -E '^[0-9]+ (begin|end) ' "$tmp/out")" = "2 begin 0 1 at 0.40625
3 end 0 1" ]
sed 's/^steps 4$/steps 4\naccuracy continuous/' "$tmp/tunnel.scene" > "$tmp/tunnel-c.scene"
expect_run 0 '^contact begins 1$' --quiet "$tmp/tunnel-c.scene"
expect_run 0 '^accuracy continuous$' --quiet "$tmp/tunnel-c.scene"
expect_run 0 '^accuracy continuous$' --write-scene - "$tmp/tunnel-c.scene"
# Per object: the cube alone continuous in an exact world sees the wall; a
# discrete cube in a continuous world does not.
sed 's/^object cube -3 0 0$/object cube -3 0 0 continuous/' "$tmp/tunnel.scene" > "$tmp/bullet.scene"
expect_run 0 '^first collision at step 2, time 0.40625 of the step: objects 0 and 1' \
    --first --quiet "$tmp/bullet.scene"
expect_run 0 '^object cube -3 0 0 type kinematic continuous$' --write-scene - "$tmp/bullet.scene"
sed 's/^object cube -3 0 0$/object cube -3 0 0 discrete/' "$tmp/tunnel-c.scene" > "$tmp/slow.scene"
expect_run 0 '^contact begins 0$' --quiet "$tmp/slow.scene"
sed 's/^object cube -3 0 0$/object cube -3 0 0 discrete continuous/' "$tmp/tunnel.scene" > "$tmp/both.scene"
expect_run 2 "both.scene:5: an object is continuous or discrete, not both" "$tmp/both.scene"
expect_run 2 "--accuracy must be box, convex, exact or continuous, not 'sweep'" --accuracy sweep "$tmp/tunnel.scene"
sed 's/^steps 4$/accuracy sweep/' "$tmp/tunnel.scene" > "$tmp/bad-acc.scene"
expect_run 2 "bad-acc.scene:1: unknown accuracy 'sweep' (box, convex, exact or continuous)" "$tmp/bad-acc.scene"

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
bad_scene shape.scene ":1: unknown mesh shape 'hollow' (solid or surface)" \
    'mesh a file bay.off hollow'
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

# ---- --report and --first ---------------------------------------------------
# Unit cubes (half-extents 0.5) on the x axis, without response, so that
# objects pass through each other: two collide after step s exactly when
# their positions (p += v each step, before detection) are at most 1 apart on
# every axis, touching included. Speeds are multiples of 1/8, so every
# position is exact. Cube 0 (x = 0.25 s) meets the static cube 2 (x = 1.75)
# at steps 3 to 11, cube 1 (x = 5 - 0.25 s) meets cube 2 at 9 to 17 and
# cube 0 at 8 to 12.
cat > "$tmp/three.scene" <<'SCENE'
effects motion events
mesh cube box 0.5 0.5 0.5
object cube 0 0 0     velocity 0.25 0 0
object cube 5 0 0     velocity -0.25 0 0
object cube 1.75 0 0  type static
SCENE
# The oracle: the same positions, every pair tested by hand, as the CSV rows.
awk 'BEGIN {
    split("0 5 1.75", x0, " "); split("0.25 -0.25 0", v, " ")
    for (s = 1; s <= 20; ++s)
        for (i = 1; i <= 3; ++i)
            for (j = i + 1; j <= 3; ++j) {
                d = (x0[j] + v[j] * s) - (x0[i] + v[i] * s)
                if (d <= 1 && d >= -1)
                    printf "%d,collide,%d,%d\n", s, i - 1, j - 1
            }
}' > "$tmp/want.csv"
check "oracle: 23 colliding rows" [ "$(wc -l < "$tmp/want.csv")" -eq 23 ]

# CSV on standard output; the summary goes to standard error then.
"$sim" --report csv --steps 20 --quiet "$tmp/three.scene" > "$tmp/csv" 2> "$tmp/err"
check "--report csv: exit 0" [ $? -eq 0 ]
check "--report csv: header step,kind,a,b" [ "$(head -1 "$tmp/csv")" = "step,kind,a,b" ]
tail -n +2 "$tmp/csv" > "$tmp/rows.csv"
check "--report csv: the rows are the oracle's" cmp -s "$tmp/rows.csv" "$tmp/want.csv"
check "--report csv: standard output holds only the report" \
    [ "$(grep -c -v '^[0-9]*,collide,[0-9]*,[0-9]*$' "$tmp/csv")" -eq 1 ]
check "--report csv: the summary goes to standard error" \
    grep -q '^contact begins 3$' "$tmp/err"

# The table: a header, then a line per step with pairs (3 to 17), in the
# world's order; the same pairs as the CSV rows.
"$sim" --report table --steps 20 --quiet "$tmp/three.scene" > "$tmp/table" 2> /dev/null
check "--report table: header" \
    [ "$(head -1 "$tmp/table" | awk '{ $1 = $1; print }')" = "step kind count pairs" ]
check "--report table: 15 lines of pairs" [ "$(tail -n +2 "$tmp/table" | wc -l)" -eq 15 ]
check "--report table: step 8 has 0-1 and 0-2" grep -q '^ *8  *collide  *2  *0-1 0-2$' "$tmp/table"
check "--report table: step 10 has all three pairs" \
    grep -q '^ *10  *collide  *3  *0-1 0-2 1-2$' "$tmp/table"
check "--report table: no line for step 2 or 18" \
    [ "$(awk 'NR > 1 && ($1 == 2 || $1 == 18)' "$tmp/table" | wc -l)" -eq 0 ]
awk 'NR > 1 { for (i = 4; i <= NF; ++i) { split($i, ab, "-"); print $1 "," $2 "," ab[1] "," ab[2] }
              if (NF - 3 != $3) print "count " $3 " for " NF - 3 " pairs at step " $1 }' \
    "$tmp/table" > "$tmp/table.csv"
check "--report table: counts and pairs agree with the oracle" \
    cmp -s "$tmp/table.csv" "$tmp/want.csv"

# --output: the report in the file; the summary and events stay on standard
# output, and --events works as without --report.
"$sim" --report csv --output "$tmp/out.csv" --events --steps 20 "$tmp/three.scene" \
    > "$tmp/stdout" 2> /dev/null
check "--output: the file holds the CSV" cmp -s "$tmp/out.csv" "$tmp/csv"
check "--output: the summary on standard output" grep -q '^contact begins 3$' "$tmp/stdout"
check "--output --events: the events on standard output" \
    [ "$(grep -c '^[0-9]* \(begin\|end\) [0-9]* [0-9]*$' "$tmp/stdout")" -eq 6 ]
check "--output --events: 0-1 begins at step 8" grep -q '^8 begin 0 1$' "$tmp/stdout"
"$sim" --report table --events --steps 20 "$tmp/three.scene" > "$tmp/stdout" 2> "$tmp/err"
check "--report --events without --output: the events on standard error" \
    grep -q '^18 end 1 2$' "$tmp/err"
check "--report --events without --output: standard output holds only the table" \
    cmp -s "$tmp/stdout" "$tmp/table"

# gnuplot: a script with its data inline, a row a step, zeros included.
"$sim" --report gnuplot --output "$tmp/plot.gp" --steps 20 --quiet "$tmp/three.scene" \
    > "$tmp/stdout" 2> /dev/null
check "--report gnuplot: the summary stays on standard output" \
    grep -q '^contact begins 3$' "$tmp/stdout"
# starts_line FILE TEXT: a line of FILE starts with TEXT.
starts_line() { awk -v t="$2" 'index($0, t) == 1 { found = 1 } END { exit !found }' "$1"; }
for line in "set terminal svg " "set output '$tmp/plot.svg'" "set title '" \
        "set xlabel 'step'" "set ylabel 'colliding pairs'" '$data << EOD' 'EOD' \
        'plot $data using 1:2 '; do
    check "--report gnuplot: a line starting '$line'" starts_line "$tmp/plot.gp" "$line"
done
awk '/^EOD$/ { inside = 0 } inside && !/^#/ { print } /^\$data << EOD$/ { inside = 1 }' \
    "$tmp/plot.gp" > "$tmp/rows"
awk -F, '{ n[$1]++ } END { for (s = 1; s <= 20; ++s) print s, n[s] + 0 }' \
    "$tmp/want.csv" > "$tmp/want.rows"
check "--report gnuplot: 20 rows, step and pairs, the oracle's counts" \
    cmp -s "$tmp/rows" "$tmp/want.rows"
check "--report gnuplot: plot after the data" \
    [ "$(grep -n '^EOD$' "$tmp/plot.gp" | cut -d: -f1)" -lt \
      "$(grep -n '^plot ' "$tmp/plot.gp" | cut -d: -f1)" ]
"$sim" --report gnuplot --steps 20 --quiet "$tmp/three.scene" > "$tmp/stdout.gp" 2> /dev/null
check "--report gnuplot without --output: no set output" \
    [ "$(grep -c '^set output' "$tmp/stdout.gp")" -eq 0 ]
mkdir "$tmp/d.x"
"$sim" --report gnuplot --output "$tmp/d.x/plot" --steps 2 "$tmp/three.scene" > /dev/null 2>&1
check "--report gnuplot: .svg added to a name without an extension" \
    grep -q -F -x "set output '$tmp/d.x/plot.svg'" "$tmp/d.x/plot"
"$sim" --report gnuplot --output "$tmp/it's.gp" --steps 20 "$tmp/three.scene" > /dev/null 2>&1
check "--report gnuplot: a quote in the name doubled" \
    grep -q -F -x "set output '$tmp/it''s.svg'" "$tmp/it's.gp"
if command -v gnuplot > /dev/null 2>&1; then
    check "gnuplot draws the script's SVG" gnuplot "$tmp/plot.gp"
    check "gnuplot: the SVG is whole" grep -q '</svg>' "$tmp/plot.svg"
    check "gnuplot: the quoted name" gnuplot "$tmp/it's.gp"
    check "gnuplot: the SVG under the quoted name" grep -q '</svg>' "$tmp/it's.svg"
    gnuplot "$tmp/stdout.gp" > "$tmp/stdout.svg" 2> "$tmp/err"
    check "gnuplot: without --output, the SVG on standard output" \
        grep -q '</svg>' "$tmp/stdout.svg"
    "$sim" --report gnuplot --output "$tmp/none.gp" --steps 1 "$tmp/three.scene" > /dev/null 2>&1
    check "gnuplot: one step without a collision, without a warning" \
        [ "$(gnuplot "$tmp/none.gp" 2>&1 | wc -c)" -eq 0 ]
else
    echo "sim: gnuplot not installed, the scripts are not run"
fi

# --first: the step follows from the gap g between the faces and the closing
# speed c = v0 + v1: ceil(g / c) (in eighths: (8g + 8c - 1) / 8c). At that
# step cube 0 is at x0 = v0 s and cube 1 at (x1, dy, dz), x1 = 1 + g - v1 s
# > x0, so the boxes' intersection is x1 - 0.5 to x0 + 0.5 on x, and
# max(-0.5, d - 0.5) to min(0.5, d + 0.5) for d = dy, dz on y and z.
first_case() { # G V0 V1 DY DZ: the gap and the speeds in eighths, cube 1's offset
    awk -v g="$1" -v a="$2" -v b="$3" -v dy="$4" -v dz="$5" -v f="$tmp/first.scene" 'BEGIN {
        print "mesh cube box 0.5 0.5 0.5" > f
        printf "object cube 0 0 0 velocity %g 0 0\n", a / 8 > f
        printf "object cube %g %g %g velocity %g 0 0\n", 1 + g / 8, dy, dz, -b / 8 > f
        s = int((g + a + b - 1) / (a + b)); x0 = a * s / 8; x1 = 1 + (g - b * s) / 8
        line = "first collision at step %d: objects 0 and 1, contact box (%g, %g, %g) (%g, %g, %g)\n"
        ylo = dy > 0 ? dy - 0.5 : -0.5; yhi = dy < 0 ? dy + 0.5 : 0.5
        zlo = dz > 0 ? dz - 0.5 : -0.5; zhi = dz < 0 ? dz + 0.5 : 0.5
        printf line, s, x1 - 0.5, ylo, zlo, x0 + 0.5, yhi, zhi
    }' > "$tmp/first.want"
    "$sim" --first --quiet "$tmp/first.scene" > "$tmp/first.got" 2> /dev/null
    check "--first, gap $1/8, speeds $2/8 and $3/8: exit 0" [ $? -eq 0 ]
    check "--first, gap $1/8, speeds $2/8 and $3/8: want $(cat "$tmp/first.want"), got $(cat "$tmp/first.got")" \
        cmp -s "$tmp/first.got" "$tmp/first.want"
}
first_case 32 2 3 0 0         # ceil(32 / 5) = 7; the boxes overlap by 0.375
first_case 16 2 2 0 0         # 16 / 4 = 4: touching faces count
first_case 24 1 0 0.25 -0.5   # cube 1 still, offset on y and z: step 24
first_case 12 3 2 -0.75 0.125 # ceil(12 / 5) = 3

expect_run 0 '^first collision at step 3: objects 0 and 2, contact box (1.25, -0.5, -0.5) (1.25, 0.5, 0.5)$' \
    --first --quiet "$tmp/three.scene"
# It stops there: no event after step 3, no summary.
"$sim" --first --events --quiet "$tmp/three.scene" > "$tmp/out" 2>&1
check "--first --events: the begin at step 3, then the line" \
    [ "$(cat "$tmp/out")" = "3 begin 0 2
first collision at step 3: objects 0 and 2, contact box (1.25, -0.5, -0.5) (1.25, 0.5, 0.5)" ]
expect_run 0 '^no collision in 2 steps$' --first --steps 2 --quiet "$tmp/three.scene"
"$sim" --first --steps 2 --quiet "$tmp/three.scene" > "$tmp/out" 2>&1
check "--first without a collision: one line, no summary" [ "$(wc -l < "$tmp/out")" -eq 1 ]
# Sensors' pairs are not collisions.
expect_run 0 '^no collision in 100 steps$' --first --steps 100 --quiet "$tmp/sensor.scene"
# Overlapping before the first step: that is step 1.
cat > "$tmp/overlap.scene" <<'SCENE'
mesh cube box 0.5 0.5 0.5
object cube 0 0 0
object cube 0.5 0.25 0
SCENE
expect_run 0 '^first collision at step 1: objects 0 and 1, contact box (0, -0.25, -0.5) (0.5, 0.5, 0.5)$' \
    --first "$tmp/overlap.scene"
# Two pairs meet at step 8: the first in the world's order, 0-3, not 1-2.
cat > "$tmp/two-pairs.scene" <<'SCENE'
mesh cube box 0.5 0.5 0.5
object cube 0 0 0    velocity 0.25 0 0
object cube 0 10 0   velocity 0.25 0 0
object cube 3 10 0   type static
object cube 3 0 0    type static
SCENE
expect_run 0 '^first collision at step 8: objects 0 and 3, contact box (2.5, -0.5, -0.5) (2.5, 0.5, 0.5)$' \
    --first "$tmp/two-pairs.scene"

# With sub-steps the plates of fast.scene meet and part within step 6
# (ceil(10.1 / 2)): in the events, not in the colliding list at the step's
# end, which is all --first and --report see; a warning says so.
expect_run 0 "^noctree-sim: warning: step 6: objects 0 and 1 met and parted within the step's sub-steps; --first sees only" \
    --quiet --substep --first "$tmp/fast.scene"
expect_run 0 '^no collision in 10 steps$' --quiet --substep --first "$tmp/fast.scene"
expect_run 0 "^noctree-sim: warning: step 6: objects 0 and 1 met and parted within the step's sub-steps; the report lists only" \
    --quiet --substep --report csv "$tmp/fast.scene"
"$sim" --quiet --report csv --steps 20 "$tmp/three.scene" 2>&1 | grep -q 'met and parted' &&
    fail "--report: a parting warning without sub-steps" || ok

# Bad usage: exit 2.
expect_run 2 'give one scene' --quiet
expect_run 2 "unknown scene 'nope:3'" --scene nope:3
expect_run 2 "unknown scene 'planes:-1'" --scene planes:-1
expect_run 2 "unknown scene 'gas:x'" --scene gas:x
expect_run 2 "'--N must be a positive integer\|--N must be" --scene planes:1 --N 0
expect_run 2 '--steps must be' --scene planes:1 --steps abc
expect_run 2 "unknown option" --scene planes:1 --frob
expect_run 2 '--accuracy must be' --scene planes:1 --accuracy perfect
expect_run 2 "^noctree-sim: --report must be table, csv or gnuplot, not 'xml'$" \
    --scene planes:1 --report xml
expect_run 2 "unknown option or missing value: '--report'" --scene planes:1 --report
expect_run 2 '^noctree-sim: --first and --report cannot be combined$' \
    --scene planes:1 --first --report table
expect_run 2 '^noctree-sim: --output needs --report$' --scene planes:1 --output "$tmp/o.csv"
check "--output without --report: no file made" [ ! -e "$tmp/o.csv" ]
expect_run 2 "^noctree-sim: cannot open '$tmp/no-such-dir/r.csv' for writing: " \
    --scene planes:1 --report csv --output "$tmp/no-such-dir/r.csv"
expect_run 2 "^noctree-sim: --output '$tmp/p.svg': the script would draw its plot over itself" \
    --scene planes:1 --report gnuplot --output "$tmp/p.svg"
# A report that cannot be written: exit 1, as a failed run.
if [ -w /dev/full ]; then
    expect_run 1 "^noctree-sim: cannot write '/dev/full': " \
        --quiet --report csv --output /dev/full "$tmp/three.scene"
fi

# The families made of tracks, and --write-scene: the example files under
# docs/examples/scenes are what the families write, and run the same.
scenes="$top_srcdir/docs/examples/scenes"
"$sim" --scene arms:3 --write-scene "$tmp/arms.scene" > "$tmp/out" 2>&1
check "--write-scene: exit 0, nothing printed" [ $? -eq 0 ] && [ ! -s "$tmp/out" ]
check "--write-scene arms:3 is docs/examples/scenes/arms-3.scene" \
    cmp -s "$tmp/arms.scene" "$scenes/arms-3.scene"
"$sim" --scene keyframes:20 --write-scene - > "$tmp/kf.scene" 2>&1
check "--write-scene - keyframes:20 is docs/examples/scenes/keyframes-20.scene" \
    cmp -s "$tmp/kf.scene" "$scenes/keyframes-20.scene"
"$sim" --quiet --events --scene arms:3 > "$tmp/fam.events" 2>&1
"$sim" --quiet --events "$scenes/arms-3.scene" > "$tmp/file.events" 2>&1
check "arms:3: the family and its file give the same events" \
    sh -c "grep -E '^[0-9]+ (begin|end)' '$tmp/fam.events' > '$tmp/fam.e'; grep -E '^[0-9]+ (begin|end)' '$tmp/file.events' > '$tmp/file.e'; [ -s '$tmp/fam.e' ] && cmp -s '$tmp/fam.e' '$tmp/file.e'"
check "arms:3: the arms' tips (objects 16 and 19) touch from step 1 and part at 9" \
    sh -c "grep -q '^1 begin 16 19\$' '$tmp/fam.events' && grep -q '^9 end 16 19\$' '$tmp/fam.events'"
expect_run 0 '^first collision at step 1: objects 16 and 19, contact box ' \
    --quiet --first --scene arms:3
"$sim" --quiet --events --maintenance rebuild "$scenes/keyframes-20.scene" > "$tmp/kf1" 2>&1
"$sim" --quiet --events --N big "$scenes/keyframes-20.scene" > "$tmp/kf2" 2>&1
check "keyframes-20: the same events whatever the tree" \
    sh -c "grep -E '^[0-9]+ (begin|end)' '$tmp/kf1' > '$tmp/kf1e'; grep -E '^[0-9]+ (begin|end)' '$tmp/kf2' > '$tmp/kf2e'; [ -s '$tmp/kf1e' ] && cmp -s '$tmp/kf1e' '$tmp/kf2e'"
expect_run 2 "^noctree-sim: /nonexistent/x.scene: cannot open" \
    --scene arms:1 --write-scene /nonexistent/x.scene
expect_run 2 "unknown scene 'arms:9'" --scene arms:9
expect_run 2 "unknown scene 'keyframes:0'" --scene keyframes:0

# The margin: the near pairs include the colliding ones, step by step, and
# there are more of them; their events are printed.
"$sim" --quiet --margin 0.3 --report csv --output "$tmp/near.csv" --scene arms:3 \
    > "$tmp/near.out" 2>&1
check "--margin: exit 0" [ $? -eq 0 ]
check "--margin: the summary counts the near events" grep -q '^near begins [1-9]' "$tmp/near.out"
check "--margin --report csv: every colliding pair is near at its step" \
    awk -F, 'NR > 1 { if ($2 == "collide") c[$1 "," $3 "," $4] = 1; else if ($2 == "near") n[$1 "," $3 "," $4] = 1 }
        END { for (k in c) { if (!(k in n)) exit 1; cc++ } for (k in n) nn++; exit !(cc > 0 && nn > cc) }' \
    "$tmp/near.csv"
"$sim" --quiet --margin 0.3 --events --scene arms:3 > "$tmp/near.ev" 2>&1
check "--margin --events: near-begin 16 19 at step 1" grep -q '^1 near-begin 16 19$' "$tmp/near.ev"
check "--margin --events: near-end lines" grep -q '^[0-9]* near-end [0-9]* [0-9]*$' "$tmp/near.ev"
"$sim" --quiet --events --scene arms:3 > "$tmp/nomargin.ev" 2>&1
check "no margin: no near events" sh -c "! grep -q near '$tmp/nomargin.ev'"
expect_run 2 "^noctree-sim: --margin must be a distance" --margin -1 --scene arms:1
expect_run 2 "^noctree-sim: --margin must be a distance" --margin nan --scene arms:1


# ---- names, objects' margins, --distance, --near-distances -------------------
# three.scene with names for two of its cubes: the same rows, by name.
sed -e '3s/$/ name left/' -e '4s/$/ name right/' "$tmp/three.scene" > "$tmp/named.scene"
sed -e 's/,0,/,left,/; s/,0$/,left/; s/,1,/,right,/; s/,1$/,right/' "$tmp/want.csv" \
    > "$tmp/want-named.csv"
"$sim" --report csv --steps 20 --quiet "$tmp/named.scene" 2> /dev/null | tail -n +2 \
    > "$tmp/named.csv"
check "names: the csv rows name the objects (indices for the unnamed)" \
    cmp -s "$tmp/named.csv" "$tmp/want-named.csv"
check "names: the oracle's rows hold names" grep -q '^9,collide,right,2$' "$tmp/want-named.csv"
expect_run 0 '^ *8  *collide  *2  *left-right left-2$' --report table --steps 20 --quiet \
    "$tmp/named.scene"
expect_run 0 '^first collision at step 3: objects left and 2, contact box ' --first --quiet \
    "$tmp/named.scene"
expect_run 0 '^8 begin left right$' --events --quiet --steps 20 "$tmp/named.scene"
expect_run 0 '^13 end left right$' --events --quiet --steps 20 "$tmp/named.scene"
"$sim" --write-scene "$tmp/named2.scene" "$tmp/named.scene"
check "names: written back" grep -q ' name right$' "$tmp/named2.scene"
"$sim" --events --quiet --steps 20 "$tmp/named2.scene" 2>&1 | grep ' begin \| end ' \
    > "$tmp/named2.ev"
"$sim" --events --quiet --steps 20 "$tmp/named.scene" 2>&1 | grep ' begin \| end ' \
    > "$tmp/named.ev"
check "names: the written scene gives the same events" \
    sh -c "[ -s '$tmp/named.ev' ] && cmp -s '$tmp/named.ev' '$tmp/named2.ev'"
printf 'mesh c box 1 1 1\nobject c 0 0 0 name x\nobject c 5 0 0 name x\n' > "$tmp/dup.scene"
expect_run 2 "dup.scene:3: object name 'x' is taken (line 2)" "$tmp/dup.scene"
printf 'mesh c box 1 1 1\nobject c 0 0 0 name 12\n' > "$tmp/badname.scene"
expect_run 2 "badname.scene:2: bad object name '12'" "$tmp/badname.scene"
printf 'mesh c box 1 1 1\nobject c 0 0 0 margin -1\n' > "$tmp/badmargin.scene"
expect_run 2 "badmargin.scene:2: object margin -1: it must be 0 to" "$tmp/badmargin.scene"

# --distance: a unit cube at the origin and a slab of half-extents
# (1, 0.5, 0.25) at (4.5, 4, 0) moving by -1/8 along x: after step s the
# gaps are 3 on y and max(0, 3 - s/8, -(4 + s/8)...) on x (every position
# exact), so the distance is sqrt(gx^2 + 9); the nearest points have y 0.5
# and 3.5.
cat > "$tmp/dist.scene" <<'SCENE'
effects motion
steps 40
mesh cube box 0.5 0.5 0.5
mesh slab box 1 0.5 0.25
object cube 0 0 0 type static name a
object slab 4.5 4 0 velocity -0.125 0 0 name b
object cube 0.25 0.25 0 type static
SCENE
"$sim" --quiet --distance a b "$tmp/dist.scene" > "$tmp/dist.out" 2>&1
check "--distance: exit 0" [ $? -eq 0 ]
check "--distance: a line at the start and after each of the 40 steps" \
    [ "$(grep -c '^[0-9]* distance a b ' "$tmp/dist.out")" -eq 41 ]
check "--distance: the closed form, inside the proved interval, with the nearest points" \
    awk '$2 == "distance" {
        s = $1; x = 4.5 - s / 8; gx = x - 1 - 0.5; if (-0.5 - (x + 1) > gx) gx = -0.5 - (x + 1)
        if (gx < 0) gx = 0
        want = sqrt(gx * gx + 9); d = $5; lo = substr($6, 2) + 0; hi = $7 + 0
        if (d - want > 1e-12 || want - d > 1e-12 || lo > want + 1e-15 || hi < want - 1e-15) exit 1
        if ($8 != "points" || $10 != "0.5," || $13 != "3.5,") exit 1
        n++
    } END { exit n != 41 }' "$tmp/dist.out"
expect_run 0 '^0 distance a b 4.2426406871192' --quiet --distance 0 1 --steps 1 "$tmp/dist.scene"
expect_run 0 '^24 distance b a 3 ' --quiet --distance b a "$tmp/dist.scene"
expect_run 0 '^0 distance a 2 0 \[0, 0\] colliding$' --quiet --distance a 2 --steps 1 \
    "$tmp/dist.scene"
expect_run 2 "^noctree-sim: --distance: no object 'c'" --distance a c "$tmp/dist.scene"
expect_run 2 "^noctree-sim: --distance: no object '3'" --distance a 3 "$tmp/dist.scene"
expect_run 2 "give one scene" --distance a "$tmp/dist.scene"

# Objects' margins and --near-distances: cubes 0.25 and 0.5 thick skins,
# the second coming at 1/8 a step from 4: 3 - s/8 apart after step s,
# near from step 18 (0.75 = 0.25 + 0.5), colliding from 24 to 30.
cat > "$tmp/skins.scene" <<'SCENE'
effects motion events
steps 30
mesh cube box 0.5 0.5 0.5
object cube 0 0 0 type static margin 0.25 name left
object cube 4 0 0 velocity -0.125 0 0 margin 0.5 name right
object cube 0 5 0 type static
SCENE
awk 'BEGIN { for (s = 1; s <= 30; ++s) { d = 3 - s / 8; if (d < 0) d = 0
    if (d == 0) printf "%d,collide,left,right,\n", s
    if (d <= 0.75) printf "%d,near,left,right,%s\n", s, d } }' > "$tmp/want-skins.csv"
"$sim" --quiet --report csv --near-distances "$tmp/skins.scene" > "$tmp/skins.csv" \
    2> "$tmp/skins.err"
check "--near-distances csv: the header has a distance" \
    [ "$(head -1 "$tmp/skins.csv")" = "step,kind,a,b,distance" ]
tail -n +2 "$tmp/skins.csv" | sort -t, -k1,1n -k2,2 > "$tmp/skins.rows"
sort -t, -k1,1n -k2,2 "$tmp/want-skins.csv" > "$tmp/want-skins.rows"
check "objects' margins: near by their skins, with the closed-form distances" \
    cmp -s "$tmp/skins.rows" "$tmp/want-skins.rows"
check "objects' margins: the summary counts the near pair" \
    grep -q '^near begins 1$' "$tmp/skins.err"
expect_run 0 '^ *19  *near  *1  *left-right(0.625)$' --quiet --report table --near-distances \
    "$tmp/skins.scene"
expect_run 0 '^18 near-begin left right distance 0.75$' --quiet --events --near-distances \
    "$tmp/skins.scene"
expect_run 0 '^18 near-begin left right$' --quiet --events "$tmp/skins.scene"
"$sim" --quiet --events "$tmp/three.scene" > "$tmp/noskins.ev" 2>&1
check "no margins: no near events" sh -c "! grep -q near '$tmp/noskins.ev'"
expect_run 2 "^noctree-sim: --near-distances needs" --near-distances "$tmp/skins.scene"
expect_run 2 "^noctree-sim: --near-distances needs" --near-distances --report gnuplot \
    "$tmp/skins.scene"

# --contacts: cube b overlaps cube a by 0.25 along x (and is shifted 0.25
# along y), so the contact is convex, 0.25 deep along +x, at the four
# corners of the overlap's middle section x = 0.375.
printf 'steps 1\nmesh cube box 0.5 0.5 0.5\nobject cube 0 0 0 type static name a\nobject cube 0.75 0.25 0 type static name b\nobject cube 5 0 0 type static\n' \
    > "$tmp/contact.scene"
"$sim" --quiet --contacts "$tmp/contact.scene" > "$tmp/contact.out" 2>&1
check "--contacts: exit 0" [ $? -eq 0 ]
check "--contacts: the pair by name, convex, 0.25 deep along +x" \
    grep -q '^1 contact a b convex depth 0.25 normal 1 -\{0,1\}0 -\{0,1\}0$' "$tmp/contact.out"
check "--contacts: the overlap's four corners at x = 0.375" \
    sh -c "[ \"\$(grep -c '^1 point 0.375 \(0.5\|-0.25\) \(0.5\|-0.5\) 0.25$' '$tmp/contact.out')\" -eq 4 ]"
check "--contacts: one contact, for the one colliding pair" \
    [ "$(grep -c ' contact ' "$tmp/contact.out")" -eq 1 ]

finish sim
