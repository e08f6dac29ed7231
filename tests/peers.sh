#!/bin/sh
# SPDX-License-Identifier: MIT
# bench-peers end to end: every library finds the scenes' known numbers of
# contact-begin events (noctree-families(7): (2R + 1)^2 on the planes, where R is the
# last ring whose facing pair met, at step 51 + 2R; 6 212 on gas 1 000 in
# 200 steps), the world driven by the program (--driven) the same as the
# built-in motion, the queries (--queries) the same as FCL's where both
# answer, one CSV row per run, and exit status 2 for bad usage.
set -u
. "${srcdir:-.}/lib.sh"
peers="$top_builddir/tools/bench-peers"

# begins_are FILE SCENE COUNT ROWS: the table has ROWS rows for SCENE, and
# every one of them counts COUNT contact begins (column 9).
begins_are() {
    awk -v s="$2" -v n="$3" -v rows="$4" '$1 == s { r++; if ($9 != n) bad = 1 }
        END { exit bad || r != rows }' "$1"
}

"$peers" --quick --csv "$tmp/q.csv" > "$tmp/q.txt" 2> "$tmp/q.err"
check "bench-peers --quick exits 0" [ $? -eq 0 ]
check "bench-peers: nothing on stderr" [ ! -s "$tmp/q.err" ]
check "bench-peers: planes:3, 3 libraries, 49 begins each" begins_are "$tmp/q.txt" planes:3 49 3
check "bench-peers: gas:1000, 3 libraries, 6212 begins each" \
    begins_are "$tmp/q.txt" gas:1000 6212 3
check "bench-peers: a header and 6 CSV rows" [ "$(wc -l < "$tmp/q.csv")" -eq 7 ]
check "bench-peers: libnoctree is the base (x = -)" \
    grep -q '^planes:3  *98  *libnoctree .* -$' "$tmp/q.txt"

# 55 steps: the facing pairs of rings 0 to 2 have met (steps 51, 53, 55).
"$peers" --steps 55 --repeats 2 --libs libnoctree,fcl-dtree,ode-sap,ode-hash \
    --csv "$tmp/s.csv" planes:3 > "$tmp/s.txt" 2>&1
check "bench-peers --steps 55 exits 0" [ $? -eq 0 ]
check "bench-peers: 4 libraries, 25 begins each" begins_are "$tmp/s.txt" planes:3 25 4
check "bench-peers: 2 repeats x 4 libraries in the CSV" [ "$(wc -l < "$tmp/s.csv")" -eq 9 ]

# The bare broadphases on the same boxes: every library counts the same
# overlapping pairs (the tool fails otherwise), 248 650 on gas:1000.
"$peers" --quick --broadphase > "$tmp/b.txt" 2> "$tmp/b.err"
check "bench-peers --broadphase --quick exits 0" [ $? -eq 0 ]
check "bench-peers --broadphase: nothing on stderr" [ ! -s "$tmp/b.err" ]
check "bench-peers --broadphase: planes:3, 3 libraries, 980 pairs each" \
    begins_are "$tmp/b.txt" planes:3 980 3
check "bench-peers --broadphase: gas:1000, 3 libraries, 248650 pairs each" \
    begins_are "$tmp/b.txt" gas:1000 248650 3

# The world driven by the program (--driven): the same events as the
# built-in motion, one row and one CSV row more per scene, and the line
# that compares the two.
"$peers" --quick --driven --libs libnoctree --csv "$tmp/d.csv" > "$tmp/d.txt" 2> "$tmp/d.err"
check "bench-peers --driven --quick exits 0" [ $? -eq 0 ]
check "bench-peers --driven: nothing on stderr" [ ! -s "$tmp/d.err" ]
check "bench-peers --driven: planes:3, built-in and driven, 49 begins each" \
    begins_are "$tmp/d.txt" planes:3 49 2
check "bench-peers --driven: gas:1000, built-in and driven, 6212 begins each" \
    begins_are "$tmp/d.txt" gas:1000 6212 2
check "bench-peers --driven: a noct-driven row for gas:1000" \
    grep -q '^gas:1000  *1000  *noct-driven ' "$tmp/d.txt"
check "bench-peers --driven: the same events on gas:1000" \
    grep -q '^driven/built-in gas:1000: .* = [0-9.]*; contact begins 6212 and 6212, the same$' \
    "$tmp/d.txt"
check "bench-peers --driven: a header and 4 CSV rows" [ "$(wc -l < "$tmp/d.csv")" -eq 5 ]
check "bench-peers --driven: noct-driven in the CSV" \
    grep -q '^gas:1000,1000,noct-driven,0,200,' "$tmp/d.csv"

# Queries (--queries): libnoctree's and FCL's box queries find the same
# objects (the tool fails otherwise); every kind finds some.
"$peers" --queries 2000 gas:1000 > "$tmp/qq.txt" 2> "$tmp/qq.err"
check "bench-peers --queries exits 0" [ $? -eq 0 ]
check "bench-peers --queries: nothing on stderr" [ ! -s "$tmp/qq.err" ]
check "bench-peers --queries: 8 rows (ours 4, FCL 1, Bullet 3), each found something" \
    awk '$1 == "gas:1000" { r++; if ($NF + 0 <= 0) bad = 1 } END { exit bad || r != 8 }' \
    "$tmp/qq.txt"
check "bench-peers --queries: Bullet's box, all-hits and first-hit rows" \
    sh -c "grep -q '^gas:1000  *bullet  *box ' '$tmp/qq.txt' &&
           grep -q '^gas:1000  *bullet  *segment, all ' '$tmp/qq.txt' &&
           grep -q '^gas:1000  *bullet  *segment, first ' '$tmp/qq.txt'"
check "bench-peers --queries: libnoctree and FCL find the same objects in boxes" \
    awk '$1 == "gas:1000" && $3 == "box" { n[$2] = $NF }
        END { exit !(n["libnoctree"] > 0 && n["libnoctree"] == n["fcl-dtree"]) }' \
    "$tmp/qq.txt"
expect_prog "$peers" 1 'runs on gas scenes only' --queries 10 planes:1

# Triangle soups (--soups): the tool fails if libnoctree's verdict differs
# from its exact check; the solids differ from FCL only where one is
# inside the other, the open surface not at all.
"$peers" --soups 300 > "$tmp/so.txt" 2> "$tmp/so.err"
check "bench-peers --soups exits 0" [ $? -eq 0 ]
check "bench-peers --soups: nothing on stderr" [ ! -s "$tmp/so.err" ]
check "bench-peers --soups: 3 cases of 300 poses, some meeting, libnoctree never wrong" \
    awk 'NF > 8 && $(NF - 8) == 300 { r++; if ($(NF - 7) + 0 <= 0 || $NF != 0) bad = 1 }
        END { exit bad || r != 3 }' "$tmp/so.txt"
check "bench-peers --soups: every difference is a solid inside the other" \
    awk 'NF > 8 && $(NF - 8) == 300 && $(NF - 3) != $(NF - 2) { bad = 1 } END { exit bad }' "$tmp/so.txt"
check "bench-peers --soups: the open surface agrees with FCL everywhere" \
    awk 'NF > 8 && $1 ~ /^open/ && $(NF - 8) == 300 { f = 1; if ($(NF - 3) != 0) bad = 1 }
        END { exit bad || !f }' "$tmp/so.txt"

expect_prog "$peers" 0 '^usage' --help
expect_prog "$peers" 2 'no noct-driven' --broadphase --driven planes:1
expect_prog "$peers" 2 "'planes:x': a scene is planes:K" planes:x
expect_prog "$peers" 2 "'gas:0': a scene is" gas:0
expect_prog "$peers" 2 "unknown library 'bullet'" --libs fcl-dtree,bullet
expect_prog "$peers" 2 'bad option or value: --steps' --steps 0
expect_prog "$peers" 2 "/nonexistent/p.csv:" --csv /nonexistent/p.csv planes:1

finish peers.sh
