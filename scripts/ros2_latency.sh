#!/usr/bin/env bash
# Latency of a facet graph on a ROS 2 camera over DDS on this computer's loopback interface:
# graphs/ros2_camera.yaml plays the bundled frames (looped) as a live camera, stamping each frame
# when it publishes it; graphs/ros2_tabletop.yaml in a second process segments them and publishes
# the labels. Prints the medians of the subscriber's metrics: latency_ms (camera publish stamp to
# the frame taken from DDS) and stamp_age_ms (camera publish stamp to labels published), and the
# frames it dropped (qos sensor: it takes the newest frame).
#
#   scripts/ros2_latency.sh [frames] [fps] [qos]     # defaults: 300 frames, 30 Hz, sensor
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
frames="${1:-300}"
fps="${2:-30}"
qos="${3:-sensor}"
work="$(mktemp -d)"
subscriber=""
# The subscriber is stopped if this script ends early (an error, Ctrl-C).
trap '[ -n "$subscriber" ] && kill "$subscriber" 2>/dev/null; rm -rf "$work"' EXIT
export CYCLONEDDS_URI='<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><Peers><Peer address="127.0.0.1"/></Peers><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>50</MaxAutoParticipantIndex></Discovery></Domain></CycloneDDS>'
export ROS_DOMAIN_ID=$(( 100 + $$ % 100 ))
topic="/latency_$$/depth"
"$here/build/bin/facet" run "$here/graphs/ros2_tabletop.yaml" -q --param topic="$topic" \
  --param labels_topic="/latency_$$/labels" --param objects_topic="/latency_$$/objects" \
  --param markers_topic="/latency_$$/markers" --param qos="$qos" --param idle_timeout_s=2 \
  --param output="$work/out" --json "$work/subscriber.json" &
subscriber=$!
"$here/build/bin/facet" run "$here/graphs/ros2_camera.yaml" -q --param topic="$topic" \
  --param fps="$fps" --set source.loop=true --frames "$frames" --set camera.wait_for_readers=1
wait "$subscriber"
subscriber=""
python3 - "$work/subscriber.json" "$frames" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
frames = stats["frames"]
source = stats["stages"]["source"]["metrics"]
publish = stats["stages"]["publish"]["metrics"]
print(f"published {sys.argv[2]}, segmented {frames}, "
      f"dropped {round(source['dropped_frames']['mean'] * frames)}")
print(f"latency_ms (publish stamp -> taken from DDS): median {source['latency_ms']['median']:.2f}, "
      f"max {source['latency_ms']['max']:.2f}")
print(f"stamp_age_ms (publish stamp -> labels out): median {publish['stamp_age_ms']['median']:.2f}, "
      f"max {publish['stamp_age_ms']['max']:.2f}")
PY
