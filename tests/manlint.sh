#!/bin/sh
# SPDX-License-Identifier: MIT
# Lint man pages (CI, after make doc): groff's and man's warnings; words
# glued to a reference (a .BR-style line with more arguments than its
# alternation means, as ".BR foo (3)). A world" renders "(3)).Aworld");
# and Doxygen headings that landed inside a Returns section (an @post
# inside @return). Usage: manlint.sh PAGE...; exit 1 if any page is off.
status=0
for f in "$@"; do
    # from the section's parent, where a page's .so requests resolve
    dir=$(dirname "$f")
    w=$(cd "$dir/.." && LC_ALL=C.UTF-8 MANWIDTH=80 \
        man --warnings -l "$(basename "$dir")/$(basename "$f")" 2>&1 >/dev/null)
    if [ -n "$w" ]; then
        printf '%s: %s\n' "$f" "$w"
        status=1
    fi
    awk -v f="$f" '
        /^\.(BR|IR|RB|RI|BI|IB) / && !/"/ && NF >= 6 {
            print f ": " FNR ": words glued to a reference: " $0; bad = 1 }
        /\\fBReturns\\fP/ { ret = 1; next }
        ret && /^\.RE/ { ret = 0 }
        ret && /\\fB(Postcondition|Precondition|Note|See also)\\fP/ {
            print f ": " FNR ": a heading inside Returns"; bad = 1 }
        END { exit bad }' "$f" || status=1
done
exit $status
