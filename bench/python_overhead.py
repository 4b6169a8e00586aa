#!/usr/bin/env python3
"""Times facet.Pipeline on graphs/tabletop.yaml from Python, one bundled frame, one thread:
the median milliseconds per call, to set beside build/bin/facet_bench_pipeline (the same graph
and frame through the C++ API). The difference is what the Python layer costs per frame.

    PYTHONPATH=build/python python3 bench/python_overhead.py [--frames 200]
"""

import argparse
import pathlib
import statistics
import time

import cv2

import facet

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=200)
    args = parser.parse_args()
    seg = facet.Pipeline(ROOT / "graphs" / "tabletop.yaml")
    depth = cv2.imread(str(ROOT / "data" / "mosd" / "depth" / "learn0.png"), cv2.IMREAD_UNCHANGED)
    intrinsics = (525.0, 525.0, 319.5, 239.5)
    for _ in range(10):  # warm-up: caches, allocator
        seg(depth, intrinsics=intrinsics)
    calls, inside, outside = [], [], []
    for _ in range(args.frames):
        start = time.perf_counter()
        out = seg(depth, intrinsics=intrinsics)
        call = (time.perf_counter() - start) * 1000.0
        stages = sum(out.timings.values())
        calls.append(call)
        inside.append(stages)
        outside.append(call - stages)
    # Outside the stages: the median over the frames of each call's time minus its stage calls,
    # as facet_bench_pipeline's outside_stages_ms; the difference of the two medians would carry
    # the frame-to-frame spread of the stages' time, which is far larger.
    print(f"python call: median {statistics.median(calls):.3f} ms over {args.frames} frames")
    print(f"stage calls inside it: median {statistics.median(inside):.3f} ms; outside the stages: "
          f"{statistics.median(outside):.3f} ms")


if __name__ == "__main__":
    main()
