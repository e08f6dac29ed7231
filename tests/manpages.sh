#!/bin/sh
# SPDX-License-Identifier: MIT
# The man pages: tests/manlint.sh catches the errors it is for (checked on
# pages made to have them), and passes the hand-written pages (and the
# generated section 3 pages once make doc made them); every reference to a
# page of the library's (noct*, oct*, NOCT_*, OCT_*) names one that
# exists; and every installed example a page or the README names is one
# that is installed (docs/examples, docs/examples/scenes).
set -u
. "${srcdir:-.}/lib.sh"
src=${top_srcdir:-..}
command -v man > /dev/null 2>&1 || { echo "no man: skipped"; exit 77; }
lint="$src/tests/manlint.sh"

# the lint fails on each kind of error it is for
mkdir "$tmp/man7"
page() { printf '.TH X 7\n.SH NAME\nx \\- y\n.SH DESCRIPTION\n%s\n' "$1" > "$tmp/man7/$2.7"; }
page '.BR noctTrackAt (3)). A world without the
motion effect.' glued
page 'needs
.BR "\-\-accuracy continuous" . A step that would need more' glued-quoted
page '.PP
\fBReturns\fP
.RS 4
NOCT_OK.
.PP
\fBPostcondition\fP
.RS 4
Done.
.RE
.RE' returns
page '.BR noctTrackAt (3)
and
.BR "\-\-accuracy continuous" ,
.IR file : line : " problem"' clean
for bad in glued glued-quoted returns; do
    check "manlint catches $bad" sh -c "! sh '$lint' '$tmp/man7/$bad.7' > /dev/null 2>&1"
done
check "manlint passes a clean page" sh "$lint" "$tmp/man7/clean.7"

# the pages themselves
man3=$top_builddir/docs/man/man3
set -- "$src"/docs/man/*.[157]
# (a page that is only a .so request to its module's page adds nothing)
if [ -d "$man3" ]; then
    for f in "$man3"/*.3; do
        head -n 1 "$f" | grep -q '^\.so ' || set -- "$@" "$f"
    done
fi
check "manlint: the pages" sh "$lint" "$@"

# references to the library's pages name pages that exist: sections 1, 5
# and 7 in docs/man, section 3 among the generated pages (when made)
for f in "$src"/docs/man/*.[157]; do
    sed 's/\\-/-/g' "$f" |
        sed -n 's/^\.[BI]*R* *(\{0,1\} *\([A-Za-z_][A-Za-z0-9_.-]*\) (\([1357]\)).*/\1 \2/p' |
        grep -E '^(noct|oct|NOCT_|OCT_)' | sort -u |
        while read -r name sec; do
            if [ "$sec" = 3 ]; then
                [ -d "$man3" ] || continue
                # a header's page is installed as noctree_world.h (world.h here)
                case $name in noctree_*.h) name=${name#noctree_} ;; esac
                [ -f "$man3/$name.3" ] || echo "${f##*/}: $name($sec): no such page"
            else
                [ -f "$src/docs/man/$name.$sec" ] || echo "${f##*/}: $name($sec): no such page"
            fi
        done
done > "$tmp/refs"
check "references name pages that exist" [ ! -s "$tmp/refs" ]
cat "$tmp/refs"

# installed examples named in the pages and the README are installed
sed 's/\\-/-/g' "$src"/docs/man/*.[157] "$src/README.md" |
    grep -o -e '/usr/share/doc/libnoctree-dev/examples/[A-Za-z0-9._-]*' \
        -e '/usr/share/doc/noctree-tools/examples/scenes/[A-Za-z0-9._-]*' | sed 's/[.]$//' |
    sort -u |
    while read -r path; do
        case $path in
        */libnoctree-dev/examples/*) file=$src/docs/examples/${path##*/examples/} ;;
        *) file=$src/docs/examples/scenes/${path##*/scenes/} ;;
        esac
        case $path in */) continue ;; esac
        grep -q "docs/examples/${file#"$src"/docs/examples/}" "$src/docs/local.mk" ||
            echo "$path: not installed (docs/local.mk)"
        [ -f "$file" ] || echo "$path: no $file"
    done > "$tmp/paths"
check "installed examples named in the pages are installed" [ ! -s "$tmp/paths" ]
cat "$tmp/paths"
finish manpages
