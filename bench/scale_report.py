"""Summarises bench/run_scale_bench.sh's run (scale.csv) as results/scale/README.md, and writes the
same summary between the scale markers of the top README.

usage: scale_report.py SCALE_CSV MEM_TOTAL_BYTES LOAD [--readme README.md]
"""
import csv
import sys

from readme_block import replace_block

# Issue 13: 10^8 points within 24 GiB.
GOAL_POINTS = 100_000_000
GOAL_BYTES = 24 * 2**30


def main(argv):
    if len(argv) not in (4, 6) or (len(argv) == 6 and argv[4] != "--readme"):
        sys.exit(__doc__)
    with open(argv[1]) as f:
        rows = [r for r in csv.DictReader(f) if r["peak_rss_bytes"] != "0"]
    if not rows:
        sys.exit(f"{argv[1]}: no run with a peak memory")
    mem_total, load = int(argv[2]), argv[3]
    out = ["# cavity at scale\n",
           "Made by `bench/run_scale_bench.sh` (`bench/peers_bench --only cavity`): uniform points in "
           "the unit cube generated in the process, then cavity's defaults (BRIO order with ratio 1/8, "
           "Hilbert curve within rounds, walking location, array storage, the sequential engine, exact "
           "and perturbed). Time: CPU and wall seconds of order + triangulation. Memory: the whole "
           "process's peak resident set, which holds the points, the order and the mesh; nothing is "
           "written. The machine's physical memory: "
           f"{mem_total / 2**30:.2f} GiB. Load average while it ran: {load}.\n",
           "| points | CPU s | wall s | µs/point | tetrahedra | tets/point | peak GiB | bytes/point | goal |",
           "|---|---|---|---|---|---|---|---|---|"]
    summary = []
    for r in rows:
        n, peak = int(r["n"]), int(r["peak_rss_bytes"])
        goal = ""
        if n >= GOAL_POINTS:
            verdict = "met" if peak <= GOAL_BYTES else "**not met**"
            goal = f"within 24 GiB: {verdict}"
            summary.append(f"{n} points in {peak / 2**30:.2f} GiB peak, {peak / n:.0f} bytes/point "
                           f"(goal: 10⁸ within 24 GiB, {verdict}), {float(r['seconds']):.0f} CPU s")
        out.append(f"| {n} | {float(r['seconds']):.1f} | {float(r['wall_seconds']):.1f} | "
                   f"{1e6 * float(r['seconds']) / n:.2f} | {r['tets']} | {int(r['tets']) / n:.3f} | "
                   f"{peak / 2**30:.2f} | {peak / n:.0f} | {goal or '—'} |")
    print("\n".join(out))
    if len(argv) == 6:
        item = ("- **Scale** (`bench/run_scale_bench.sh` → `results/scale/README.md`; this item is "
                "written by that script), uniform cube, cavity's defaults: "
                + ("; ".join(summary) if summary else
                   f"largest run {max(int(r['n']) for r in rows)} points, below the 10⁸ of the goal")
                + ".")
        replace_block(argv[5], "scale", item)


if __name__ == "__main__":
    main(sys.argv)
