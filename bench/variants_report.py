"""Tabulates the --stats JSON files of bench/run_variants.sh as results/variants/README.md.

usage: variants_report.py FOLDER LOAD [--readme README.md]
The page goes to stdout; with --readme, the item between "<!-- variants:begin -->" and
"<!-- variants:end -->" of that file is rewritten from the same files.
"""
import glob
import json
import os
import sys

from readme_block import replace_block

if len(sys.argv) not in (3, 5) or (len(sys.argv) == 5 and sys.argv[3] != "--readme"):
    sys.exit(__doc__)
folder, load = sys.argv[1], sys.argv[2]
readme = sys.argv[4] if len(sys.argv) == 5 else None
runs = []
for path in sorted(glob.glob(os.path.join(folder, "*.json"))):
    d = json.load(open(path))
    runs.append(d)
runs.sort(key=lambda d: (d["points"], d["locate"], d["storage"]))
print("# Algorithm variants at scale\n")
print("Made by `bench/run_variants.sh` (uniform points in the cube, BRIO order, instrumented runs "
      "with `--stats`; wall-clock seconds of the triangulation alone). Load average while it ran: "
      f"{load} on a shared 2-core machine, so the times are inflated and noisy; the counts are "
      "exact.\n")
print("| points | locate | storage | seconds | µs/point | peak RSS MiB | B/point | tets | created/pt | walk steps/pt | redistributed/pt | hash probes/pt |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
base = {}
for d in runs:
    n = d["points"]
    c = d["counters"]
    t = d["timings"]["triangulate_s"]
    rss = d["peak_rss_bytes"]
    print(f"| {n} | {d['locate']} | {d['storage']} | {t:.2f} | {1e6 * t / n:.2f} | {rss / 2**20:.0f} | "
          f"{rss / n:.0f} | {d['counts']['tets']} | {c['tets_created'] / n:.2f} | {c['walk_steps'] / n:.2f} | "
          f"{c['points_redistributed'] / n:.2f} | {c['hash_probes'] / n:.1f} |")
print("\nRatios against walking + array storage at the same size (time, peak memory):\n")
ref = {d["points"]: d for d in runs if d["locate"] == "walk" and d["storage"] == "array"}
for d in runs:
    r = ref.get(d["points"])
    if r is None or d is r:
        continue
    print(f"- {d['locate']} + {d['storage']} at {d['points']}: time × "
          f"{d['timings']['triangulate_s'] / r['timings']['triangulate_s']:.2f}, memory × "
          f"{d['peak_rss_bytes'] / r['peak_rss_bytes']:.2f}")


def readme_item():
    """The top README's summary: the largest walk run's peak memory and time, and the variants'
    time and memory ratios at the size where all four ran. (The goal of 10^8 points within 24 GiB
    is bench/run_scale_bench.sh's: these runs go through the CLI and write their meshes.)"""
    walk = [d for d in runs if d["locate"] == "walk" and d["storage"] == "array"]
    largest = max(walk, key=lambda d: d["points"])
    n = largest["points"]
    gib = largest["peak_rss_bytes"] / 2**30
    parts = [f"{n} points triangulate with `cavity triangulate` in {gib:.2f} GiB peak, "
             f"{1e6 * largest['timings']['triangulate_s'] / n:.1f} µs/point instrumented"]
    for size in sorted(ref):
        r = ref[size]
        ratio = {(d["locate"], d["storage"]): d for d in runs if d["points"] == size and d is not r}
        graph, hashed = ratio.get(("conflict-graph", "array")), ratio.get(("walk", "hash"))
        if graph is None or hashed is None:
            continue
        parts.append(
            f"at {size} points the conflict graph takes "
            f"{graph['timings']['triangulate_s'] / r['timings']['triangulate_s']:.1f}× the walk's time and "
            f"{graph['peak_rss_bytes'] / r['peak_rss_bytes']:.1f}× its memory, the book's face hash table "
            f"{hashed['timings']['triangulate_s'] / r['timings']['triangulate_s']:.1f}× the time and "
            f"{hashed['peak_rss_bytes'] / r['peak_rss_bytes']:.1f}× the memory of the array storage")
    return ("- **Variants at scale** (`bench/run_variants.sh` → `results/variants/README.md`; this item "
            "is written by that script), uniform points: " + "; ".join(parts) + ".")


if readme:
    replace_block(readme, "variants", readme_item())
