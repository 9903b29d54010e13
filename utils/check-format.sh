#!/usr/bin/env bash
# Checks that every C++ source of the checkout is laid out as .clang-format says.
#   bash utils/check-format.sh          list the files clang-format would change; exit 1 if any
#   bash utils/check-format.sh --fix    reformat them in place
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then
  echo "Usage: bash utils/check-format.sh [--fix]"
  echo "Checks (or with --fix, applies) .clang-format on packages/, apps/ and tests/ (*.cpp, *.hpp)."
  exit 0
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
if ! command -v clang-format >/dev/null 2>&1; then
  echo "check-format: clang-format is not installed (bash utils/install-deps.sh installs it)" >&2
  exit 1
fi
mapfile -t files < <(find packages apps tests -type f \( -name '*.cpp' -o -name '*.hpp' \) | sort)
if [[ ${1:-} == --fix ]]; then
  clang-format -i "${files[@]}"
  echo "check-format: ${#files[@]} files formatted"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [[ ${#bad[@]} -gt 0 ]]; then
  printf 'check-format: not formatted: %s\n' "${bad[@]}" >&2
  echo "check-format: run 'bash utils/check-format.sh --fix'" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted as .clang-format says"
