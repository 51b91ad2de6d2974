#!/usr/bin/env bash
# The format and lint gates: .clang-format over every C/C++ file, .clang-tidy
# over src/ (with a compile database of its own, build-lint/). Not yet called by
# scripts/test.sh: the tree is formatted in one commit of its own first.
#   scripts/lint.sh            counts what each would change or report; exit 1 when any
#   scripts/lint.sh --fix      formats every file in place (clang-format -i)
#   scripts/lint.sh --format   only the format check (seconds); --tidy: only clang-tidy (minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh clang-format clang-tidy
lint_build=${LINT_BUILD_DIR:-build-lint}
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.c' '*.h')
what=${1:-all}
if [[ $what == --fix ]]; then
  clang-format -i "${files[@]}"
  exit 0
fi
status=0

if [[ $what == all || $what == --format ]]; then
  # One warning per place clang-format would change; the files they are in.
  out=$(mktemp)
  clang-format --dry-run "${files[@]}" 2>"$out" || true
  # (awk, not grep | cut | sort: a grep that finds nothing, on a clean tree,
  # fails the pipeline under pipefail.)
  places=$(awk '/: warning: code should be clang-formatted/ { n++ } END { print n + 0 }' "$out")
  unformatted=$(awk -F: '/: warning: code should be clang-formatted/ && !seen[$1]++ { n++ } END { print n + 0 }' "$out")
  echo "format: $places place(s) in $unformatted of ${#files[@]} files differ from .clang-format (scripts/lint.sh --fix)"
  rm -f "$out"
  ((places == 0)) || status=1
fi

if [[ $what == all || $what == --tidy ]]; then
  # A compile database of its own, file by file (the build compiles the cli
  # stage in unity groups, which clang-tidy would not see as src/ files).
  cmake -S . -B "$lint_build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DANDROS_UNITY_CLI=OFF -DANDROS_CCACHE=OFF \
    -DANDROS_BUILD_TESTS=OFF -DANDROS_BUILD_BENCH=OFF >/dev/null
  log="$lint_build/clang-tidy.log"
  run-clang-tidy -p "$lint_build" -j "$(nproc)" -quiet "$PWD/src/" 2>&1 | sed 's/\x1b\[[0-9;]*m//g' >"$log" || true
  # A header's finding is reported from each file that includes it: counted once.
  grep -E '^/.*: (warning|error): .*\[[a-z.-]+(,[a-z.-]+)*\]$' "$log" | sort -u >"$log.findings" || true
  findings=$(wc -l <"$log.findings")
  echo "tidy: $findings finding(s) in src/ (.clang-tidy; the list: $log.findings)"
  sed -E 's/.*\[([a-z.-]+)(,.*)?\]$/\1/' "$log.findings" | sort | uniq -c | sort -rn | sed 's/^/  /'
  ((findings == 0)) || status=1
fi
exit $status
