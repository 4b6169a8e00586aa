#!/usr/bin/env python3
"""Segments a bundled depth frame with graphs/tabletop.yaml and shows the objects over the depth.

    PYTHONPATH=build/python python3 examples/segment.py [--frame learn18] [--save overlay.png]
"""

import argparse
import pathlib

import cv2
import matplotlib.pyplot as plt
import numpy as np

import facet

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frame", default="learn0", help="a stem in data/mosd/depth")
    parser.add_argument("--save", help="write the picture to this file instead of showing it")
    args = parser.parse_args()

    seg = facet.Pipeline(ROOT / "graphs" / "tabletop.yaml")
    depth = cv2.imread(str(ROOT / "data" / "mosd" / "depth" / f"{args.frame}.png"),
                       cv2.IMREAD_UNCHANGED)  # uint16 millimetres
    out = seg(depth, intrinsics=(525.0, 525.0, 319.5, 239.5), stem=args.frame)

    labels = out["labels"]
    print(f"{args.frame}: {len(out['objects'])} objects in "
          f"{sum(out.timings.values()):.1f} ms")
    for obj in out["objects"]:
        print(f"  object {obj['id']}: {obj['pixel_count']} px, centroid "
              f"{np.round(obj['centroid_m'], 3).tolist()} m, grasp {obj['grasp']}")

    objects = np.ma.masked_equal(labels, 0)
    plt.figure(figsize=(8, 6))
    plt.imshow(np.where(depth > 0, depth, np.nan), cmap="gray")
    plt.imshow(objects, cmap="tab20", alpha=0.6, interpolation="nearest")
    plt.title(f"{args.frame}: {len(out['objects'])} objects")
    plt.axis("off")
    if args.save:
        plt.savefig(args.save, dpi=100, bbox_inches="tight")
    else:
        plt.show()


if __name__ == "__main__":
    main()
