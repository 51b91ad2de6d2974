#!/usr/bin/env bash
# copy_source.sh TREE DEST: copies the source tree TREE into DEST (made if
# missing), without what builds and runs make in it. scripts/package.sh
# builds the Debian package from such a copy, while the test command's other
# jobs write into the tree beside it.
#
# The copy takes a list of the tree's files, not the tree. Archiving the
# folder failed whenever anything beside it made or removed an entry in it
# while tar read it ("tar: .: file changed as we read it": the test command's
# sanitizer build made build-asan/ beside the package's copy, and a CI run
# went red); tar looks only at the files listed.
#
# The list: what git knows of (tracked, and new files it does not ignore)
# and is there; safe.directory, so that a clone another user owns, as CI's
# root may find it, is still read. Outside git (an unpacked source tarball):
# every file but the build's outputs (build*, obj-*, dist, .git,
# __pycache__), passing over an entry made and removed while find read the
# tree. A listed file gone before tar reads it is left out
# (--ignore-failed-read), not a failed copy.
set -euo pipefail
(($# == 2)) || { echo "usage: copy_source.sh TREE DEST" >&2; exit 2; }
dest=$(realpath -m "$2")
cd "$1"
mkdir -p "$dest"
list=$(mktemp)
trap 'rm -f "$list" "$list.git" "$list.err"' EXIT
if git -c safe.directory="$PWD" ls-files -z --cached --others --exclude-standard >"$list.git" 2>/dev/null; then
  while IFS= read -r -d '' file; do
    if [[ -e $file || -L $file ]]; then printf '%s\0' "$file"; fi
  done <"$list.git" >"$list"
elif ! find . \( -path './build*' -o -path './obj-*' -o -path ./dist -o -path ./.git -o -name __pycache__ \) -prune \
  -o \( -type f -o -type l \) -printf '%P\0' >"$list" 2>"$list.err"; then
  # Passed over: an entry made and removed while find read the tree; any other error fails the copy.
  if grep -v ': No such file or directory$' "$list.err" >&2; then
    echo "copy_source: could not list the files of $PWD" >&2
    exit 1
  fi
fi
tar -c --null --no-recursion --ignore-failed-read -T "$list" | tar -x -C "$dest"
