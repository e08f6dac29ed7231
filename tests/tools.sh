#!/bin/sh
# SPDX-License-Identifier: MIT
# octprint and noctree-bench end to end: octprint's tree text against the
# objects of the scene, its dot and SVG output, noctree-bench --quick's
# tables and CSV files, and exit status 2 with a message for bad usage;
# noctree-mesh's inspection, repair and exit statuses on STL files.
set -u
. "${srcdir:-.}/lib.sh"
octprint="$top_builddir/tools/octprint"
bench="$top_builddir/tools/noctree-bench"

# ---- octprint ------------------------------------------------------------

"$octprint" --scene planes:3 --step 60 --N 10 --max-depth 10 --dot "$tmp/t3.dot" \
    --svg "$tmp/t3.svg" > "$tmp/t3.txt" 2> "$tmp/err"
check "octprint planes:3 --step 60 exits 0" [ $? -eq 0 ]
check "octprint: nothing on stderr" [ ! -s "$tmp/err" ]
check "octprint: header names 98 objects and step 60" \
    grep -q '^# planes:3, N = 10, max depth 10, step 60: 98 objects' "$tmp/t3.txt"
check "octprint: a split tree at N = 10" [ "$(wc -l < "$tmp/t3.txt")" -gt 9 ]
# At the defaults the world chooses: N = 128 holds t3's 98 cubes in the root.
"$octprint" --scene planes:3 --step 60 > "$tmp/auto.txt"
check "octprint: the defaults say what was chosen" \
    grep -q '^# planes:3, N = 128 (auto), max depth [0-9]* (auto), step 60: 98 objects' \
    "$tmp/auto.txt"
check "octprint: the defaults' tree is the root" [ "$(wc -l < "$tmp/auto.txt")" -eq 2 ]
check "octprint: one root line" [ "$(grep -c '^OMEGA 0: ' "$tmp/t3.txt")" -eq 1 ]
# Every node line: indentation of two spaces per generation, a child type,
# the generation, the cube; the node count is 1 + 8 * (split nodes).
awk 'NR > 1 {
        match($0, /^ */); ind = RLENGTH
        if ($0 !~ /^ *(OMEGA|[LR][DU][BF]) [0-9]+: lo \([^)]*\) size [0-9.e+-]+(; objects( [0-9]+)+)?$/)
            { print "bad line " NR ": " $0; bad = 1 }
        split($0, w, " "); g = w[2]; sub(":", "", g)
        if (ind != 2 * g) { print "bad indent " NR; bad = 1 }
        nodes++; if (g > maxg) maxg = g
     } END { exit bad }' "$tmp/t3.txt" > "$tmp/awk" 2>&1
check "octprint: every line well formed ($(head -1 "$tmp/awk"))" [ ! -s "$tmp/awk" ]
# Leaves are the nodes not followed by a deeper line; all 98 objects appear.
objs=$(grep -o 'objects.*' "$tmp/t3.txt" | tr ' ' '\n' | grep -E '^[0-9]+$' | sort -un | wc -l)
check "octprint: the leaves hold all 98 objects (got $objs)" [ "$objs" -eq 98 ]
nodes=$(($(wc -l < "$tmp/t3.txt") - 1))
check "octprint: node count is 1 mod 8 ($nodes)" [ $((nodes % 8)) -eq 1 ]
check "octprint: dot has one node per tree node" \
    [ "$(grep -c '^  n[0-9]* \[label' "$tmp/t3.dot")" -eq "$nodes" ]
check "octprint: dot has nodes-1 edges" \
    [ "$(grep -c -- '->' "$tmp/t3.dot")" -eq $((nodes - 1)) ]
check "octprint: dot is closed" [ "$(tail -1 "$tmp/t3.dot")" = "}" ]
if command -v dot > /dev/null 2>&1; then
    check "octprint: graphviz reads the dot" dot -Tsvg "$tmp/t3.dot" -o "$tmp/t3-dot.svg"
fi
check "octprint: the SVG is closed" [ "$(tail -1 "$tmp/t3.svg")" = "</svg>" ]
# The z = 0 slice cuts one cube per (plane, row): 2 * 7 = 14 boxes.
check "octprint: the slice draws 14 cubes" \
    [ "$(grep -c '<title>object ' "$tmp/t3.svg")" -eq 14 ]
"$octprint" --scene planes:3 --step 60 --N big > "$tmp/big.txt"
check "octprint --N big: the root is the only node" [ "$(wc -l < "$tmp/big.txt")" -eq 2 ]
expect_prog "$octprint" 0 '^usage' --help
expect_prog "$octprint" 0 '^octprint [0-9]' --version
expect_prog "$octprint" 2 'give one scene' --step 3
expect_prog "$octprint" 2 '^octprint: --step must be 0 to' --scene planes:1 --step -4
expect_prog "$octprint" 2 '^octprint: --slice must look like' --scene planes:1 --slice w=2
expect_prog "$octprint" 2 '^octprint: --N must be' --scene planes:1 --N 0
expect_prog "$octprint" 2 "unknown option" --scene planes:1 --frobnicate
printf 'steps 10\nobject cube 0 0 0\n' > "$tmp/bad.scene"
expect_prog "$octprint" 2 "^octprint: $tmp/bad.scene:2:" "$tmp/bad.scene"
expect_prog "$octprint" 1 '^octprint: /nonexistent/t.svg:' --scene planes:1 --svg /nonexistent/t.svg

# ---- noctree-bench --quick -------------------------------------------------

out="$tmp/bench"
"$bench" --quick --all --out "$out" > "$tmp/bench.txt" 2> "$tmp/bench.err"
check "noctree-bench --quick --all exits 0" [ $? -eq 0 ]
check "bench: nothing on stderr" [ ! -s "$tmp/bench.err" ]
for title in 'Table 1, reproduced' 'At scale' 'Where the time goes' 'What accuracy costs'; do
    check "bench: section '$title'" grep -q "== $title" "$tmp/bench.txt"
done
# Table 1: rows N=5 ... N=50, the defaults (auto) and N=big over sets t0 ... t3.
check "bench: table rows" \
    [ "$(grep -c '^N=\(5\|10\|30\|50\|auto\|big\) ' "$tmp/bench.txt")" -eq 12 ]
check "bench: set header" grep -q '^set  *t0  *t1  *t2  *t3$' "$tmp/bench.txt"
check "bench: the verdict line" \
    grep -q '^\(smallest set at which the octree is significantly faster: \|no set at which\)' \
    "$tmp/bench.txt"
# CSV files: a header and one row per run (4 sets x 6 settings x 3 repeats;
# the scale section: 2 sets).
check "bench: table1.csv rows" [ "$(wc -l < "$out/table1.csv")" -eq 73 ]
check "bench: scale.csv rows" [ "$(wc -l < "$out/scale.csv")" -eq 37 ]
check "bench: table1-stats.csv rows" [ "$(wc -l < "$out/table1-stats.csv")" -eq 5 ]
check "bench: accuracy.csv rows (5 scenes x 8 rungs)" [ "$(wc -l < "$out/accuracy.csv")" -eq 41 ]
check "bench: stages.csv rows" [ "$(wc -l < "$out/stages.csv")" -eq 3 ]
# Every run of a set found the same contact-begin count, whatever N.
check "bench: begins agree across N" \
    [ "$(awk -F, 'NR > 1 { print $1, $9 }' "$out/table1.csv" | sort -u | wc -l)" -eq 4 ]
# Closed forms: t_k in 20 steps has no begins yet (the first at step 51).
check "bench: no begins within 20 steps" \
    [ "$(awk -F, 'NR > 1 && $9 != 0' "$out/table1.csv" | wc -l)" -eq 0 ]
# The reference row (exact continuous) has no error against itself; the box
# level in the notch scene has false collisions; on the tunnelling scene the
# exact level without sub-steps misses contacts.
check "bench: reference row is error free" \
    [ "$(awk -F, '$3 == "continuous" && ($8 + $9 + $11 + $12 + $13) != 0' "$out/accuracy.csv" | wc -l)" -eq 0 ]
check "bench: box level errs on notch" \
    [ "$(awk -F, '$1 ~ /^notch/ && $3 == "box" { print $8 }' "$out/accuracy.csv")" -gt 0 ]
check "bench: exact level without sub-steps misses on bullets" \
    [ "$(awk -F, '$1 ~ /^bullets/ && $3 == "exact" { print $9 }' "$out/accuracy.csv")" -gt 0 ]
# The turning scene: the continuous rung is the conservative one, against
# which misses are counted (so it misses nothing by definition), and the
# exact level without sub-steps misses there too.
check "bench: the turning scene's continuous rung is conservative" \
    [ "$(awk -F, '$1 ~ /[+]spin$/ && $3 == "conservative continuous" && $9 == 0 && $11 == 0' "$out/accuracy.csv" | wc -l)" -eq 1 ]
check "bench: exact level without sub-steps misses on the turning scene" \
    [ "$(awk -F, '$1 ~ /[+]spin$/ && $3 == "exact" { print $9 }' "$out/accuracy.csv")" -gt 0 ]
check "bench: exact k=32 has every entry of the conservative rung's" \
    grep -q "its entries the conservative rung lacks: 0$" "$tmp/bench.txt"
check "bench: error is false + missed + begins missed" \
    [ "$(awk -F, 'NR > 1 && $13 != $8 + $9 + $11' "$out/accuracy.csv" | wc -l)" -eq 0 ]
# The broadphase's settings are costs only: the same answers at every N and depth.
check "bench: accuracy-settings.csv rows (2 rungs x 4 settings)" \
    [ "$(wc -l < "$out/accuracy-settings.csv")" -eq 9 ]
check "bench: the broadphase's settings change no answer" \
    [ "$(awk -F, 'NR > 1 && $6 != 0' "$out/accuracy-settings.csv" | wc -l)" -eq 0 ]
check "bench: continuous against exact printed" \
    grep -q '^exact .* ms/step, continuous .* ms/step: .* times' "$tmp/bench.txt"
# The Pareto front, recomputed here from accuracy.csv: the rungs that no rung
# of the same scene matches or beats in time and error (the error column) while
# beating them in one; listed cheapest first, the error falling along it, and
# ending error free (the reference has no error against itself), but on the
# turning scene, where no rung is exact.
check "bench: accuracy-front.csv is the Pareto front" \
    [ "$(awk -F, 'NR > 1 { n++; s[n] = $1; t[n] = $6; e[n] = $13; r[n] = $3 }
        END { for (i = 1; i <= n; i++) { d = 0
                for (j = 1; j <= n; j++)
                    if (s[j] == s[i] && t[j] <= t[i] && e[j] <= e[i] && (t[j] < t[i] || e[j] < e[i])) d = 1
                if (!d) print s[i] "," r[i] } }' "$out/accuracy.csv" | sort)" = \
      "$(awk -F, 'NR > 1 { print $1 "," $2 }' "$out/accuracy-front.csv" | sort)" ]
check "bench: the front trades time for error and ends error free" \
    [ "$(awk -F, 'NR > 1 && $1 == s && ($3 < t || $4 > e) { bad++ }
                  NR > 1 && $1 != s && s != "" && e != 0 && s !~ /[+]spin$/ { bad++ }
                  NR > 1 { s = $1; t = $3; e = $4 }
                  END { print bad + (e != 0 && s !~ /[+]spin$/) }' "$out/accuracy-front.csv")" -eq 0 ]
if command -v gnuplot > /dev/null 2>&1; then
    for p in fig9 fig10 scaling accuracy; do
        check "bench: $p.svg drawn" grep -q '</svg>' "$out/$p.svg"
    done
else
    check "bench: says plots were skipped" grep -q 'plots skipped' "$tmp/bench.txt"
fi
expect_prog "$bench" 0 '^usage' --help
check "bench: --help lists the rungs and the tunnelling scene" \
    sh -c '"$1" --help | grep -q "exact k=8" && "$1" --help | grep -q "bullets:1000" &&
           "$1" --help | grep -q "gas:1000+spin"' sh "$bench"
expect_prog "$bench" 2 '^noctree-bench: --repeats must be 2 to 64' --repeats 1
expect_prog "$bench" 2 '^noctree-bench: --sections takes' --sections table1,nope
expect_prog "$bench" 2 '^noctree-bench: --budget must be' --budget nan
expect_prog "$bench" 2 "unknown option" --frobnicate
: > "$tmp/file"
expect_prog "$bench" 2 "is not a folder" --quick --out "$tmp/file"

# ---- octprint on a scene with turned box primitives, velocities, types,
# filters and a sensor (noctree-scene(5)) ----------------------------------

cat > "$tmp/turned.scene" <<'SCENE'
N 2
mesh cube box 0.5 0.5 0.5
mesh bar box 1 0.1 0.1
object cube 0 0 0 1 0 0 0.05
object cube 4 0 0 -1 0 0 0.05
object bar 2 2 0 rotate 0 0 1 30 velocity 0 -0.05 0 filter 1 0xff
object cube 2 -2 0 type static filter 2 1 sensor
SCENE
"$octprint" --step 10 "$tmp/turned.scene" > "$tmp/turned.txt" 2> "$tmp/err"
check "octprint on a turned scene exits 0" [ $? -eq 0 ]
check "octprint: the turned scene's 4 objects at step 10" \
    grep -q 'turned.scene, N = 2, max depth [0-9]* (auto), step 10: 4 objects' "$tmp/turned.txt"

# ---- octprint --broadphase: a bare broadphase of a box file ---------------

# Boxes 0 and 1 overlap on [0.5, 1]^3; box 2 is 3 away from both.
cat > "$tmp/three.boxes" <<'BOXES'
# lo_x lo_y lo_z hi_x hi_y hi_z
0 0 0  1 1 1
0.5 0.5 0.5  2 2 2   # overlaps the first

5 5 5 6 6 6
BOXES
"$octprint" --broadphase "$tmp/three.boxes" > "$tmp/bp.txt" 2> "$tmp/err"
check "octprint --broadphase exits 0" [ $? -eq 0 ]
check "octprint --broadphase: nothing on stderr" [ ! -s "$tmp/err" ]
check "octprint --broadphase: header names the file, the settings chosen and 3 boxes" \
    grep -q "^# $tmp/three.boxes (broadphase), N = 128 (auto), max depth [0-9]* (auto): 3 boxes;" \
    "$tmp/bp.txt"
# N = 128 holds 3 boxes in the root: one leaf with all three.
check "octprint --broadphase: the defaults' tree is one leaf" [ "$(wc -l < "$tmp/bp.txt")" -eq 2 ]
check "octprint --broadphase: the root holds boxes 0 1 2" \
    grep -q '^OMEGA 0: .*; objects 0 1 2$' "$tmp/bp.txt"
# N = 1 splits the root: 1 + 8k nodes of which 1 + 7k leaves; box 2 alone
# in its leaves (a cube that meets box 2 and another is 4 wide or more, and
# holds two boxes at most a quarter of its size: it splits, far above the
# maximum depth 6); boxes 0 and 1 together in the leaves of their common
# cube [0.5, 1]^3, and either may be alone elsewhere.
"$octprint" --N 1 --max-depth 6 --broadphase "$tmp/three.boxes" --dot "$tmp/bp.dot" \
    --svg "$tmp/bp.svg" --slice z=0.75 > "$tmp/bp1.txt"
check "octprint --broadphase --N 1 exits 0" [ $? -eq 0 ]
check "octprint --broadphase --N 1: header" \
    grep -q "^# $tmp/three.boxes (broadphase), N = 1, max depth 6: 3 boxes;" "$tmp/bp1.txt"
nodes=$(($(wc -l < "$tmp/bp1.txt") - 1))
leaves=$(awk 'NR > 1 { match($0, /^ */); d[NR] = RLENGTH } END {
    for (i = 2; i <= NR; ++i) n += !(i < NR && d[i + 1] > d[i]); print n }' "$tmp/bp1.txt")
full=$(grep -c '; objects' "$tmp/bp1.txt")
check "octprint --broadphase --N 1: the root split ($nodes nodes)" [ "$nodes" -gt 1 ]
check "octprint --broadphase --N 1: 1 + 8k nodes ($nodes)" [ $((nodes % 8)) -eq 1 ]
check "octprint --broadphase --N 1: 1 + 7k leaves ($leaves of $nodes)" \
    [ $((leaves - 1)) -eq $(((nodes - 1) / 8 * 7)) ]
check "octprint --broadphase --N 1: box 2 in no leaf with another" \
    [ "$(grep '; objects' "$tmp/bp1.txt" |
         grep -cEv '; objects (0|1|0 1|1 0|2)$')" -eq 0 ]
check "octprint --broadphase --N 1: box 2 in a leaf" grep -q '; objects 2$' "$tmp/bp1.txt"
check "octprint --broadphase --N 1: boxes 0 and 1 in a leaf" \
    grep -Eq '; objects (0 1|1 0)$' "$tmp/bp1.txt"
check "octprint --broadphase: dot has one node per tree node" \
    [ "$(grep -c '^  n[0-9]* \[label' "$tmp/bp.dot")" -eq "$nodes" ]
check "octprint --broadphase: dot has a box per leaf ($full with boxes)" \
    [ "$(grep -c 'shape=box' "$tmp/bp.dot")" -eq "$leaves" ]
# z = 0.75 cuts boxes 0 and 1, not 2.
check "octprint --broadphase: the slice draws boxes 0 and 1" \
    [ "$(grep -o '<title>object [0-9]*' "$tmp/bp.svg" | tr '\n' ' ')" = \
      "<title>object 0 <title>object 1 " ]
# The same boxes as a world's box primitives make the same tree.
cat > "$tmp/three.scene" <<'SCENE'
mesh a box 0.5 0.5 0.5
mesh b box 0.75 0.75 0.75
object a 0.5 0.5 0.5
object b 1.25 1.25 1.25
object a 5.5 5.5 5.5
SCENE
"$octprint" --N 1 --max-depth 6 "$tmp/three.scene" | tail -n +2 > "$tmp/world1.txt"
check "octprint --broadphase: the tree of a world of the same boxes" \
    sh -c "tail -n +2 '$tmp/bp1.txt' | cmp -s - '$tmp/world1.txt'"
check "octprint --broadphase -: standard input" \
    sh -c "'$octprint' --N 1 --max-depth 6 --broadphase - < '$tmp/three.boxes' | tail -n +2 |
           cmp -s - '$tmp/world1.txt'"
# Bad box files: the file, the line and the problem, exit status 2.
bad_boxes() { # NAME CONTENT PATTERN
    printf "$2" > "$tmp/$1"
    expect_prog "$octprint" 2 "^octprint: $tmp/$1$3" --broadphase "$tmp/$1"
}
bad_boxes short.boxes '0 0 0 1 1 1\n0 0 0 1 1\n' ':2: 5 numbers, want 6'
bad_boxes long.boxes '0 0 0 1 1 1 1\n' ':1: more than 6 numbers'
bad_boxes word.boxes '# ok\n0 0 0 1 one 1\n' ":2: 'one' is not a number"
bad_boxes glued.boxes '0 0 0 1 1 1x\n' ":1: '1x' is not a number"
bad_boxes nan.boxes '0 0 0 1 1 1\n\n0 0 NaN 1 1 1\n' ':3: .*NaN'
bad_boxes inf.boxes '0 0 0 inf 1 1\n' ':1: .*infinite'
bad_boxes range.boxes '0 0 0 1e999 1 1\n' ':1: .*out of range'
bad_boxes inverted.boxes '0 0 0 1 1 1\n0 2 0 1 3 1\n0 3 0 1 1 1\n' ':3: inverted box: lo_y 3 > hi_y 1'
bad_boxes far.boxes '0 0 0 1 1 1e300\n' ':1: .*beyond'
bad_boxes empty.boxes '# no boxes\n\n' ': no boxes'
expect_prog "$octprint" 2 "^octprint: $tmp/none.boxes: No such file" --broadphase "$tmp/none.boxes"
expect_prog "$octprint" 2 '^octprint: --step needs a scene' --broadphase "$tmp/three.boxes" --step 1
expect_prog "$octprint" 2 '^octprint: give a scene or --broadphase FILE, not both' \
    --broadphase "$tmp/three.boxes" --scene planes:1
expect_prog "$octprint" 2 'unknown option or missing value' --broadphase

# ---- noctree-mesh ----------------------------------------------------------

mesh="$top_builddir/tools/noctree-mesh"
# The unit cube as an ASCII STL soup (12 triangles, 36 vertices).
awk 'BEGIN {
    split("0 2 3 1 4 5 7 6 0 1 5 4 2 6 7 3 1 3 7 5 0 4 6 2", q, " ")
    print "solid cube"
    for (f = 0; f < 6; f++)
        for (h = 0; h < 2; h++) {
            a = q[4 * f + 1]; b = q[4 * f + 2 + h]; c = q[4 * f + 3 + h]
            print " facet normal 0 0 0"; print "  outer loop"
            n = split(a " " b " " c, v, " ")
            for (i = 1; i <= 3; i++)
                printf "   vertex %d %d %d\n", v[i] % 2, int(v[i] / 2) % 2, int(v[i] / 4)
            print "  endloop"; print " endfacet"
        }
    print "endsolid cube"
}' > "$tmp/cube.stl"
expect_prog "$mesh" 0 '^solid: yes' "$tmp/cube.stl"
expect_prog "$mesh" 0 '^welded vertices: 28' "$tmp/cube.stl"
expect_prog "$mesh" 0 '^volume: 1$' "$tmp/cube.stl"
# The last face (two facets of 7 lines) removed: open, 4 boundary edges, exit
# status 1.
head -n 71 "$tmp/cube.stl" > "$tmp/open.stl"
echo "endsolid cube" >> "$tmp/open.stl"
expect_prog "$mesh" 1 '^boundary edges: 4 (first' "$tmp/open.stl"
expect_prog "$mesh" 1 '^solid: no: 4 boundary edges' "$tmp/cube.stl" "$tmp/open.stl"
# It loads as a surface, and says so; the closed cube too.
expect_prog "$mesh" 1 '^surface: yes: it loads as a surface (noctMeshReadSurface()' \
    "$tmp/open.stl"
expect_prog "$mesh" 0 '^surface: yes$' "$tmp/cube.stl"
# Inside out (every facet's corners reversed): a solid; --repair turns it.
awk '/vertex/ { v[++n] = $0; if (n == 3) { print v[1]; print v[3]; print v[2]; n = 0 }; next }
     { print }' "$tmp/cube.stl" > "$tmp/inside.stl"
expect_prog "$mesh" 0 '^volume: -1$' "$tmp/inside.stl"
expect_prog "$mesh" 0 '^repaired: 0 duplicates removed, 12 polygons flipped' --repair \
    --output "$tmp/fixed.off" "$tmp/inside.stl"
expect_prog "$mesh" 0 '^volume: 1$' "$tmp/fixed.off"
check "noctree-mesh --output: an OFF of 8 vertices and 12 triangles" \
    [ "$(sed -n 2p "$tmp/fixed.off")" = "8 12 0" ]
# One corner one ulp off: not welded unless within a tolerance.
sed '0,/vertex 1 1 1/s//vertex 1.0000000000000002 1 1/' "$tmp/cube.stl" > "$tmp/ulp.stl"
expect_prog "$mesh" 1 '^solid: no: .*boundary edges' "$tmp/ulp.stl"
expect_prog "$mesh" 0 '^solid: yes' --weld-tolerance 1e-9 "$tmp/ulp.stl"
# Errors: the file and line, exit status 2 (and 2 beats 1).
sed '5s/.*/   vertex 1 0/' "$tmp/cube.stl" > "$tmp/bad.stl"
expect_prog "$mesh" 2 "^noctree-mesh: $tmp/bad.stl:5: expected 3 coordinates" "$tmp/bad.stl"
expect_prog "$mesh" 2 "bad.stl:5:" "$tmp/open.stl" "$tmp/bad.stl"
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty int128 x\nend_header\n' \
    > "$tmp/bad.ply"
expect_prog "$mesh" 2 "bad.ply:4: unsupported PLY property type 'int128'" "$tmp/bad.ply"
expect_prog "$mesh" 2 "none.stl: cannot open" "$tmp/none.stl"
expect_prog "$mesh" 2 'give at least one mesh file'
expect_prog "$mesh" 2 'must be a number >= 0' --weld-tolerance -1 "$tmp/cube.stl"
expect_prog "$mesh" 2 '--output takes one mesh file' --output "$tmp/x.off" "$tmp/cube.stl" \
    "$tmp/open.stl"
expect_prog "$mesh" 0 '^usage: noctree-mesh' --help

finish tools
