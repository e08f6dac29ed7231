# SPDX-License-Identifier: MIT
# Shared by the shell tests (sourced): a scratch folder, pass and fail
# counts, and checks of a program's exit status and output.
: "${top_builddir:=..}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0 passes=0

ok() { passes=$((passes + 1)); }
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# check DESCRIPTION COMMAND...: the command succeeds.
check() {
    desc=$1
    shift
    if "$@"; then ok; else fail "$desc"; fi
}

# expect_prog PROGRAM STATUS PATTERN ARGS...: the exit status, and a line
# of the output (stdout and stderr) matching PATTERN.
expect_prog() {
    prog=$1 want=$2 pattern=$3
    shift 3
    "$prog" "$@" > "$tmp/out" 2>&1
    got=$?
    if [ "$got" -ne "$want" ]; then
        fail "${prog##*/} $*: exit $got, want $want"; sed 's/^/  /' "$tmp/out"
    elif ! grep -q -e "$pattern" "$tmp/out"; then
        fail "${prog##*/} $*: no '$pattern' in:"; sed 's/^/  /' "$tmp/out"
    else
        ok
    fi
}

# finish NAME: report and set the exit status.
finish() {
    echo "$1: $passes passed, $fails failed"
    [ "$fails" -eq 0 ]
}
