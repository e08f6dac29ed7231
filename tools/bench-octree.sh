#!/bin/sh
# SPDX-License-Identifier: MIT
# Run the octree ADT benchmark against both builds and print ns per
# operation side by side with the efficient/defensive ratio.
# Usage: bench-octree.sh [REPEATS [DEPTH]]; the raw CSV goes to
# bench-octree.csv in the current directory.
set -eu
bindir=${BENCH_BINDIR:-$(dirname "$0")}
csv=bench-octree.csv
echo "flavour,operation,ns_per_op,ops_per_repeat" > "$csv"
"$bindir/bench-octree-defensive" "$@" >> "$csv"
"$bindir/bench-octree-efficient" "$@" >> "$csv"
awk -F, '
  NR == 1 { next }
  $1 == "defensive" { def[$2] = $3; order[n++] = $2; ops[$2] = $4 }
  $1 == "efficient" { eff[$2] = $3 }
  END {
    printf "octree ADT, median ns per operation (ops per repeat in brackets)\n"
    printf "%-12s %14s %14s %12s\n", "operation", "defensive", "efficient", "eff/def"
    for (i = 0; i < n; i++) {
      op = order[i]
      printf "%-12s %14.2f %14.2f %12.2f   [%d]\n", op, def[op], eff[op],
             (def[op] > 0 ? eff[op] / def[op] : 0), ops[op]
    }
  }' "$csv"
echo "(raw figures in $csv)"
