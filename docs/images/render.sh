#!/bin/sh
# Regenerates the pictures of the tutorial graphs shown in README.md and graphs/README.md.
set -eu
cd "$(dirname "$0")/../.."
# Their named outputs:
for graph in exploded_box tangent_spheres; do
  cargo run --quiet --release -- render "graphs/$graph.ron" -o "docs/images/$graph.png" --size 640x480
done
# Every node's geometry, as Grasshopper's canvas preview shows it:
for graph in face_direction multiple_transformations surface_singularity; do
  cargo run --quiet --release -- render "graphs/$graph.ron" --preview -o "docs/images/$graph.png" --size 640x480
done
cargo run --quiet --release -- render graphs/curve_continuity_tutorial.ron --preview --view top \
  -o docs/images/curve_continuity_tutorial.png --size 640x480
