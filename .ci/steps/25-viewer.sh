#!/usr/bin/env bash
# The viewer page of `locus view` in headless Chromium (Debian's package, driven by
# playwright-core from npm): loads without console errors or network requests, holds the
# expected objects, lists the glTF's outputs in its panel, reports the output, path and index of
# an object clicked, and draws a picture that is not blank. Screenshots are kept as artifacts
# in target/artifacts/viewer/.
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! command -v chromium > /dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium > /dev/null
fi
(cd crates/export/e2e && npm ci --no-audit --no-fund --loglevel=error)
# What `cargo test --workspace` built (the locus binary, the examples) with the same profile and
# features, so nothing is built a second time: a no-op after the test command.
cargo test --workspace --no-run --quiet
out="$PWD/target/artifacts/viewer"
mkdir -p "$out"
pages=()
for graph in tangent_spheres exploded_box; do
  ./target/debug/locus view "graphs/$graph.ron" -o "$out/$graph.html" > /dev/null
  pages+=("$out/$graph.html")
done
node crates/export/e2e/viewer.mjs "${pages[@]}"

# The live page of `locus view --serve`: reloads after the graph file changes, camera kept.
live="$out/live"
mkdir -p "$live"
cat > "$live/points.ron" <<'RON'
(
    format: 1,
    name: "points",
    nodes: [
        (id: "p", type: "params.point", values: {"Pt": [(0, 0, 0), (4, 0, 0), (4, 3, 0)]}),
    ],
    wires: [],
    outputs: {"P": "p.Pt"},
)
RON
./target/debug/locus view --serve --port 0 --quiet "$live/points.ron" > "$live/address" 2> "$live/server.log" &
server=$!
trap 'kill $server 2> /dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$live/address" ] && break; sleep 0.1; done
node crates/export/e2e/live.mjs "$(head -1 "$live/address")" "$live/points.ron"
kill $server
wait $server || true
