#!/usr/bin/env bash
# scripts/copy_source.sh, which copies the tree for the package's build: what
# git knows of (an edit, a new file; not a deleted file, not an ignored one),
# or without git every file but the build's outputs; symlinks and modes kept;
# a clone another user owns read too; and no failed copy while other jobs
# make and remove entries in the tree beside it (the folder's tar failed a CI
# run so, and 20 of 20 copies with such a loop running).
set -euo pipefail
root=${1:?usage: test_copy_source.sh SOURCE_ROOT}
copy=$root/scripts/copy_source.sh
work=$(mktemp -d)
churn=
trap '[[ -n $churn ]] && kill "$churn" 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

tree=$work/tree
mkdir -p "$tree/src" "$tree/build" "$tree/tests/__pycache__"
cd "$tree"
printf '%s\n' '/build*/' '/dist/' 'crash-*' '__pycache__/' >.gitignore
echo one >src/a.cpp
echo two >src/b.cpp
echo readme >README.md
printf 'odd\n' >'src/a name with spaces'
printf '#!/bin/sh\n' >run.sh
chmod +x run.sh
ln -s ../README.md src/readme-link
git -c init.defaultBranch=main init -q
git add -A
git -c user.name=test -c user.email=test@localhost commit -qm tree
# After the commit: an edit, a deletion, a new file, and what builds and runs leave.
echo edited >>src/a.cpp
rm src/b.cpp
echo new >src/c.cpp
echo crash >crash-1
echo object >build/out.o
echo cache >tests/__pycache__/lib.pyc
mkdir dist
echo deb >dist/x.deb

files() { (cd "$1" && find . \( -type f -o -type l \) -printf '%P\n' | LC_ALL=C sort | tr '\n' ' '); }
in_git='.gitignore README.md run.sh src/a name with spaces src/a.cpp src/c.cpp src/readme-link '
expect_copy() {  # WHAT EXPECTED-FILES
  rm -rf "$work/out"
  "$copy" "$tree" "$work/out" || fail "$1: the copy failed"
  [[ $(files "$work/out") == "$2" ]] || fail "$1: copied [$(files "$work/out")], expected [$2]"
  grep -q edited "$work/out/src/a.cpp" || fail "$1: the edit was not copied"
  [[ -L $work/out/src/readme-link ]] || fail "$1: the symlink was not copied as one"
  [[ -x $work/out/run.sh ]] || fail "$1: run.sh lost its mode"
}
expect_copy "a git work tree" "$in_git"

# Another user's clone (CI's root may find one so): still what git knows of.
if [[ $(id -u) -eq 0 ]] && id nobody >/dev/null 2>&1; then
  chown -R nobody "$tree"
  expect_copy "a clone another user owns" "$in_git"
  chown -R root "$tree"
else
  echo "copy_source: another user's clone not tried (needs root and the user nobody)"
fi

# Other jobs writing into the tree beside the copy: each copy whole.
churning() {  # WHAT EXPECTED-FILES
  bash -c 'while :; do mkdir -p "$0/build-x" "$0/zz-new" 2>/dev/null; rmdir "$0/build-x" "$0/zz-new" 2>/dev/null; done' \
    "$tree" &
  churn=$!
  for _ in $(seq 20); do expect_copy "$1, with entries made and removed beside it" "$2"; done
  kill "$churn"
  wait "$churn" 2>/dev/null || true
  churn=
}
churning "a git work tree" "$in_git"

# No git (an unpacked source tarball): every file but the build's outputs.
rm -rf .git
no_git='.gitignore README.md crash-1 run.sh src/a name with spaces src/a.cpp src/c.cpp src/readme-link '
expect_copy "a tree outside git" "$no_git"
churning "a tree outside git" "$no_git"

# A copy that cannot be written is an error, not a partial success.
echo file >"$work/a-file"
if "$copy" "$tree" "$work/a-file/out" 2>"$work/err"; then fail "a copy into a path under a file succeeded"; fi
echo "copy_source checks: ok"
