#!/bin/sh
# Regenerates the pictures of the tutorial graphs shown in README.md and graphs/README.md.
set -eu
cd "$(dirname "$0")/../.."
for graph in exploded_box tangent_spheres; do
  cargo run --quiet --release -- render "graphs/$graph.ron" -o "docs/images/$graph.png" --size 640x480
done
