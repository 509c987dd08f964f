#!/usr/bin/env bash
# The Python package (python/): lint its Rust crate, build the abi3 wheel the way
# `pip install ./python` does, install it in a virtualenv with the test dependencies, and run
# pytest (conversions, pickling, GIL release, sweeps on a local pool and on a Dask LocalCluster).
# Idempotent: the virtualenv and cargo's target directory are reused when present.
set -euo pipefail
cd "$(dirname "$0")/../.."

venv=target/python-ci-venv
if ! "$venv/bin/python" -c 'import sys' 2>/dev/null; then
  rm -rf "$venv"
  python3 -m venv "$venv"
fi
py="$PWD/$venv/bin/python"
"$py" -m pip install -q --disable-pip-version-check \
  maturin numpy pandas "dask[distributed]" tqdm pytest hypothesis matplotlib

# The extension crate is a workspace of its own (it needs Python to build), so the root's
# fmt and clippy do not see it.
cargo fmt --manifest-path python/Cargo.toml -- --check
PYO3_PYTHON="$py" cargo clippy --manifest-path python/Cargo.toml --release --all-targets -- -D warnings

# Build the wheel through pip's build front end (the path `pip install ./python` takes, with
# maturin from PyPI in an isolated build environment), then install that wheel.
rm -rf target/python-wheels
"$py" -m pip wheel -q --disable-pip-version-check --no-deps -w target/python-wheels ./python
wheel=$(ls target/python-wheels/locus-*-cp39-abi3-*.whl)
"$py" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheel"

# From inside tests/: `python -m pytest` puts the working folder on sys.path, and from python/
# the source package (without its compiled _locus) would shadow the installed wheel.
cd python/tests
"$py" -m pytest -q -p no:cacheprovider .

# The graphs with Python script nodes (graphs/python/), now that a Python with the package is at
# hand: tests/graphs.rs requires them to pass (LOCUS_REQUIRE_PYTHON=1) and tests/cli.rs runs
# them through `locus test`.
cd ../..
LOCUS_PYTHON="$py" LOCUS_REQUIRE_PYTHON=1 cargo test --test graphs --test cli
