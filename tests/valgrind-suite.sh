#!/bin/sh
# SPDX-License-Identifier: MIT
# Run one Check suite under valgrind (make check-valgrind runs several of
# these side by side): in one process (no fork), without the death tests
# (they abort by design) and the slow ones; its log is shown if it fails.
# The loops that repeat the same checks on more random data run a
# quarter of their rounds (NOCT_TEST_ROUNDS_DIVISOR=4, read by
# test_rounds() in tests/testutil.c; never below the rounds their
# distinct cases need): plain make check and the sanitizer builds run all.
# It reports the suite's seconds, by which valgrind_first in
# tests/local.mk lists the slowest suites.
# Usage: valgrind-suite.sh LIBTOOL VALGRIND SUITE
set -u
libtool=$1 valgrind=$2 suite=$3
log=$suite.valgrind.log
start=$(date +%s)
if CK_FORK=no CK_EXCLUDE_TAGS='death slow' NOCT_TEST_ROUNDS_DIVISOR=4 \
    $libtool --mode=execute \
    $valgrind -q --error-exitcode=1 --leak-check=full \
    --errors-for-leak-kinds=definite,indirect "./$suite" > "$log" 2>&1; then
    printf 'valgrind %s: %s (%s s)\n' "$suite" "$(grep -E '^[0-9]+%: Checks:' "$log")" \
        "$(($(date +%s) - start))"
    rm -f "$log"
else
    cat "$log"
    printf 'valgrind %s: FAILED\n' "$suite"
    exit 1
fi
