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
    calls, inside = [], []
    for _ in range(args.frames):
        start = time.perf_counter()
        out = seg(depth, intrinsics=intrinsics)
        calls.append((time.perf_counter() - start) * 1000.0)
        inside.append(sum(out.timings.values()))
    call, stages = statistics.median(calls), statistics.median(inside)
    print(f"python call: median {call:.3f} ms over {args.frames} frames")
    print(f"stage calls inside it: median {stages:.3f} ms; outside the stages: "
          f"{call - stages:.3f} ms")


if __name__ == "__main__":
    main()
