#!/bin/sh
# SPDX-License-Identifier: MIT
# Lint man pages (CI, after make doc): groff's and man's warnings; words
# glued to a reference (a .BR-style line with more arguments than its
# alternation means, as ".BR foo (3)). A world" renders "(3)).Aworld",
# and a word after an argument that ends a clause, quoted or not);
# and Doxygen headings that landed inside a Returns section (an @post
# inside @return). Usage: manlint.sh PAGE...; exit 1 if any page is off.
# PAGE may be gzipped, as installed.
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
    # an installed page may be compressed
    src=$f
    case $f in *.gz) src=$(mktemp) && gzip -dc "$f" > "$src" ;; esac
    awk -v f="$f" '
        # split a request line into arguments, minding double quotes:
        # arg[i] without its quotes, quoted[i] whether it had them
        function args(line,   n, i, c, q) {
            n = 0; q = 0
            for (i = 1; i <= length(line); ++i) {
                c = substr(line, i, 1)
                if (q) {
                    if (c != "\"") arg[n] = arg[n] c
                    else if (substr(line, i + 1, 1) == "\"") { arg[n] = arg[n] c; ++i }
                    else q = 0
                } else if (c == " " || c == "\t") {
                    sep = 1
                } else {
                    if (n == 0 || sep) { ++n; arg[n] = ""; quoted[n] = c == "\""; sep = 0 }
                    if (c == "\"") q = 1; else arg[n] = arg[n] c
                }
            }
            return n
        }
        /^\.(BR|IR|RB|RI|BI|IB) / && !/"/ && NF >= 6 {
            print f ": " FNR ": words glued to a reference: " $0; bad = 1; next }
        # alternating fonts join their arguments without spaces: a word
        # after an argument that ends a clause, as in ".BR x (3)). A world"
        # or ".BR \"a b\" . A step", is prose glued on
        /^\.(BR|IR|RB|RI|BI|IB)[ \t]/ {
            sep = 0; n = args(substr($0, 4))
            for (i = 1; i < n; ++i)
                if (!quoted[i] && arg[i] ~ /[.,;)]$/ &&
                    !quoted[i + 1] && arg[i + 1] ~ /^[A-Za-z]/) {
                    print f ": " FNR ": words glued to a reference: " $0; bad = 1; break }
        }
        /\\fBReturns\\fP/ { ret = 1; next }
        ret && /^\.RE/ { ret = 0 }
        ret && /\\fB(Postcondition|Precondition|Note|See also)\\fP/ {
            print f ": " FNR ": a heading inside Returns"; bad = 1 }
        END { exit bad }' "$src" || status=1
    [ "$src" = "$f" ] || rm -f "$src"
done
exit $status
