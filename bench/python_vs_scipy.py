#!/usr/bin/python3
"""cavity.Delaunay beside scipy.spatial.Delaunay (Qhull), measured side by side in one run.

For each size n and repeat, one fresh process per tool (the two alternate which goes first) draws
the same n uniform points in the unit cube, times the construction (CPU seconds of the calling
thread, and wall seconds) and reports the process's peak memory and a digest of its tetrahedra
(sorted vertex sets), so that "the same tetrahedra" is checked, not assumed. A last measurement
triangulates two point sets of n points in two threads of one process, against the same two one
after the other, to show the GIL released during construction.

Writes OUT/python_vs_scipy.csv (one row per measurement) and OUT/README.md (medians, ratios and
the goals of the Python issue, all computed here from the CSV's rows):

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_vs_scipy.py --out results/python
"""

import argparse
import csv
import hashlib
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import threading
import time

import numpy as np

FIELDS = ["n", "repeat", "tool", "cpu_s", "wall_s", "peak_mib", "tets", "digest", "load1"]
#: The Python issue's goals: CPU-time ratio scipy / cavity by size.
GOALS = {100_000: 10.0, 1_000_000: 12.0}


def points(n, seed):
    return np.random.default_rng(seed).random((n, 3))


def digest(simplices):
    s = np.sort(np.asarray(simplices, dtype=np.int64), axis=1)
    s = s[np.lexsort(s.T[::-1])]
    return hashlib.sha256(s.tobytes()).hexdigest()[:16]


def worker(tool, n, seed):
    """Runs in a fresh process: one construction, reported as JSON on stdout."""
    p = points(n, seed)
    if tool == "cavity":
        import cavity
        make = cavity.Delaunay
    else:
        from scipy.spatial import Delaunay as make
    wall, cpu = time.perf_counter(), time.thread_time()
    tri = make(p)
    cpu, wall = time.thread_time() - cpu, time.perf_counter() - wall
    peak_mib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(json.dumps(dict(cpu_s=cpu, wall_s=wall, peak_mib=peak_mib, tets=len(tri.simplices),
                          digest=digest(tri.simplices))))


def threads_worker(n, seed):
    """Two point sets: one after the other, then in two threads (wall seconds of each)."""
    import cavity
    sets = [points(n, seed), points(n, seed + 1)]
    start = time.perf_counter()
    sequential = [cavity.Delaunay(s) for s in sets]
    one_by_one = time.perf_counter() - start
    out = [None, None]
    runners = [threading.Thread(target=lambda i=i: out.__setitem__(i, cavity.Delaunay(sets[i])))
               for i in range(2)]
    start = time.perf_counter()
    for t in runners:
        t.start()
    for t in runners:
        t.join()
    parallel = time.perf_counter() - start
    same = all(np.array_equal(a.simplices, b.simplices) for a, b in zip(sequential, out))
    print(json.dumps(dict(sequential_s=one_by_one, threads_s=parallel, same=same)))


def run(args):
    command = [sys.executable, os.path.abspath(__file__)] + args
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def git_commit():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], check=True, text=True,
                              capture_output=True,
                              cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def report(rows, threads, out, meta):
    lines = [
        "# cavity.Delaunay beside scipy.spatial.Delaunay",
        "",
        "Written by `bench/python_vs_scipy.py` from the measurements in",
        "[python_vs_scipy.csv](python_vs_scipy.csv), all of one run; nothing here is typed.",
        "",
        "Each measurement is a fresh process that draws the same uniform points in the unit cube",
        "(numpy `default_rng(seed)`) and builds one triangulation with the defaults. Time is CPU",
        "seconds of the calling thread (both run on one thread, so CPU time is the fair measure on",
        "a shared machine) and wall seconds; memory is the process's peak resident set. The tools",
        "alternate which goes first. Medians over the repeats; ratios are scipy / cavity.",
        "",
        f"Run: {meta['date']}, commit {meta['commit']}, scipy {meta['scipy']}, numpy "
        f"{meta['numpy']}, cavity {meta['cavity']}, {meta['cpus']} CPUs; load average "
        f"{meta['load_before']:.2f} before, {meta['load_after']:.2f} after.",
        "",
        "| n | cavity CPU s | scipy CPU s | **CPU ratio** | goal | wall ratio | cavity peak MiB "
        "| scipy peak MiB | same tetrahedra |",
        "|---:|---:|---:|---:|---|---:|---:|---:|---|",
    ]
    for n in sorted({r["n"] for r in rows}):
        mine = [r for r in rows if r["n"] == n and r["tool"] == "cavity"]
        theirs = [r for r in rows if r["n"] == n and r["tool"] == "scipy"]

        def med(rs, key):
            return statistics.median(float(r[key]) for r in rs)

        ratio = med(theirs, "cpu_s") / med(mine, "cpu_s")
        goal = GOALS.get(n)
        verdict = "–" if goal is None else (
            f"≥ {goal:g}×: {'met' if ratio >= goal else '**not met**'}")
        same = len({r["digest"] for r in mine + theirs}) == 1
        lines.append(
            f"| {n:,} | {med(mine, 'cpu_s'):.3f} | {med(theirs, 'cpu_s'):.3f} | **{ratio:.1f}×** "
            f"| {verdict} | {med(theirs, 'wall_s') / med(mine, 'wall_s'):.1f}× "
            f"| {med(mine, 'peak_mib'):.0f} | {med(theirs, 'peak_mib'):.0f} "
            f"| {'yes' if same else '**no**'} ({int(mine[0]['tets']):,}) |")
    memory_ok = all(
        statistics.median(float(r["peak_mib"]) for r in rows if r["n"] == n and r["tool"] == t1)
        < statistics.median(float(r["peak_mib"]) for r in rows if r["n"] == n and r["tool"] == t2)
        for n in {r["n"] for r in rows} for t1, t2 in [("cavity", "scipy")])
    lines += [
        "",
        f"Memory below scipy's at every size: {'yes' if memory_ok else '**no**'}.",
        "",
        f"Two threads, each triangulating its own {threads['n']:,} points, in one process: "
        f"{threads['threads_s']:.2f} s wall against {threads['sequential_s']:.2f} s one after "
        f"the other ({threads['sequential_s'] / threads['threads_s']:.2f}× on "
        f"{meta['cpus']} CPUs; identical tetrahedra: {'yes' if threads['same'] else '**no**'}).",
        "",
    ]
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100_000, 1_000_000])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", help="directory for python_vs_scipy.csv and README.md")
    parser.add_argument("--worker", choices=["cavity", "scipy", "threads"], help=argparse.SUPPRESS)
    parser.add_argument("--n", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker == "threads":
        threads_worker(args.n, args.seed)
        return
    if args.worker:
        worker(args.worker, args.n, args.seed)
        return
    if not args.out:
        parser.error("--out is required")
    try:
        import scipy
    except ImportError:
        print("scipy is not installed (Debian: python3-scipy)", file=sys.stderr)
        sys.exit(77)  # ctest's "skipped"
    import cavity

    load_before = os.getloadavg()[0]
    rows = []
    for n in args.sizes:
        for repeat in range(args.repeats):
            tools = ["cavity", "scipy"] if repeat % 2 == 0 else ["scipy", "cavity"]
            for tool in tools:
                r = run(["--worker", tool, "--n", str(n), "--seed", str(args.seed)])
                rows.append(dict(n=n, repeat=repeat, tool=tool, load1=os.getloadavg()[0], **r))
                print(f"n={n} repeat={repeat} {tool}: {r['cpu_s']:.3f} s CPU, "
                      f"{r['peak_mib']:.0f} MiB", file=sys.stderr)
    threads = run(["--worker", "threads", "--n", str(max(args.sizes)), "--seed",
                   str(args.seed)])
    threads["n"] = max(args.sizes)
    meta = dict(date=time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), commit=git_commit(),
                scipy=scipy.__version__, numpy=np.__version__, cavity=cavity.__version__,
                cpus=os.cpu_count(), load_before=load_before, load_after=os.getloadavg()[0],
                python=platform.python_version())
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "python_vs_scipy.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        for r in rows:
            writer.writerow({k: r[k] for k in FIELDS})
    report(rows, threads, args.out, meta)


if __name__ == "__main__":
    main()
