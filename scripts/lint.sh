#!/usr/bin/env bash
# The format and lint gates (scripts/test.sh runs both; docs/testing.md):
# .clang-format over every C/C++ file, .clang-tidy over src/ (with a compile
# database of its own, build-lint/, and a cache of each file's result:
# scripts/lint_tidy.py).
#   scripts/lint.sh            both; exit 1 on any finding
#   scripts/lint.sh --format   only the format check (seconds)
#   scripts/lint.sh --tidy     only clang-tidy (minutes; seconds for what the cache has)
#   scripts/lint.sh --fix      formats every file in place (clang-format -i)
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
  if ((places > 0)); then
    awk -F: '/: warning: code should be clang-formatted/ { n[$1]++ } END { for (f in n) print "  " f ": " n[f] " place(s)" }' \
      "$out" | sort | head -20
    echo "format: FAILED: run scripts/lint.sh --fix (clang-format -i; $(clang-format --version | sed 's/.*version \([0-9.]*\).*/\1/')) and commit the result"
    status=1
  fi
  rm -f "$out"
fi

if [[ $what == all || $what == --tidy ]]; then
  # A compile database of its own. Configuring only (no build: clang-tidy reads
  # the sources) takes seconds. src/ is checked as the build compiles it, in
  # its unity groups (each file's findings still named by file): the headers
  # parsed and studied once a group, not once a file (CLI11 four times, not
  # 24; the run stage's 15 files: CPU 50 s one by one, 18 s as 3 groups).
  cmake -S . -B "$lint_build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DANDROS_UNITY=ON -DANDROS_CCACHE=OFF \
    -DANDROS_BUILD_TESTS=OFF -DANDROS_BUILD_BENCH=OFF >/dev/null
  log="$lint_build/clang-tidy.log"
  # In the background, waited for: a TERM (scripts/test.sh ending early)
  # reaches it, and it ends the clang-tidy processes it started.
  scripts/lint_tidy.py "$lint_build" . "$log" &
  tidy_py=$!
  trap 'kill "$tidy_py" 2>/dev/null' TERM INT
  wait "$tidy_py"
  trap - TERM INT
  # A header's finding is reported from each file that includes it: counted once.
  grep -E '^/.*: (warning|error): .*\[[a-z.-]+(,[a-z.-]+)*\]$' "$log" | sort -u >"$log.findings" || true
  findings=$(wc -l <"$log.findings")
  echo "tidy: $findings finding(s) in src/ (.clang-tidy; the list: $log.findings)"
  sed -E 's/.*\[([a-z.-]+)(,.*)?\]$/\1/' "$log.findings" | sort | uniq -c | sort -rn | sed 's/^/  /'
  if ((findings > 0)); then
    sed "s|^$PWD/|  |" "$log.findings"
    echo "tidy: FAILED: fix each finding (the whole report, with the code: $log), or, where a check is wrong for"
    echo "  this code, turn it off in .clang-tidy with a line saying why; scripts/lint.sh --tidy checks again"
    status=1
  fi
fi
exit $status
