#!/bin/sh
# SPDX-License-Identifier: MIT
# Build the libFuzzer targets of tests/fuzz/ with clang against the
# library's sources, and run each for a while.
#
#   tests/fuzz/run.sh BUILD_TREE [SECONDS [TARGET...]]
#
# BUILD_TREE is a configured build tree (its config.h and version.h are
# used; nothing in it is rebuilt). SECONDS per target, 60 by default.
# Targets: scene off obj stl ply narrowphase (all by default). Everything goes to
# BUILD_TREE/fuzz-out/: the programs fuzz-TARGET, the corpora the runs
# grow (corpus/TARGET; the seeds in the source tree are only read), the
# logs TARGET.log and any crashing input, TARGET-crash-... (or -leak-,
# -timeout-, -oom-). Exits 1 if any target fails, naming the input and
# the command that reproduces it.
#
# Environment: CLANG (default clang), FUZZ_FLAGS (more libFuzzer flags,
# such as -jobs=4 or -max_len=65536), FUZZ_TIMEOUT (seconds one input may
# take before it counts as a failure; default 30).
set -eu

usage() {
    echo "usage: $0 BUILD_TREE [SECONDS [TARGET...]]" >&2
    exit 2
}
[ $# -ge 1 ] || usage
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
[ -f "$1/config.h" ] && [ -f "$1/include/noctree/version.h" ] || {
    echo "$0: $1 is not a configured build tree (no config.h or include/noctree/version.h)" >&2
    exit 2
}
build=$(cd "$1" && pwd)
secs=${2:-60}
case $secs in '' | *[!0-9]*) usage ;; esac
if [ $# -ge 2 ]; then shift 2; else shift; fi
targets=${*:-scene off obj stl ply narrowphase}
cc=${CLANG:-clang}
out=$build/fuzz-out

command -v "$cc" > /dev/null || {
    echo "$0: $cc not found (Debian: apt-get install clang libclang-rt-14-dev)" >&2
    exit 2
}
if [ -z "${ASAN_SYMBOLIZER_PATH:-}" ] && ! command -v llvm-symbolizer > /dev/null; then
    for s in /usr/lib/llvm-*/bin/llvm-symbolizer; do
        [ -x "$s" ] && ASAN_SYMBOLIZER_PATH=$s && export ASAN_SYMBOLIZER_PATH
    done
fi

san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
deps="ccd qhull_r gmp"
# assimp when the build tree was configured with it (lib/meshio_assimp.c)
grep -q '^#define HAVE_ASSIMP 1' "$build/config.h" && deps="$deps assimp"
# shellcheck disable=SC2086 # the list is split on purpose
deps_cflags=$(pkg-config --cflags $deps)
# shellcheck disable=SC2086
deps_libs=$(pkg-config --libs $deps)
cflags="-std=c11 -g -O1 -Wall -Wextra $san -DNOCT_BUILDING -I$build -I$build/include \
-I$top/include -I$top/lib $deps_cflags"

# The library's sources, instrumented for coverage; rebuilt when a source,
# a header or the configuration is newer than the last build.
mkdir -p "$out/lib"
stamp=$out/lib/stamp
if [ ! -f "$stamp" ] ||
   [ -n "$(find "$top/lib" "$top/include" "$build/config.h" "$build/include" \
           -newer "$stamp" -name '*.[ch]' 2>/dev/null | head -n 1)" ]; then
    echo "fuzz: compiling the library with $cc"
    rm -f "$out"/lib/*.o
    for src in "$top"/lib/*.c; do
        # shellcheck disable=SC2086 # flag lists are split on purpose
        $cc $cflags -fsanitize=fuzzer-no-link -c "$src" \
            -o "$out/lib/$(basename "$src" .c).o"
    done
    touch "$stamp"
fi

status=0
for t in $targets; do
    src=$here/fuzz_$t.c
    [ -f "$src" ] || { echo "$0: unknown target '$t'" >&2; exit 2; }
    echo "fuzz: building fuzz-$t"
    # shellcheck disable=SC2086
    $cc $cflags -fsanitize=fuzzer "$src" "$out"/lib/*.o $deps_libs -lm -o "$out/fuzz-$t"
    mkdir -p "$out/corpus/$t" "$out/work"
    dict=
    [ -f "$here/$t.dict" ] && dict=-dict=$here/$t.dict
    rm -f "$out/$t"-crash-* "$out/$t"-leak-* "$out/$t"-timeout-* "$out/$t"-oom-*
    echo "fuzz: running fuzz-$t for $secs s (log: $out/$t.log)"
    # The first corpus folder receives the new inputs; the seeds are read.
    # shellcheck disable=SC2086
    if (cd "$out/work" && "$out/fuzz-$t" -max_total_time="$secs" \
            -timeout="${FUZZ_TIMEOUT:-30}" -print_final_stats=1 \
            -artifact_prefix="$out/$t-" $dict ${FUZZ_FLAGS:-} \
            "$out/corpus/$t" "$here/corpus/$t") > "$out/$t.log" 2>&1; then
        grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE' "$out/$t.log" |
            sed "s/^/fuzz: $t: /" || true
    else
        status=1
        tail -n 40 "$out/$t.log"
        for a in "$out/$t"-crash-* "$out/$t"-leak-* "$out/$t"-timeout-* "$out/$t"-oom-*; do
            [ -f "$a" ] || continue
            echo "fuzz: $t FAILED on $a"
            echo "fuzz: reproduce with: $out/fuzz-$t $a"
        done
    fi
done
exit $status
