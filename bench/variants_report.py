"""Tabulates the --stats JSON files of bench/run_variants.sh as results/variants/README.md."""
import glob
import json
import os
import sys

folder, load = sys.argv[1], sys.argv[2]
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
