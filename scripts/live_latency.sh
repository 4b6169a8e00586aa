#!/usr/bin/env bash
# Does the latency of a live `latest` stream stay flat over a long run? Turns a dataset folder
# into an .oni recording (graphs/record_oni.yaml), plays it through graphs/live.yaml in a loop at
# SPEED times its 30 Hz (faster than the graph can follow, so stale frames are dropped), with
# `--source-policy latest` and a trace, and prints the median per-frame latency of each tenth of
# the run (first source call to the end of the frame's last stage call, from the trace), the p95
# of the first and last tenth, and the frames the source dropped. No window: io.view warns once.
#
#   scripts/live_latency.sh DATASET [OUT [FRAMES [SPEED [THREADS]]]]
#     defaults: OUT out/live_latency, FRAMES 6000, SPEED 6, THREADS 2
#   FACET_BUILD_DIR  build tree holding bin/facet (default build)
set -euo pipefail
dataset="${1:?dataset folder}"
out="${2:-out/live_latency}"
frames="${3:-6000}"
speed="${4:-6}"
threads="${5:-2}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="${FACET_BUILD_DIR:-$here/build}/bin/facet"
[[ -x "$facet" ]] || { echo "no $facet (build it first)" >&2; exit 2; }
mkdir -p "$out"
"$facet" run "$here/graphs/record_oni.yaml" -q --param input="$dataset" \
  --param output="$out/take.oni"
DISPLAY='' WAYLAND_DISPLAY='' "$facet" run "$here/graphs/live.yaml" -q --threads "$threads" \
  --source-policy latest --param uri="$out/take.oni" --set source.speed="$speed" \
  --set source.loop=true -n "$frames" --trace "$out/trace.json" --json "$out/run.json" 2>/dev/null
python3 - "$out/trace.json" "$out/run.json" <<'PY'
import json, statistics, sys
trace = json.load(open(sys.argv[1]))
events = trace["traceEvents"] if isinstance(trace, dict) else trace
span = {}
for e in events:
    if e.get("ph") != "X":
        continue
    frame, begin, end = e["args"]["frame"], e["ts"], e["ts"] + e["dur"]
    low, high = span.get(frame, (begin, end))
    span[frame] = (min(low, begin), max(high, end))
latency = [(span[f][1] - span[f][0]) / 1000 for f in sorted(span)]
tenth = len(latency) // 10
medians = [statistics.median(latency[i * tenth:(i + 1) * tenth]) for i in range(10)]
def p95(values):
    return sorted(values)[int(0.95 * (len(values) - 1))]
run = json.load(open(sys.argv[2]))
dropped = run["stages"]["source"]["metrics"]["dropped_frames"]["mean"] * len(latency)
print(f"{len(latency)} frames, {run['total']['wall_ms'] / 1000:.1f} s, "
      f"{run['total']['throughput_fps']:.1f} frames/s processed, {dropped:.0f} dropped by the source")
print("median latency per tenth of the run (ms): " + " ".join(f"{m:.2f}" for m in medians))
print(f"p95 latency, first tenth {p95(latency[:tenth]):.2f} ms, last tenth {p95(latency[-tenth:]):.2f} ms")
PY
