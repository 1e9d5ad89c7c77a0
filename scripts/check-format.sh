#!/usr/bin/env bash
# Checks that every C++ file of the repository is formatted as .clang-format says, with Debian 12's
# clang-format 14 (another version formats some constructs differently); ctest runs it. With --fix it
# formats them in place instead.
set -euo pipefail
cd "$(dirname "$0")/.."
format=clang-format-14
if ! command -v "$format" >/dev/null; then
  echo "check-format: $format is missing; scripts/install-deps.sh installs it" >&2
  exit 1
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find apps benchmarks core plugins sdk tests -name '*.cpp' -o -name '*.hpp' -o -name '*.h')
fi
if [ "${1:-}" = --fix ]; then
  "$format" -i "${files[@]}"
  exit 0
fi
unformatted=$("$format" --dry-run "${files[@]}" 2>&1 | grep -E '^[^:]+:[0-9]+:[0-9]+: warning' | cut -d: -f1 | sort -u || true)
if [ -n "$unformatted" ]; then
  echo "check-format: these files differ from .clang-format's style:" >&2
  echo "$unformatted" | sed 's/^/  /' >&2
  echo "  fix: scripts/check-format.sh --fix (or $format -i FILE), then review and commit" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files follow .clang-format"
