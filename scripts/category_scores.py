#!/usr/bin/env python3
"""Per-category F of a score.py result (--json, per image), from a dataset's frames.csv.

    category_scores.py SCORE_JSON FRAMES_CSV            prints "F per category: boxes (17) 0.981, ..."
    category_scores.py SCORE_JSON FRAMES_CSV --row NAME prints a markdown table row for NAME:
                                                        P, R, F, seg %, over, under, merged, categories

A category's F is the mean of its frames' F. Frames missing from frames.csv count as "?".
"""
import argparse
import csv
import json
import os
from collections import defaultdict


def per_category(overlap, frames_csv):
    with open(frames_csv, newline="") as f:
        category = {row["frame"]: row["category"] for row in csv.DictReader(f)}
    scores = defaultdict(list)
    for image in overlap["images"]:
        stem = os.path.splitext(os.path.basename(image["key"]))[0]
        scores[category.get(stem, "?")].append(image["f_measure"])
    return ", ".join(f"{name} ({len(f)}) {sum(f) / len(f):.3f}" for name, f in sorted(scores.items()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("score_json")
    parser.add_argument("frames_csv")
    parser.add_argument("--row", metavar="NAME", help="print a markdown table row for NAME")
    args = parser.parse_args()
    with open(args.score_json) as f:
        overlap = json.load(f)["overlap"]
    categories = per_category(overlap, args.frames_csv)
    if args.row is None:
        print(f"F per category: {categories}")
        return
    o = overlap["overall"]
    print(f"| {args.row} | {100 * o['precision']:.1f} | {100 * o['recall']:.1f} | "
          f"**{o['f_measure']:.3f}** | {o['objects_segmented_pct']:.1f} | {o['over_segmented']} | "
          f"{o['under_segmenting']} | {o['merged_objects']} | {categories} |")


if __name__ == "__main__":
    main()
