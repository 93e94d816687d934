#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fails, listing the files, when a C++ file in git is not formatted as .clang-format says.
# `scripts/check_format.sh --fix` formats them in place.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format > /dev/null || { echo "check_format: clang-format is not installed (scripts/setup.sh)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [[ ${1:-} == --fix ]]; then
    clang-format -i "${files[@]}"
    exit 0
fi
bad=()
for f in "${files[@]}"; do
    clang-format --dry-run --Werror "$f" > /dev/null 2>&1 || bad+=("$f")
done
if [[ ${#bad[@]} -gt 0 ]]; then
    printf 'not formatted as .clang-format says: %s\n' "${bad[@]}" >&2
    echo "check_format: ${#bad[@]} of ${#files[@]} files; scripts/check_format.sh --fix formats them" >&2
    exit 1
fi
echo "check_format: ${#files[@]} files formatted as .clang-format says"
