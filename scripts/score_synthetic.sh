#!/usr/bin/env bash
# Scores graphs/tabletop.yaml on io.synthetic's presets against their exact ground truth, as a
# markdown table: for each preset, `new` (FRAMES frames of as many layouts) and `static` (twice
# as many frames of one layout with independent noise).
#
#   scripts/score_synthetic.sh SCORER [OUT] [SEED] [FRAMES] [-- TABLETOP ARGS...]
#     SCORER   path of the scoring script (score.py), run with the system python3
#     OUT      where scenes and results go (default out/score_synthetic)
#     SEED     io.synthetic's seed (default 1); FRAMES (default 10)
#     after --, arguments for `facet run graphs/tabletop.yaml`, e.g. --variant pca5
set -euo pipefail
scorer="${1:?path of score.py}"
out="${2:-out/score_synthetic}"
seed="${3:-1}"
frames="${4:-10}"
shift $(($# < 4 ? $# : 4))
[[ "${1:-}" == "--" ]] && shift
tabletop_args=("$@")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="$here/build/bin/facet"

summary() {  # the ALL row of score.py: P R F seg over under merged
  awk '/^ALL/ {printf "%s | %s | **%.3f** | %s | %s | %s | %s", $5, $6, $7 / 100, $8, $11, $12, $13}'
}

echo "| preset | run | frames | P | R | **F** | seg [%] | over | under | merged |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for preset in separated3 touching_pairs stacked_occluded clutter20; do
  for run in new static; do
    n="$frames"
    scene=(--set source.scene=new)
    [[ "$run" == static ]] && n=$((2 * frames)) && scene=()
    scenes="$out/$run/$preset"
    "$facet" run "$here/graphs/synthetic.yaml" -q --param preset="$preset" --param seed="$seed" \
      --param frames="$n" "${scene[@]}" --param output="$scenes"
    "$facet" run "$here/graphs/tabletop.yaml" -q "${tabletop_args[@]}" \
      --param input="$scenes" --param output="$out/${run}_seg/$preset"
    row=$(/usr/bin/python3 "$scorer" --gt "$scenes/label" --gt-name '*.png' \
      --pred "$out/${run}_seg/$preset/labels" --pred-name '*.png' | summary)
    echo "| \`$preset\` | $run | $n | $row |"
  done
done
