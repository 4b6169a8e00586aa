#!/usr/bin/env bash
# Runs the bundled graphs that write results on each dataset folder given and prints one line per
# output file: its SHA-256 and its path under OUT. Run it with the facet of two commits and diff
# the two lists: a change that must not change results (a refactoring, a speed-up) leaves them
# identical.
#
#   scripts/output_digest.sh FACET OUT DATASET...   > digest.txt
#   FACET=build/bin/facet; scripts/output_digest.sh "$FACET" /tmp/after data/mosd > after.txt
#   diff before.txt after.txt
#
# The graphs: tabletop.yaml (and its variants bsp and convex), tabletop_cloud.yaml,
# tabletop_graph.yaml, objects_planes.yaml and faces.yaml. OUT/<dataset>/<graph> holds their
# output; a dataset is named by its last two path components (tune/office, real/mosd).
set -euo pipefail
facet="${1:?usage: output_digest.sh FACET OUT DATASET...}"
out="${2:?usage: output_digest.sh FACET OUT DATASET...}"
shift 2
[[ $# -gt 0 ]] || { echo "usage: output_digest.sh FACET OUT DATASET..." >&2; exit 2; }
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

runs=(
  "tabletop:tabletop.yaml"
  "tabletop_bsp:tabletop.yaml --variant bsp"
  "tabletop_convex:tabletop.yaml --variant convex"
  "tabletop_cloud:tabletop_cloud.yaml"
  "tabletop_graph:tabletop_graph.yaml"
  "objects_planes:objects_planes.yaml"
  "faces:faces.yaml"
)
for dataset in "$@"; do
  name="$(basename "$(dirname "$dataset")")/$(basename "$dataset")"
  for run in "${runs[@]}"; do
    label="${run%%:*}"
    read -r -a graph_args <<<"${run#*:}"
    dir="$out/$name/$label"
    rm -rf "$dir"
    "$facet" run "$here/graphs/${graph_args[0]}" "${graph_args[@]:1}" -q \
      --param input="$dataset" --param output="$dir" >/dev/null
  done
done
cd "$out"
find . -type f -print0 | sort -z | xargs -0 sha256sum
