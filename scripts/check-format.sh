#!/usr/bin/env bash
# Checks that every C++ source (*.h, *.cpp) is formatted as .clang-format says, without changing any file.
# Lists the files that are not and exits 1; exit 0 when all are formatted; exit 2 when clang-format is missing;
# exit 3 when clang-format fails on a file for another reason (a bad .clang-format, a file it cannot parse).
# Files: `git ls-files` in a git checkout, else src/ tests/ bench/ examples/. The *.h.in templates are not checked.
# .clang-format targets Debian bookworm's clang-format 14; another major version may format some lines differently,
# so a mismatch is warned about (install with: bash scripts/install-deps.sh clang-format).
# Usage: bash scripts/check-format.sh        (CLANG_FORMAT overrides the binary, default clang-format)
# Fix:   git ls-files '*.h' '*.cpp' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."

clang_format=${CLANG_FORMAT:-clang-format}
if ! command -v "$clang_format" >/dev/null 2>&1; then
  echo "check-format: $clang_format not found; install it with: bash scripts/install-deps.sh clang-format" >&2
  exit 2
fi
version=$("$clang_format" --version)
major=$(sed -n 's/.*clang-format version \([0-9]*\).*/\1/p' <<<"$version")
if [ "$major" != "14" ]; then
  echo "check-format: warning: .clang-format targets clang-format 14, this is: $version" >&2
fi

files=()
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  # A tracked file deleted in the work tree is not there to check.
  while IFS= read -r -d '' f; do [ -f "$f" ] && files+=("$f"); done < <(git ls-files -z -- '*.h' '*.cpp')
else
  dirs=()
  for d in src tests bench examples; do [ -d "$d" ] && dirs+=("$d"); done
  if [ ${#dirs[@]} -gt 0 ]; then
    while IFS= read -r -d '' f; do files+=("$f"); done < <(find "${dirs[@]}" -type f \( -name '*.h' -o -name '*.cpp' \) -print0 | sort -z)
  fi
fi
if [ ${#files[@]} -eq 0 ]; then
  echo "check-format: no C++ sources found under $(pwd)" >&2
  exit 3
fi

# A .clang-format this clang-format cannot read (an option it does not know) fails every file: say so once.
if ! config_error=$("$clang_format" --dump-config --assume-filename=x.cpp 2>&1 >/dev/null); then
  echo "check-format: $clang_format cannot use .clang-format: $config_error" >&2
  exit 3
fi
# One clang-format run over all files (it goes on past a violation); a formatting difference is reported as
# "FILE:LINE:COL: error: code should be clang-formatted [-Wclang-format-violations]".
status=0
messages=$(printf '%s\0' "${files[@]}" | xargs -0 "$clang_format" --dry-run --Werror 2>&1) || status=$?
unformatted=()
while IFS= read -r f; do
  [ -n "$f" ] && unformatted+=("$f")
done < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<<"$messages" | sort -u)
if [ "$status" -ne 0 ] && [ ${#unformatted[@]} -eq 0 ]; then
  echo "check-format: $clang_format failed (exit $status):" >&2
  head -20 <<<"$messages" >&2
  exit 3
fi

if [ ${#unformatted[@]} -gt 0 ]; then
  echo "check-format: ${#unformatted[@]} of ${#files[@]} files are not formatted as .clang-format says:" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  echo "check-format: see the differences with: $clang_format --dry-run FILE; fix them with: $clang_format -i FILE" >&2
  exit 1
fi
echo "check-format: all ${#files[@]} files formatted ($version)" >&2
