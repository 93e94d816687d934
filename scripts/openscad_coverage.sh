#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Which .scad files scadray covers, and whether its geometry agrees with OpenSCAD's mesh of
# them (`scadray check --openscad`). A file is covered when scadray imports it without an
# unsupported-feature warning; that is decided here, at run time, so the list grows with the
# importer.
#
#   scripts/openscad_coverage.sh [-b SCADRAY] [-o OUTDIR] [-W W] [-H H] [FILE...]
#       prints a table (file, covered or the unsupported features, result, differing pixels,
#       OpenSCAD time, scadray time) and the counts. Without FILEs: every example installed with
#       OpenSCAD (/usr/share/openscad/examples, read in place) and every scene under scenes/.
#   scripts/openscad_coverage.sh --test -b SCADRAY -o OUTDIR FILE
#       one file as a test: exit 0 agrees, 1 differs or fails, 77 skipped (no openscad, not
#       covered, or no 3D geometry to compare).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scadray=$here/../build/tools/scadray
out=${TMPDIR:-/tmp}/scadray_openscad_coverage
width=160 height=120 test_mode=0
while [ $# -gt 0 ]; do
    case $1 in
        -b) scadray=$2; shift 2 ;;
        -o) out=$2; shift 2 ;;
        -W) width=$2; shift 2 ;;
        -H) height=$2; shift 2 ;;
        --test) test_mode=1; shift ;;
        -h|--help) sed -n 3,14p "$0"; exit 0 ;;
        -*) echo "unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
if ! command -v openscad >/dev/null 2>&1; then
    echo "SKIPPED: openscad is not installed (scripts/setup.sh installs it)"
    exit 77
fi
if [ ! -x "$scadray" ]; then
    echo "scadray binary not found at $scadray (build it, or pass -b)" >&2
    exit 2
fi
examples=/usr/share/openscad/examples
if [ $# -eq 0 ]; then
    mapfile -t files < <(find "$examples" "$here/../scenes" -name '*.scad' ! -name scadray.scad | sort)
else
    files=("$@")
fi
mkdir -p "$out"

# check_file FILE: sets covered (yes / the unsupported features), result, differing, osc (CGAL),
# osc_wall, ours
# and checklog (what `check --openscad` printed)
check_file() {
    local file=$1 name log csv
    name=$(echo "$file" | sed -e "s|^$examples/||" -e 's|.*/scenes/|scenes/|' -e 's|[/.]|_|g')
    log=$out/$name.log csv=$out/$name.csv checklog=$out/$name.check.log
    covered=yes result=- differing=- osc=- osc_wall=- ours=-
    if ! "$scadray" dump "$file" >/dev/null 2>"$log"; then
        covered="import error: $(grep -m1 error "$log" | sed 's|.*error: ||' | cut -c1-50)"
        return
    fi
    if grep -q "not supported" "$log"; then
        covered=$(grep -o "[a-z_]*() is not supported\|import of [a-z.]* files\|projective" "$log" |
                  sed -e 's/() is not supported/()/' -e 's/ files//' | sort -u | tr '\n' ' ')
        covered="no: ${covered% }"
        # Warnings that name no module: a 2D/3D mix (OpenSCAD's export keeps one dimension, so
        # there is no mesh of what scadray draws) or a twisted 2D boolean (not yet exact)
        if [ "$covered" = "no: " ]; then
            if grep -q "Mixing 2D and 3D" "$log"; then covered="no: 2D and 3D mixed"
            elif grep -q "each is swept" "$log"; then covered="no: twist of 2D booleans"
            else covered="no: $(grep -m1 -o 'warning: .*not supported' "$log" | cut -c10-40)"; fi
        fi
        return
    fi
    rm -f "$csv"
    "$scadray" check --openscad "$file" -W "$width" -H "$height" -o "$out/$name" \
        --csv "$csv" >"$checklog" 2>&1
    local rc=$?
    if [ -s "$csv" ]; then
        IFS=, read -r _ result differing _ _ _ _ _ osc_wall osc ours < <(tail -n1 "$csv")
        osc=$(printf '%.2f' "$osc") osc_wall=$(printf '%.2f' "$osc_wall") ours=$(printf '%.2f' "$ours")
    elif grep -q "empty top level\|2D top level" "$checklog"; then
        result="no 3D geometry"
    else
        result="error (exit $rc): $(grep -m1 'error' "$checklog" | cut -c1-60)"
    fi
}

if [ $test_mode -eq 1 ]; then
    [ ${#files[@]} -eq 1 ] || { echo "--test takes one file" >&2; exit 2; }
    check_file "${files[0]}"
    case $covered in yes) ;; *) echo "SKIPPED: ${files[0]} is not covered ($covered)"; exit 77 ;; esac
    [ "$result" = "no 3D geometry" ] && { echo "SKIPPED: OpenSCAD finds no 3D geometry in ${files[0]}"; exit 77; }
    cat "$checklog"
    echo "$result: ${files[0]}: $differing differing pixels, OpenSCAD $osc s CGAL ($osc_wall s" \
         "wall), scadray $ours s"
    [ "$result" = pass ] && exit 0
    exit 1
fi

total=0 covered_count=0 compared=0 agree=0 osc_sum=0 wall_sum=0 ours_sum=0
printf '%-46s %-28s %-10s %9s %9s %9s %9s\n' file covered result differing \
       osc_cgal_s osc_wall_s scadray_s
for f in "${files[@]}"; do
    check_file "$f"
    total=$((total + 1))
    shown=$(echo "$f" | sed -e "s|^$examples/|examples/|" -e 's|.*/scenes/|scenes/|')
    printf '%-46s %-28s %-10s %9s %9s %9s %9s\n' "$shown" "$covered" "$result" "$differing" \
           "$osc" "$osc_wall" "$ours"
    [ "$covered" = yes ] && covered_count=$((covered_count + 1))
    case $result in
        pass|different)
            compared=$((compared + 1))
            [ "$result" = pass ] && agree=$((agree + 1))
            osc_sum=$(echo "$osc_sum + $osc" | bc) wall_sum=$(echo "$wall_sum + $osc_wall" | bc)
            ours_sum=$(echo "$ours_sum + $ours" | bc) ;;
    esac
done
echo
echo "files: $total; covered by scadray: $covered_count; rendered completely and compared" \
     "with OpenSCAD: $compared; agree with OpenSCAD: $agree"
printf 'time over the compared files: OpenSCAD %.2f s CGAL (%.2f s wall), scadray %.2f s' \
       "$osc_sum" "$wall_sum" "$ours_sum"
echo " (parse, compile, trace ${width}x${height})"
