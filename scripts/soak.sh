#!/usr/bin/env bash
# Soak test: runs graphs/tabletop.yaml over the bundled frames in a loop, FRAMES frames on THREADS
# threads, samples the process's resident memory once a second, and checks what a long run must
# keep:
#   - memory flat: after the warm-up (the first WARMUP_PERCENT of the samples, at least five
#     seconds: plugins loading, buffers growing to their frame size) the largest resident size is
#     at most 5 % above the warm-up's last sample;
#   - no frame lost: with the block policy every frame is processed (frames = FRAMES); with the
#     latest policy, frames processed plus frames the source replaced cover the frames read; in
#     both, every stage ran once per processed frame, none skipped.
# Prints one line per check and the figures; exits 1 when a check fails.
#
#   scripts/soak.sh OUT [FRAMES] [POLICY] [THREADS]
#     OUT      a new folder: memory.csv (seconds, resident kB), stats.json, the run's outputs
#     FRAMES   default 10000
#     POLICY   block (recordings, the default) or latest (the live path)
#     THREADS  default 2
set -euo pipefail
out="${1:?usage: soak.sh OUT [FRAMES] [POLICY] [THREADS]}"
frames="${2:-10000}"
policy="${3:-block}"
threads="${4:-2}"
warmup_percent="${WARMUP_PERCENT:-10}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
facet="${FACET:-$here/build/bin/facet}"

mkdir -p "$out"
# Looped, the bundled frames keep their names, so the outputs are the same few files rewritten.
"$facet" run "$here/graphs/tabletop.yaml" -q --threads "$threads" --source-policy "$policy" \
  --frames "$frames" --set source.loop=true --param output="$out/run" --json "$out/stats.json" &
pid=$!
start=$SECONDS
echo "seconds,rss_kb" >"$out/memory.csv"
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  [[ -n "$rss" ]] && echo "$((SECONDS - start)),$rss" >>"$out/memory.csv"
  sleep 1
done
wait "$pid"

/usr/bin/python3 - "$out/memory.csv" "$out/stats.json" "$frames" "$policy" "$warmup_percent" <<'PY'
import csv, json, sys
memory_csv, stats_json, frames, policy, warmup_percent = sys.argv[1:6]
frames, warmup_percent = int(frames), float(warmup_percent)
samples = [int(row["rss_kb"]) for row in csv.DictReader(open(memory_csv))]
stats = json.load(open(stats_json))
ok = True
if len(samples) < 10:
    print(f"memory: only {len(samples)} samples; run more frames")
    ok = False
else:
    warm = int(max(5, len(samples) * warmup_percent // 100))
    base = samples[warm - 1]
    peak = max(samples[warm:])
    growth = (peak - base) / base
    flat = growth <= 0.05
    ok &= flat
    print(f"memory: {len(samples)} samples, after warm-up {base / 1024:.0f} MB, peak after it "
          f"{peak / 1024:.0f} MB ({100 * growth:+.1f} %), last {samples[-1] / 1024:.0f} MB: "
          f"{'flat' if flat else 'GROWING'}")
processed = stats["frames"]
dropped = stats["total"]["dropped"]
if policy == "block":
    whole = processed == frames and dropped == 0
    print(f"frames: {processed} of {frames} processed, {dropped} dropped: "
          f"{'none lost' if whole else 'LOST'}")
else:
    whole = processed > 0 and processed + dropped >= frames
    print(f"frames: {processed} processed and {dropped} replaced by newer ones, of {frames}: "
          f"{'all accounted for' if whole else 'LOST'}")
ok &= whole
partial = [f"{node} ({s['calls']} calls, {s['skipped']} skipped)"
           for node, s in stats["stages"].items()
           if s["calls"] != processed or s["skipped"] != 0]
print("stages: every stage ran once per frame" if not partial
      else "stages: NOT ONCE PER FRAME: " + ", ".join(partial))
ok &= not partial
print(f"time per frame: median {stats['total']['median_ms']:.1f} ms, "
      f"throughput {stats['total']['throughput_fps']:.1f} frames/s")
sys.exit(0 if ok else 1)
PY
