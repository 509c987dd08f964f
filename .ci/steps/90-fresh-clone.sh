#!/usr/bin/env bash
# A fresh clone passes the README's test command with nothing beside it (issue 10, part 3):
# clone the committed repository into an empty temporary folder (no ../shared next to it) and
# run `cargo test --workspace` there. The build reuses this checkout's target folder
# (CARGO_TARGET_DIR) so that only what the clone changes is rebuilt, and it is bounded by
# FRESH_CLONE_TIMEOUT seconds (default 2400).
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
limit="${FRESH_CLONE_TIMEOUT:-2400}"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/locus-fresh-clone.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
# The clone sits alone in its own folder: neither it nor any folder above the temporary root
# may hold shared/oracle (the test data must come from the clone itself).
git clone --quiet --no-hardlinks "$repo" "$scratch/locus"
for dir in "$scratch" "$(dirname "$scratch")"; do
  if [ -e "$dir/shared/oracle" ]; then
    echo "fresh-clone: $dir/shared/oracle exists; the clone would not be alone" >&2
    exit 1
  fi
done
cd "$scratch/locus"
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$repo/target}"
echo "fresh-clone: $(git log --oneline -1) in $scratch/locus (target $CARGO_TARGET_DIR)"
# The README's test command, verbatim (checked to still be the README's).
grep -qx "cargo test --workspace" README.md || { echo "fresh-clone: the README no longer says cargo test --workspace; update this step" >&2; exit 1; }
timeout "$limit" cargo test --workspace
echo "fresh-clone: ok"
