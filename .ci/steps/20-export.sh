#!/usr/bin/env bash
# Exports every graph under graphs/ to .glb and .gltf and validates each file with the Khronos
# glTF validator (npm package gltf-validator, installed here from the lock file).
set -euo pipefail
cd "$(dirname "$0")/../.."
(cd crates/export/e2e && npm ci --no-audit --no-fund --loglevel=error)
# What `cargo test --workspace` built (the locus binary, the examples) with the same profile and
# features, so nothing is built a second time: a no-op after the test command.
cargo test --workspace --no-run --quiet
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
files=()
for graph in graphs/*.ron; do
  name=$(basename "$graph" .ron)
  ./target/debug/locus run "$graph" --export "$out/$name.glb" --export "$out/$name.gltf" > /dev/null
  files+=("$out/$name.glb" "$out/$name.gltf")
done
node crates/export/e2e/validate.mjs "${files[@]}"
echo "glTF validator: ${#files[@]} files valid"
