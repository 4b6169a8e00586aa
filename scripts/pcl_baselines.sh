#!/usr/bin/env bash
# Runs the stock PCL segmentation pipelines (bench/pcl_baselines.cpp: organized multi-plane,
# RANSAC plane + Euclidean clusters, supervoxels + LCCP) on a dataset and scores each pipeline's
# labels against part-level ground truth with an external scorer (overlap P/R/F with one-to-one
# IoU matching, over- and under-segmentation counts), plus the mean F per category when the
# dataset has a frames.csv (frame,category,...). facet's graphs/tabletop.yaml runs in the same
# sitting (three times, before the PCL pipelines) and is scored the same way, so that the ratios
# of time and quality come from one run on one machine. Builds nothing: build facet and
# facet_pcl_baselines first (the latter exists when CMake found PCL).
#
#   scripts/pcl_baselines.sh DATASET SCORER [OUT [TOOL OPTIONS...]]
#     DATASET  a dataset folder with intrinsics.yaml, depth/ and label_parts/ (e.g. the mOSD frames)
#     SCORER   path of the scoring script (score.py), run with the system python3
#     OUT      where results go (default out/pcl_baselines): OUT/<pipeline>/labels/*.png,
#              OUT/<pipeline>/score.json, OUT/timing.csv, OUT/timing.json, OUT/facet/,
#              OUT/facet<N>.json
#     TOOL OPTIONS  passed on to facet_pcl_baselines (e.g. --repeat 3; see its --help)
#   FACET_BUILD_DIR  build tree holding bin/facet and bin/facet_pcl_baselines (default build)
set -euo pipefail
dataset="${1:?dataset folder}"
scorer="${2:?path of score.py}"
out="${3:-out/pcl_baselines}"
shift $(($# < 3 ? $# : 3))
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${FACET_BUILD_DIR:-$here/build}/bin"
for program in facet facet_pcl_baselines; do
  [[ -x "$bin/$program" ]] || { echo "no $bin/$program (build it first)" >&2; exit 2; }
done
mkdir -p "$out"

# facet first: its per-stage medians (processing stages without file I/O) and whole-frame time,
# on one thread (--threads 1: the sequential executor) as the PCL pipelines run.
for run in 1 2 3; do
  "$bin/facet" run "$here/graphs/tabletop.yaml" -q --threads 1 --param input="$dataset" \
    --param output="$out/facet" --json "$out/facet$run.json"
done
# One thread: none of these pipelines is parallel, but keep OpenMP out of the timing for sure.
OMP_NUM_THREADS=1 "$bin/facet_pcl_baselines" "$dataset" "$out" "$@"

score() {
  echo "== $1"
  /usr/bin/python3 "$scorer" --gt "$dataset/label_parts" --gt-name '*.png' \
    --pred "$2" --pred-name '*.png' --json "$3" | grep -E '^ALL'
  if [[ -f "$dataset/frames.csv" ]]; then
    /usr/bin/python3 "$here/scripts/category_scores.py" "$3" "$dataset/frames.csv"
  fi
}
score facet "$out/facet/labels" "$out/facet/score.json"
for labels in "$out"/*/labels; do
  pipeline="$(basename "$(dirname "$labels")")"
  [[ "$pipeline" == facet ]] || score "$pipeline" "$labels" "$out/$pipeline/score.json"
done

# Time per frame: facet's processing stages (sum of the stage medians, io.* stages left out, as
# the PCL times leave out file I/O; median over the three runs) against each PCL pipeline's
# median.
/usr/bin/python3 - "$out" <<'EOF'
import json, statistics, sys, pathlib
out = pathlib.Path(sys.argv[1])
runs = [json.loads(p.read_text()) for p in sorted(out.glob("facet[0-9]*.json"))]
def processing(run, shapes=True):
    return sum(s["median_ms"] for s in run["stages"].values()
               if not s["stage"].startswith("io.") and (shapes or not s["stage"].startswith("shape.")))
facet = statistics.median(processing(r) for r in runs)
segmentation = statistics.median(processing(r, False) for r in runs)
total = statistics.median(r["total"]["median_ms"] for r in runs)
total_p95 = statistics.median(r["total"]["p95_ms"] for r in runs)
print(f"facet tabletop: processing stages {facet:.2f} ms (without shape fitting {segmentation:.2f}),"
      f" whole frame with file I/O {total:.2f} / p95 {total_p95:.2f} ms")
pcl = json.loads((out / "timing.json").read_text())["pipelines"]
print(f"{'pipeline':<12} {'median ms':>10} {'p95 ms':>8} {'x facet':>8} {'x facet seg.':>12}")
for name, t in pcl.items():
    print(f"{name:<12} {t['median_ms']:>10.2f} {t['p95_ms']:>8.2f} {t['median_ms'] / facet:>8.1f}"
          f" {t['median_ms'] / segmentation:>12.1f}")
EOF
