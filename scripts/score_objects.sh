#!/usr/bin/env bash
# Scores the objects of graphs/tabletop.yaml and its variants against ground truth with an
# external scorer, overall and per category of the dataset's frames.csv (mean F over the frames
# of each category), as a markdown table. Part-level ground truth (label_parts) by default;
# LABELS=label scores against whole objects.
#
#   [LABELS=label] [RERUN=0] scripts/score_objects.sh DATASET SCORER [OUT] [VARIANT...]
#     RERUN=0  score the labels already in OUT (e.g. against the other label set) without running
#     DATASET  a dataset folder with intrinsics.yaml, depth/, label_parts/ (or $LABELS/) and
#              frames.csv (mOSD)
#     SCORER   path of the scoring script (score.py), run with the system python3
#     OUT      where results go (default out/score_objects)
#     VARIANT  variants to score besides the default graph (default: convex pca5)
set -euo pipefail
dataset="${1:?dataset folder}"
scorer="${2:?path of score.py}"
out="${3:-out/score_objects}"
shift $(($# < 3 ? $# : 3))
variants=("$@")
labels="${LABELS:-label_parts}"
[[ -d "$dataset/$labels" ]] || { echo "no ground truth folder '$dataset/$labels'" >&2; exit 2; }
[[ ${#variants[@]} -gt 0 ]] || variants=(convex pca5)
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="$here/build/bin/facet"

echo "| variant | P | R | **F** | seg [%] | over | under | merged | per category F |"
echo "|---|---|---|---|---|---|---|---|---|"
for variant in default "${variants[@]}"; do
  args=()
  [[ "$variant" == default ]] || args=(--variant "$variant")
  if [[ "${RERUN:-1}" != 0 ]]; then
    mkdir -p "$out/$variant"
    "$facet" run "$here/graphs/tabletop.yaml" -q "${args[@]}" \
      --param input="$dataset" --param output="$out/$variant" --json "$out/$variant/stats.json"
  fi
  /usr/bin/python3 "$scorer" --gt "$dataset/$labels" --gt-name '*.png' \
    --pred "$out/$variant/labels" --pred-name '*.png' --per-image \
    --json "$out/$variant/score_$labels.json" >/dev/null
  /usr/bin/python3 "$here/scripts/category_scores.py" "$out/$variant/score_$labels.json" \
    "$dataset/frames.csv" --row "$variant"
done
