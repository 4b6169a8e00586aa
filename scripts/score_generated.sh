#!/usr/bin/env bash
# Scores graphs/tabletop.yaml on generated development sets (scripts/make_dev_sets.sh writes them:
# SETS/tune/<preset>/, SETS/check/<preset>/ and SETS/holdout/<preset>/, disjoint seeds; a set
# that is missing is left out) against their whole-object ground truth, as a markdown table: one
# row per preset and set, the mean F of each set, and the gap between tuning and checking sets.
# A default that wins on one set and loses on another is not a default.
#
#   scripts/score_generated.sh SCORER SETS [OUT] [-- TABLETOP ARGS...]
#     SCORER  path of the scoring script (score.py), run with the system python3
#     SETS    the folder make_dev_sets.sh wrote
#     OUT     where results go (default out/score_generated)
#     after --, arguments for `facet run graphs/tabletop.yaml`, e.g. --variant convex
set -euo pipefail
scorer="${1:?path of score.py}"
sets="${2:?folder of the development sets}"
out="${3:-out/score_generated}"
shift $(($# < 3 ? $# : 3))
[[ "${1:-}" == "--" ]] && shift
tabletop_args=("$@")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="${FACET:-$here/build/bin/facet}"

summary() {  # the ALL row of score.py: P R F seg over under merged
  awk '/^ALL/ {printf "%s | %s | **%.3f** | %s | %s | %s | %s", $5, $6, $7 / 100, $8, $11, $12, $13}'
}

echo "| set | preset | frames | P | R | **F** | seg [%] | over | under | merged |"
echo "|---|---|---|---|---|---|---|---|---|---|"
declare -A f_sum f_count
for set in tune check holdout; do
  [[ -d "$sets/$set" ]] || continue
  for scenes in "$sets/$set"/*/; do
    scenes="${scenes%/}"
    preset="$(basename "$scenes")"
    result="$out/$set/$preset"
    "$facet" run "$here/graphs/tabletop.yaml" -q "${tabletop_args[@]}" \
      --param input="$scenes" --param output="$result"
    frames=$(find "$scenes/depth" -name '*.png' | wc -l)
    row=$(/usr/bin/python3 "$scorer" --gt "$scenes/label" --gt-name '*.png' \
      --pred "$result/labels" --pred-name '*.png' | summary)
    echo "| $set | \`$preset\` | $frames | $row |"
    f=$(awk -F'|' '{gsub(/[ *]/, "", $4); print $4}' <<<"| $row")
    f_sum[$set]=$(awk -v a="${f_sum[$set]:-0}" -v b="$f" 'BEGIN {print a + b}')
    f_count[$set]=$((${f_count[$set]:-0} + 1))
  done
done
tune=$(awk -v s="${f_sum[tune]:-0}" -v n="${f_count[tune]:-1}" 'BEGIN {printf "%.3f", s / n}')
check=$(awk -v s="${f_sum[check]:-0}" -v n="${f_count[check]:-1}" 'BEGIN {printf "%.3f", s / n}')
gap=$(awk -v a="$tune" -v b="$check" 'BEGIN {printf "%+.3f", a - b}')
holdout=""
if [[ -n "${f_count[holdout]:-}" ]]; then
  holdout=$(awk -v s="${f_sum[holdout]}" -v n="${f_count[holdout]}" 'BEGIN {printf ", holdout %.3f", s / n}')
fi
echo
echo "mean F over presets: tune $tune, check $check, gap (tune - check) $gap$holdout"
