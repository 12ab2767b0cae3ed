#!/usr/bin/env bash
# Checks that every C and C++ source of the project is formatted as .clang-format says
# (`make test` runs it; `scripts/check_format.sh --fix` rewrites the files that are not).
set -euo pipefail
cd "$(dirname "$0")/.."
fmt=$(command -v clang-format || command -v clang-format-14 || true)
if [ -z "$fmt" ]; then
  echo "check_format: clang-format is not installed (scripts/deps.sh installs it)" >&2
  exit 1
fi
if [ -d .git ] || git rev-parse --git-dir >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.inc' '*.c')
else
  mapfile -t files < <(find apps bench examples include src tests \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \
    -o -name '*.inc' -o -name '*.c' \) -print | sort)
fi
if [ "${1:-}" = "--fix" ]; then
  "$fmt" -i "${files[@]}"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  if ! "$fmt" --dry-run --Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done
if [ ${#bad[@]} -ne 0 ]; then
  echo "check_format: ${#bad[@]} file(s) differ from .clang-format ($("$fmt" --version | head -1)):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  echo "run scripts/check_format.sh --fix" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files formatted as .clang-format says"
