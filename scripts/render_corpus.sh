#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Render every scene the project knows (the test scenes, scenes/ and OpenSCAD's installed
# examples) into OUT: a picture, the scene IR (`dump`) and the POV-Ray export of each, with the
# messages and exit status. Two such folders made by two builds compare byte for byte with
# `render_corpus.sh --compare A B`, which is how a change that must not change any picture
# (a refactoring, a new build option) is checked.
#
#   scripts/render_corpus.sh OUT            # uses build/tools/scadray (SCADRAY=... to override)
#   scripts/render_corpus.sh --compare A B  # exit 0 when every file is the same
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

if [[ ${1:-} == --compare ]]; then
    [[ $# -eq 3 ]] || { echo "usage: $0 --compare A B" >&2; exit 2; }
    a=$2 b=$3
    diff <(cd "$a" && find . -type f | sort) <(cd "$b" && find . -type f | sort) ||
        { echo "the two folders hold different files" >&2; exit 1; }
    n=0 bad=0
    while IFS= read -r f; do
        n=$((n + 1))
        cmp -s "$a/$f" "$b/$f" || { echo "differs: $f"; bad=$((bad + 1)); }
    done < <(cd "$a" && find . -type f | sort)
    echo "$((n - bad)) of $n files identical"
    [[ $bad -eq 0 ]]
    exit
fi

[[ $# -eq 1 ]] || { echo "usage: $0 OUT | --compare A B" >&2; exit 2; }
out=$1
scadray=${SCADRAY:-$root/build/tools/scadray}
[[ -x $scadray ]] || { echo "no scadray at $scadray (build it, or set SCADRAY)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
examples=${OPENSCAD_EXAMPLES:-/usr/share/openscad/examples}

scenes=()
while IFS= read -r f; do scenes+=("$f"); done < <(
    cd "$root" && find tests scenes -not -path 'tests/fuzz/*' \
        \( -name '*.scad' -o -name '*.gltf' -o -name '*.glb' -o -name '*.stl' -o -name '*.off' \) \
        -type f | LC_ALL=C sort)
if [[ -d $examples ]]; then
    while IFS= read -r f; do scenes+=("$f"); done < <(find "$examples" -name '*.scad' -type f | LC_ALL=C sort)
else
    echo "warning: no OpenSCAD examples at $examples (apt-get install openscad)" >&2
fi

for s in "${scenes[@]}"; do
    src=$s
    [[ $s == /* ]] || src=$root/$s
    # One flat name per scene: the path with '/' turned into '__'
    rel=${s#"$examples"/}
    [[ $s == "$rel" ]] || rel=openscad-examples/$rel
    name=${rel//\//__}
    # Outputs are named relative to OUT, so the .ini files and messages are the same wherever
    # OUT lies; messages name the scene by its own path, the same in both runs.
    {
        "$scadray" render -q -t 2 -W 200 -H 150 -o "$name.png" "$src" 2>&1; echo "render exit $?"
        "$scadray" dump "$src" > "$name.ir" 2>&1; echo "dump exit $?"
        "$scadray" export -q -o "$name.pov" "$src" 2>&1; echo "export exit $?"
    } > "$name.log" 2>&1 || true
done
echo "${#scenes[@]} scenes rendered into $out"
