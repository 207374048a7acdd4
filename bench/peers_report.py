"""Summarises bench/peers_bench runs (peers.csv) as results/peers/README.md, and writes the same
summary between the peers markers of the top README.

usage: peers_report.py PEERS_CSV N LOAD [--readme README.md]
The Markdown goes to stdout; with --readme, the block between "<!-- peers:begin -->" and
"<!-- peers:end -->" in that file is replaced by the summary lines (the file must have both).
"""
import csv
import statistics
import sys

from readme_block import replace_block

# Issue 13's goals: CPU time ratios to CGAL, peak bytes per point on the cube, 2-thread speed-up.
TIME_GOALS = {"cube": 0.45, "grid": 0.75, "sphere": 0.70}
BYTES_PER_POINT_GOAL = 250
SPEEDUP_GOAL = 1.7
DISTRIBUTIONS = ["cube", "grid", "sphere"]


def main(argv):
    if len(argv) not in (4, 6) or (len(argv) == 6 and argv[4] != "--readme"):
        sys.exit(__doc__)
    path, n, load = argv[1], argv[2], argv[3]
    readme = argv[5] if len(argv) == 6 else None
    with open(path) as f:
        rows = list(csv.DictReader(f))
    threads = next((r["threads"] for r in rows if r["engine"] == "cavity-threads"), "?")

    def timed(dist, engine):
        return [r for r in rows
                if r["distribution"] == dist and r["engine"] == engine and r["peak_rss_bytes"] == "0"]

    def median(dist, engine, column):
        return statistics.median(float(r[column]) for r in timed(dist, engine))

    def alone_mib(dist, engine):
        alone = [r for r in rows
                 if r["distribution"] == dist and r["engine"] == engine and r["peak_rss_bytes"] != "0"]
        return int(alone[0]["peak_rss_bytes"]) / 2**20 if alone else float("nan")

    out = ["# cavity against CGAL, and cavity's threads\n",
           f"Made by `bench/run_peers_bench.sh {n}` (CGAL `Delaunay_triangulation_3<Epick>`, range "
           "insertion with its own spatial sort; cavity with its defaults: BRIO + walk + array storage, "
           "exact and perturbed). Time: seconds of order + triangulation, same process, same points, "
           "median of the runs, engines rotating. Memory: whole-process peak RSS of a process running "
           f"one engine alone. Load average when it ran: {load} on this 2-core machine; absolute times "
           "move with the load, the ratios less.\n",
           "## One thread: CPU time against CGAL\n",
           "| input | points | cavity CPU s | CGAL CPU s | time ratio | goal | cavity MiB | CGAL MiB | "
           "cavity bytes/point | tets (cavity / CGAL) |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    summary = []
    for dist in DISTRIBUTIONS:
        if not timed(dist, "cavity") or not timed(dist, "cgal"):
            continue
        points = int(timed(dist, "cavity")[0]["n"])
        cav, cgal = median(dist, "cavity", "seconds"), median(dist, "cgal", "seconds")
        ratio = cav / cgal
        goal = TIME_GOALS[dist]
        verdict = "met" if ratio <= goal else "**not met**"
        mib = alone_mib(dist, "cavity")
        per_point = mib * 2**20 / points
        mem_note = ""
        if dist == "cube":
            mem_verdict = "met" if per_point <= BYTES_PER_POINT_GOAL else "**not met**"
            mem_note = f" (goal ≤ {BYTES_PER_POINT_GOAL}: {mem_verdict})"
        tets = (timed(dist, "cavity")[0]["tets"], timed(dist, "cgal")[0]["tets"])
        out.append(f"| {dist} | {points} | {cav:.3f} | {cgal:.3f} | {ratio:.2f} | ≤ {goal}: {verdict} | "
                   f"{mib:.0f} | {alone_mib(dist, 'cgal'):.0f} | {per_point:.0f}{mem_note} | "
                   f"{tets[0]} / {tets[1]} |")
        summary.append(f"{dist} **{ratio:.2f}×** CGAL's CPU time (goal ≤ {goal}×: {verdict})")
        if dist == "cube":
            summary.append(f"cube peak memory {per_point:.0f} bytes/point (goal ≤ {BYTES_PER_POINT_GOAL}: "
                           f"{mem_verdict})")
    out += ["", f"## {threads} threads: wall time against cavity's sequential engine\n",
            "The parallel construction (`--threads`) builds the same tetrahedra as the sequential "
            "engine; the table compares wall-clock seconds of order + triangulation.\n",
            f"| input | points | sequential wall s | {threads} threads wall s | speed-up | goal | "
            f"{threads} threads MiB | same tets |",
            "|---|---|---|---|---|---|---|---|"]
    for dist in DISTRIBUTIONS:
        if not timed(dist, "cavity") or not timed(dist, "cavity-threads"):
            continue
        seq, par = median(dist, "cavity", "wall_seconds"), median(dist, "cavity-threads", "wall_seconds")
        speedup = seq / par
        verdict = "met" if speedup >= SPEEDUP_GOAL else "**not met**"
        same = timed(dist, "cavity")[0]["tets"] == timed(dist, "cavity-threads")[0]["tets"]
        out.append(f"| {dist} | {timed(dist, 'cavity')[0]['n']} | {seq:.3f} | {par:.3f} | {speedup:.2f} | "
                   f"≥ {SPEEDUP_GOAL}: {verdict} | {alone_mib(dist, 'cavity-threads'):.0f} | "
                   f"{'yes' if same else 'NO'} |")
        summary.append(f"{dist} on {threads} threads **{speedup:.2f}×** the sequential engine's wall "
                       f"speed (goal ≥ {SPEEDUP_GOAL}×: {verdict})")
    differ = [d for d in DISTRIBUTIONS
              if len({r["tets"] for r in rows if r["distribution"] == d}) > 1]
    if differ:
        out.append("\nThe tetrahedron counts differ on " + ", ".join(differ) + ": each library breaks "
                   "exact ties with its own perturbation (CGAL's is lexicographic, cavity's keyed on "
                   "the input index), and any choice is Delaunay.")
    else:
        out.append("\nAll engines produce the same number of tetrahedra on every input here.")
    print("\n".join(out))
    if readme:
        write_readme_block(readme, n, summary)


def write_readme_block(readme, n, summary):
    replace_block(readme, "peers",
                  f"- **Against CGAL 5.5, and threads** (`bench/run_peers_bench.sh {n}` → "
                  f"`results/peers/README.md`; this item is written by that script), {n} points: "
                  + "; ".join(summary) + ".")


if __name__ == "__main__":
    main(sys.argv)
