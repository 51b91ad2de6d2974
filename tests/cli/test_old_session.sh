# A session of an earlier format still reads as it did (issue 36, item 4):
# tests/data/sessions/format3.andros-session was recorded by the program
# before the transition records (format 3, `run --input format3.events
# --mapping mappings/examples/supervisor.yaml --weapons`: both pads' stops in
# one tick, a stop pressed again, resets, a suspend, a reload, the link
# taken). verify, sessions, replay, plot and export give what that program
# gave (tests/data/sessions/format3.expected: their output; the plot's page
# and the export's rows as SHA-256, less the vehicle model's columns that
# export gained later).
source "$(dirname "$0")/lib.sh"
export TZ=UTC
name=format3.andros-session
mkdir -p "$TMP/old"
cp "$DATA/sessions/$name" "$TMP/old/"
cd "$TMP/old" || exit 1
head -1 "$name" | grep -q '^0 andros-session 3 ' || fail "$name is not of format 3"

# out WHAT CMD...: CMD's output and exit code, under WHAT.
out() {
  local what=$1; shift
  echo "== $what"
  "$@" 2>&1
  echo "exit $?"
}
# digest WHAT FILE CMD...: CMD's exit code and the SHA-256 of FILE it wrote.
digest() {
  local what=$1 file=$2; shift 2
  echo "== $what"
  "$@" >/dev/null 2>"$TMP/digest.err"
  echo "exit $? $(sha256sum <"$file" | cut -c1-64)"
  cat "$TMP/digest.err"
}
{
  out verify "$BIN" verify "$name"
  out sessions "$BIN" sessions --record-dir . --format jsonl | sed "s|$TMP/old/./||"
  out replay "$BIN" replay "$name"
  digest plot plot.svg "$BIN" plot "$name" --output plot.svg
  # The vehicle model's columns (added since) left out: the rest as it was.
  for f in csv jsonl; do
    digest "export $f" export.$f.old sh -c "\"\$0\" export \"\$1\" --format $f --output export.$f &&
      python3 '$(dirname "$0")/export_without_model.py' export.$f $f >export.$f.old" "$BIN" "$name"
  done
} >"$TMP/got"
diff "$DATA/sessions/format3.expected" "$TMP/got" >"$TMP/diff" ||
  fail "the format 3 session reads otherwise than it did: $(cat "$TMP/diff")"
finish
