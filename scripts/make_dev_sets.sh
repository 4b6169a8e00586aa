#!/usr/bin/env bash
# Writes the development data sets: generated scenes of every io.synthetic preset with their
# ground truth, in the dataset layout (docs/data-formats.md), in three sets with disjoint seeds:
#
#   OUT/tune/<preset>     seeds 1 .. FRAMES          for tuning the pipeline
#   OUT/check/<preset>    seeds 1001 .. 1000+FRAMES  for checking it on layouts it was not tuned on
#   OUT/holdout/<preset>  seeds 2001 .. 2000+FRAMES  looked at only to confirm a change that
#                                                    gained on both others (docs/evaluation.md)
#
# Each seed is one frame of a new layout (source.scene=new), named <preset>_<seed>_000000, so a
# frame is regenerated from its name alone. The view is drawn per layout as well: camera height
# 0.6-1.8 m above the table and tilt 30-70 deg (camera=random), the table's front edge in view
# in half the layouts (table_edge=random), a wall 1.5-4 m from the camera in three of four
# (wall_placement=random). VIEW=fixed keeps the classic camera and room instead.
#
#   scripts/make_dev_sets.sh OUT [FRAMES]      FRAMES per preset and set (default 10)
#   PRESETS="office pile20" scripts/make_dev_sets.sh OUT 50
set -euo pipefail
out="${1:?usage: make_dev_sets.sh OUT [FRAMES]}"
frames="${2:-10}"
presets="${PRESETS:-separated3 touching_pairs stacked_occluded clutter20 on_flat pile20 office containers}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="${FACET:-$here/build/bin/facet}"

view=(--set source.camera=random --set source.table_edge=random
  --set source.wall_placement=random)
[[ "${VIEW:-random}" == fixed ]] && view=()

declare -A first_seed=([tune]=1 [check]=1001 [holdout]=2001)
for set_name in tune check holdout; do
  first=${first_seed[$set_name]}
  for preset in $presets; do
    dir="$out/$set_name/$preset"
    for ((seed = first; seed < first + frames; ++seed)); do
      "$facet" run "$here/graphs/synthetic.yaml" -q --param preset="$preset" --param seed="$seed" \
        --param frames=1 --set source.scene=new "${view[@]}" --param output="$dir"
    done
    echo "$dir: $(find "$dir/depth" -name '*.png' | wc -l) frames"
  done
done
