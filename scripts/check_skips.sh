#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Lists the tests a ctest run skipped, each with its skip message, from ctest's JUnit file
# (ctest --output-junit). Skips are ctest's "notrun" tests: exit code 77 (SKIP_RETURN_CODE) and
# GTEST_SKIP (gtest_discover_tests gives every gtest SKIP_REGULAR_EXPRESSION "[  SKIPPED ]").
#
#   scripts/check_skips.sh [--strict] JUNIT.xml [ALLOWED]
#
# --strict (scripts/test.sh passes it when CI=true): exits 1 when a skipped test's message matches
# no line of ALLOWED (default tests/ci_allowed_skips.txt: extended regular expressions, '#'
# comments), that is when a test skipped for a reason CI could have met.
set -euo pipefail
strict=0
if [[ ${1:-} == --strict ]]; then strict=1; shift; fi
junit=${1:?usage: scripts/check_skips.sh [--strict] JUNIT.xml [ALLOWED]}
allowed=${2:-$(dirname "$0")/../tests/ci_allowed_skips.txt}
if [[ ! -f $junit ]]; then
    echo "check_skips: no test results in $junit (did ctest run?)" >&2
    exit $((strict ? 1 : 0))
fi

# One line per skipped test: NAME<TAB>MESSAGE, the message's lines joined by " / ". A gtest's
# message is what follows its "file:line: Skipped" line; a script's, its lines that say "skip";
# otherwise its last three lines; ctest's reason where none of these says anything.
skipped=$(awk '
    function unescape(s) {
        gsub(/&lt;/, "<", s); gsub(/&gt;/, ">", s); gsub(/&quot;/, "\"", s)
        gsub(/&apos;/, "'"'"'", s); gsub(/&amp;/, "\\&", s)
        return s
    }
    function attr(line, key,    m) {
        if (match(line, key "=\"[^\"]*\"")) return substr(line, RSTART + length(key) + 2, RLENGTH - length(key) - 3)
        return ""
    }
    function finish(    i, msg, gtest, said, n, first) {
        if (status != "notrun") return
        msg = ""; gtest = 0
        for (i = 1; i <= nout; ++i) {
            if (out[i] ~ /^\[  SKIPPED \]/) { if (gtest) break; continue }
            if (gtest) { msg = msg (msg == "" ? "" : " / ") out[i]; continue }
            if (out[i] ~ /: Skipped$/) gtest = 1
        }
        if (!gtest) {
            for (i = 1; i <= nout; ++i)
                if (tolower(out[i]) ~ /skip/) msg = msg (msg == "" ? "" : " / ") out[i]
            if (msg == "") {
                first = nout > 3 ? nout - 2 : 1
                for (i = first; i <= nout; ++i) if (out[i] != "") msg = msg (msg == "" ? "" : " / ") out[i]
            }
        }
        if (msg == "") msg = "(no message; ctest: " reason ")"
        gsub(/\t/, " ", msg)
        print name "\t" msg
    }
    /<testcase / { name = unescape(attr($0, "name")); status = attr($0, "status"); reason = ""; nout = 0; inout = 0 }
    /<skipped / { reason = unescape(attr($0, "message")) }
    {
        line = $0
        if (!inout && index(line, "<system-out>")) { inout = 1; line = substr(line, index(line, "<system-out>") + 12) }
        if (inout) {
            done = index(line, "</system-out>")
            if (done) { line = substr(line, 1, done - 1); inout = 0 }
            if (!(done && line == "")) out[++nout] = unescape(line)
        }
    }
    /<\/testcase>/ { finish() }
' "$junit")

patterns=$(mktemp)
trap 'rm -f "$patterns"' EXIT
if [[ -f $allowed ]]; then grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' "$allowed" >"$patterns" || true; fi

n_allowed=0 n_bad=0 bad=() ok=()
while IFS=$'\t' read -r name msg; do
    [[ -n $name ]] || continue
    if [[ -s $patterns ]] && grep -qE -f "$patterns" <<<"$msg"; then
        ok+=("  $name: $msg"); n_allowed=$((n_allowed + 1))
    else
        bad+=("  $name: $msg"); n_bad=$((n_bad + 1))
    fi
done <<<"$skipped"

total=$((n_allowed + n_bad))
[[ $total -eq 0 ]] && exit 0
if [[ $strict -eq 0 ]]; then
    echo "$total skipped tests:"
    printf '%s\n' "${bad[@]}" "${ok[@]}" | sed '/^$/d'
    exit 0
fi
if [[ $n_allowed -gt 0 ]]; then
    echo "CI: $n_allowed skipped tests with a reason CI cannot meet ($(basename "$allowed")):"
    printf '%s\n' "${ok[@]}"
fi
if [[ $n_bad -gt 0 ]]; then
    echo "CI: $n_bad skipped tests FAIL: CI should have run them (a reason CI cannot meet goes in $allowed):" >&2
    printf '%s\n' "${bad[@]}" >&2
    exit 1
fi
