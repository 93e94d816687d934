#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `scadray report` in a real browser: headless Chromium loads the page and its own script
# reports (in #report-selfcheck) the table's rows, their order (failures first), how many
# pictures loaded and how many plots were drawn; a screenshot stays in OUT/report.png (the CI
# artifact). Negative control: a picture deleted from beside a --link-images page must count
# as broken. Exit 77 (skipped) without chromium or povray.
set -uo pipefail
scadray=$1 scenes=$2 out=$(realpath -m "$3")
chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
    echo "SKIPPED: Chromium (chromium) is not installed; scripts/setup.sh installs it"
    exit 77
fi
if ! command -v povray >/dev/null 2>&1; then
    echo "SKIPPED: POV-Ray (povray) is not installed; scripts/setup.sh installs it"
    exit 77
fi
rm -rf "$out"
mkdir -p "$out/suite"
fail() {
    echo "FAIL: $*"
    exit 1
}

# The page as Chromium sees it once its script ran (sandbox off: CI runs as root; a fresh
# profile each time)
browse() {
    local profile rc
    profile=$(mktemp -d)
    timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
        --user-data-dir="$profile" --virtual-time-budget=10000 "$@" 2>>"$out/chromium.log"
    rc=$?
    rm -rf "$profile"
    return $rc
}
# The self-check's attributes, e.g. `selfcheck report.html` then `$rows`, `$broken`
selfcheck() {
    local line
    line=$(browse --dump-dom "file://$out/$1" | grep -o '<p id="report-selfcheck"[^>]*>') ||
        fail "no #report-selfcheck in $1 as Chromium rendered it (see $out/chromium.log)"
    for key in done rows verdicts images broken charts; do
        printf -v "$key" '%s' "$(sed -n "s/.* data-$key=\"\([^\"]*\)\".*/\1/p" <<<"$line")"
    done
    [ "$done" = 1 ] || fail "the page's self-check did not finish in $1: $line"
}

# Earlier checks, as a CTest run leaves them: one failing on purpose (margins of 0 and a
# false-alarm rate of 0.5 flag the smallest difference), and the OpenSCAD referee on one scene.
# The failing and the missing scene sort last by name, so only failures-first puts them first
"$scadray" check "$scenes/mirrors.scad" -W 64 -H 48 --margin 0 --margin-rel 0 \
    --alpha 0.5 -q -o "$out/suite/mirrors" >/dev/null
[ -f "$out/suite/mirrors/mirrors_check.json" ] || fail "check left no figures"
pictures=9
if command -v openscad >/dev/null 2>&1; then
    "$scadray" check --openscad "$scenes/crosscheck/primitives.scad" -W 64 -H 48 -q \
        -o "$out/suite/primitives" || fail "check --openscad failed"
    pictures=12
fi

# Two scenes that pass (from a list: a comment, a blank line, a path relative to the list),
# one that does not exist, the figures above, and converge's plots
mkdir -p "$out/list"
ln -s "$(realpath "$scenes")" "$out/list/scenes"
printf '# scenes that pass\n%s\n\n  scenes/crosscheck/primitives.scad\n' \
    "$(realpath "$scenes")/csg_part.scad" >"$out/list/passing.list"
"$scadray" report "$out/list/passing.list" "$scenes/zz_no_such_scene.scad" --from "$out/suite" -W 64 -H 48 --converge --converge-samples 4 -q \
    -o "$out/report.html"
rc=$?
[ $rc -eq 1 ] || fail "report exited $rc, expected 1 (a scene failed)"
selfcheck report.html
echo "report.html: rows=$rows verdicts=$verdicts images=$images broken=$broken charts=$charts"
[ "$rows" = 4 ] || fail "expected 4 rows, found $rows"
[ "$verdicts" = "error,different,pass,pass" ] || fail "not failures first: $verdicts"
[ "$images" = "$pictures" ] || fail "expected $pictures pictures, found $images"
[ "$broken" = 0 ] || fail "$broken pictures did not load"
[ "$charts" = 2 ] || fail "expected 2 converge plots, found $charts"
# The table sorts in the browser: by scene name (column 1), failures are no longer first
selfcheck "report.html#sort=1"
[ "$verdicts" = "pass,pass,different,error" ] || fail "sorting by name gave $verdicts"
browse --hide-scrollbars --run-all-compositor-stages-before-draw --window-size=1280,1600 --screenshot="$out/report.png" \
    "file://$out/report.html" >/dev/null || fail "no screenshot"
[ -s "$out/report.png" ] || fail "empty screenshot"
echo "screenshot: $out/report.png"

# Negative control: the self-check sees a missing picture
"$scadray" report --from "$out/suite/mirrors" --link-images -q -o "$out/linked.html" \
    >/dev/null
selfcheck linked.html
[ "$images" = 3 ] && [ "$broken" = 0 ] || fail "linked pictures: $images, $broken broken"
rm "$out/suite/mirrors/mirrors_diff.png"
selfcheck linked.html
[ "$broken" = 1 ] || fail "a deleted picture was not counted broken ($broken)"
echo "PASS: 4 rows failures first, sortable, $pictures pictures and 2 plots in Chromium; a missing picture is caught"
