#!/usr/bin/env bash
# Scores the surface patches of every variant of graphs/ab_normals.yaml and graphs/ab_edges.yaml
# against part-level ground truth, with an external scorer (overlap P/R/F with one-to-one IoU
# matching, over- and under-segmentation counts).
#
#   scripts/score_patches.sh DATASET SCORER [OUT]
#     DATASET  a dataset folder with intrinsics.yaml, depth/ and label_parts/ (e.g. the mOSD frames)
#     SCORER   path of the scoring script (score.py), run with the system python3
#     OUT      where results go (default out/score_patches)
set -euo pipefail
dataset="${1:?dataset folder}"
scorer="${2:?path of score.py}"
out="${3:-out/score_patches}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="$here/build/bin/facet"

run_variants() {
  local graph="$1"
  shift
  for variant in "$@"; do
    "$facet" run "$here/graphs/$graph.yaml" -q --variant "$variant" \
      --param input="$dataset" --param output="$out/$graph/$variant"
    echo "== $graph --variant $variant"
    /usr/bin/python3 "$scorer" --gt "$dataset/label_parts" --gt-name '*.png' \
      --pred "$out/$graph/$variant/patches" --pred-name '*.png' | grep -E '^ALL'
  done
}

run_variants ab_normals cross_r1 cross_r2 pca3 pca5 integral
run_variants ab_edges max1 max3 avg1 avg3
