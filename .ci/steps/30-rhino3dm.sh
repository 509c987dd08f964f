#!/usr/bin/env bash
# openNURBS archives against the real rhino3dm (PyPI): rhino3dm decodes what locus encodes and
# locus decodes what rhino3dm encodes (crates/opennurbs-archive/e2e/). Idempotent: the venv is
# reused when present.
set -euo pipefail
cd "$(dirname "$0")/../.."
VENV="$(realpath -m "${LOCUS_RHINO3DM_VENV:-target/rhino3dm-venv}")"
if ! "$VENV/bin/python" -c "import rhino3dm, pytest" 2>/dev/null; then
  if ! python3 -m venv "$VENV" 2>/dev/null; then
    # Debian splits venv (and ensurepip) out of python3.
    apt-get update -qq && apt-get install -y -qq python3-venv >/dev/null
    rm -rf "$VENV"
    python3 -m venv "$VENV"
  fi
  "$VENV/bin/pip" install --quiet --disable-pip-version-check "rhino3dm>=8.9,<9" "pytest>=8,<10"
fi
# What `cargo test --workspace` built (the locus binary, the examples) with the same profile and
# features, so nothing is built a second time: a no-op after the test command.
cargo test --workspace --no-run --quiet
export LOCUS_ARCHIVE_JSON="$PWD/target/debug/examples/archive_json"
cd crates/opennurbs-archive/e2e
timeout 600 "$VENV/bin/python" -m pytest -q -p no:cacheprovider .
