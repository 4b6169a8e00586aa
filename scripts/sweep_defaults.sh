#!/usr/bin/env bash
# Sweeps the main thresholds of graphs/tabletop.yaml one at a time, ±20 % around their defaults,
# with `facet compare --sweep` (graphs/compare_tabletop.yaml), on every data set given, and
# prints a markdown table: per threshold and data set, F at the default, the best F and where,
# and the plateau (the range over which F stays within 0.01 of its best). A default belongs on
# a plateau of every data set, not on the peak of one. The plots are OUT/<set>/<param>/sweep_*.svg.
#
#   scripts/sweep_defaults.sh OUT NAME=DATASET:LABELS [NAME=DATASET:LABELS ...]
#     e.g. mosd=<mOSD dataset>:label_parts tune=<sets>/tune_all:label
set -euo pipefail
out="${1:?usage: sweep_defaults.sh OUT NAME=DATASET:LABELS ...}"
shift
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="${FACET:-$here/build/bin/facet}"

# node.param=start:stop:step (or param=... for a graph parameter), the default in the middle.
# edge_threshold is the graph parameter that moves the edge filter and the normals' noise
# measure together, as `--param edge_threshold=T` does.
sweeps=(
  edge_threshold=0.80:0.90:0.025
  planes.distance_m=0.008:0.012:0.001
  planes.min_object_height_m=0.004:0.008:0.001
  planes.max_behind_fraction=0.04:0.06:0.005
  planes.min_view_fraction=0.008:0.012:0.001
  blobs.max_distance_m=0.008:0.012:0.001
  blobs.distance_growth_start_m=1.0:1.4:0.1
  blobs.min_raised_fraction=0.4:0.6:0.05
  patches.min_size_reference_depth_m=0.8:1.2:0.1
  patches.min_size_far_px=40:60:5
  objects.front_body_margin_m=0.012:0.018:0.003
  objects.front_body_face_rms_at_1m_m=0.0009:0.0013:0.0002
)
# Only the thresholds whose names contain this (all when empty), e.g. ONLY=patches.
only="${ONLY:-}"

echo "| threshold | set | F at default | best F (at) | plateau within 0.01 |"
echo "|---|---|---|---|---|"
for sweep in "${sweeps[@]}"; do
  [[ -z "$only" || "$sweep" == *"$only"* ]] || continue
  param="${sweep%%=*}"
  range="${sweep#*=}"
  IFS=: read -r start stop step <<<"$range"
  default=$(awk -v a="$start" -v b="$stop" 'BEGIN {print (a + b) / 2}')
  for set in "$@"; do
    name="${set%%=*}"
    spec="${set#*=}"
    dataset="${spec%:*}"
    labels="${spec##*:}"
    result="$out/$name/$param"
    "$facet" compare "$here/graphs/compare_tabletop.yaml" -q --param input="$dataset" \
      --param labels="$labels" --sweep "$sweep" --out "$result" >/dev/null
    python3 - "$result/compare.json" "$param" "$default" "$name" <<'PY'
import json, sys
path, param, default, name = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
report = json.load(open(path))
f = {}
for variant in report["variants"]:
    value = variant["sweep"][param]
    for metric in variant["metrics"]:
        if metric["node"] == "score" and metric["name"] == "f":
            f[value] = metric["mean"]
best = max(f, key=f.get)
near = min(f, key=lambda v: abs(v - default))
plateau = report["sweep"]["plateau"][0]
print(f"| `{param}` | {name} | {f[near]:.3f} | {f[best]:.3f} ({best:g}) | "
      f"{plateau['from']:g} .. {plateau['to']:g} |")
PY
  done
done
