#!/usr/bin/python3
"""Plots and summary tables from the experiment CSVs (cavity experiment ... --out IN_DIR).

Usage: /usr/bin/python3 results/plot.py IN_DIR OUT_DIR
Writes OUT_DIR/*.png and *.svg, and OUT_DIR/summary.md with every number the report quotes.
Suites whose CSV is missing are skipped. Run with Debian's python3-matplotlib.
"""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Derived constants (docs experiments.md §1.3): Poisson–Delaunay in 3D.
TETS_PER_POINT = 24 * math.pi**2 / 35          # 6.768
CREATED_PER_POINT = 96 * math.pi**2 / 35       # 27.07
DELETED_PER_POINT = CREATED_PER_POINT - TETS_PER_POINT  # 20.30
F_CONST = 4 * math.pi**2 / 35                  # F_j/n -> F_CONST (j+1)(j+2)(j+3)


def read(path):
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(row, key):
    return float(row[key])


def save(fig, out, name):
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, f"{name}.{ext}"), dpi=110, bbox_inches="tight")
    plt.close(fig)


def slope(xs, ys):
    """Least-squares slope of log y against log x."""
    lx, ly = np.log(np.asarray(xs, float)), np.log(np.asarray(ys, float))
    return float(np.polyfit(lx, ly, 1)[0]) if len(set(xs)) > 1 else float("nan")


def group(rows, *keys):
    groups = defaultdict(list)
    for r in rows:
        groups[tuple(r[k] for k in keys)].append(r)
    return groups


def mean_by_n(rows, key):
    by_n = defaultdict(list)
    for r in rows:
        by_n[int(r["points"])].append(num(r, key))
    ns = sorted(by_n)
    return ns, [float(np.mean(by_n[n])) for n in ns]


def plot_jtets(inp, out, md):
    rows = read(os.path.join(inp, "jtets.j.csv"))
    if rows is None:
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    md.append("## jtets (Proposition 5.1)\n")
    md.append("| dist | n | j | F_j | F_j/n | Poisson limit of F_j/n | F_j/(j^3 n) | F_j/(j^2 n^2) | closed form f_j |")
    md.append("|---|---|---|---|---|---|---|---|---|")
    for (dist, n), rs in sorted(group(rows, "dist", "n").items(), key=lambda kv: (kv[0][0], int(kv[0][1]))):
        n = int(n)
        js = np.array([int(r["j"]) for r in rs])
        F = np.array([num(r, "F_j") for r in rs])
        if dist == "cube":
            axes[0].loglog(js + 1, F / n, "o-", ms=3, label=f"cube n={n}")
        else:
            axes[1].loglog(js + 1, F / n**2, "o-", ms=3, label=f"{dist} n={n}")
        for r in rs:
            j = int(r["j"])
            if j in (1, 2, 4, 8, 16) or j == int(rs[-1]["j"]):
                Fj = num(r, "F_j")
                md.append(f"| {dist} | {n} | {j} | {int(Fj)} | {Fj / n:.1f} | "
                          f"{F_CONST * (j + 1) * (j + 2) * (j + 3):.1f} | {Fj / (j**3 * n):.3f} | "
                          f"{Fj / (j**2 * n**2):.4f} | {r['closed_form_f_j']} |")
    j = np.arange(0, 60)
    axes[0].loglog(j + 1, F_CONST * (j + 1) * (j + 2) * (j + 3), "k--",
                   label=r"$(4\pi^2/35)(j+1)(j+2)(j+3)$ (Poisson limit)")
    axes[0].set(xlabel="j + 1", ylabel="$F_j / n$", title="uniform points: $F_j = O(j^3 n)$")
    axes[1].loglog(j + 1, (j + 1) * (j + 2) / 8.0, "k--", label=r"$(j+1)(j+2)/8$ (two lines, $j \ll m$)")
    axes[1].set(xlabel="j + 1", ylabel="$F_j / n^2$", title="quadratic families: $F_j = O(j^2 n^2)$")
    for ax in axes:
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    save(fig, out, "jtets")
    md.append("")
    meta = read(os.path.join(inp, "jtets.csv"))
    for r in meta:
        if r["closed_form_match"] != "-":
            md.append(f"- skew-lines n={r['n']}: pencil sweep equals the closed form: "
                      f"{'yes' if r['closed_form_match'] == '1' else 'NO'} ({r['time_s']} s)")
    md.append("")


def plot_creation(inp, out, md):
    rows = read(os.path.join(inp, "creation.j.csv"))
    runs = read(os.path.join(inp, "creation.csv"))
    if rows is None:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    md.append("## creation (Propositions 5.2, 5.3)\n")
    for r in runs:
        md.append(f"- {r['dist']} n={r['n']} order={r['order']}: {r['orders']} orders, "
                  f"created solid tets per order {float(r['created_mean']):.1f}, "
                  f"creation-rule violations {r['rule_violations']}")
    md.append("")
    md.append("| order | j | f_j | created | q_hat | 1/C(j+4,4) | z | j^4 q_hat |")
    md.append("|---|---|---|---|---|---|---|---|")
    for (order,), rs in sorted(group(rows, "order").items()):
        R = int(next(r for r in runs if r["order"] == order)["orders"])
        js, y, err = [], [], []
        for r in rs:
            j, f, c = int(r["j"]), num(r, "f_j"), num(r, "created")
            q0 = num(r, "q_uniform")
            if j == 0 or f * R * q0 < 20:
                continue
            q = c / (R * f)
            js.append(j)
            y.append(q * j**4)
            err.append(math.sqrt(max(c, 1)) / (R * f) * j**4)
            z = (c - R * f * q0) / math.sqrt(R * f * q0 * (1 - q0))
            if j in (1, 2, 3, 4, 6, 8, 12, 16, 24, 32):
                md.append(f"| {order} | {j} | {int(f)} | {int(c)} | {q:.3e} | {q0:.3e} | {z:+.2f} | {q * j**4:.1f} |")
        ax.errorbar(js, y, yerr=err, fmt="o", ms=3, label=f"{order} order (measured)")
    j = np.arange(1, 60)
    ax.plot(j, 24 * j**4 / ((j + 1) * (j + 2) * (j + 3) * (j + 4)), "k-", lw=1,
            label=r"uniform: $j^4/\binom{j+4}{4}$")
    ax.axhline(24, color="g", ls="--", label="Prop. 5.2 bound 4! = 24")
    ax.axhline(385, color="r", ls="--", label="Prop. 5.3 bound 16·4!+1 = 385")
    ax.set(xscale="log", yscale="log", xlabel="j", ylabel=r"$j^4 \hat q_j$",
           title="creation probability of a j-tetrahedron")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, out, "creation")
    md.append("")


def plot_scaling(inp, out, md):
    rows = read(os.path.join(inp, "scaling.csv"))
    if rows is None:
        return
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    md.append("## scaling (Theorem 5.4)\n")
    md.append("| dist | order | locate | n (largest) | created/n | deleted/n | tets/n | walk steps/n | "
              "µs/point | slope of time | slope of created |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for (dist, order, locate), rs in sorted(group(rows, "dist", "order", "locate").items()):
        ns, created = mean_by_n(rs, "created_per_point")
        _, deleted = mean_by_n(rs, "deleted_per_point")
        _, tets = mean_by_n(rs, "tets")
        _, t = mean_by_n(rs, "time_s")
        _, walk = mean_by_n(rs, "walk_steps_per_point")
        _, us = mean_by_n(rs, "us_per_point")
        label = f"{dist} {order} {locate}"
        if dist == "cube":
            axes[0].semilogx(ns, created, "o-", ms=3, label=f"created, {order} {locate}")
            axes[0].semilogx(ns, deleted, "s--", ms=3, label=f"deleted, {order} {locate}")
        axes[1].loglog(ns, t, "o-", ms=3, label=f"{label} (slope {slope(ns, t):.2f})")
        axes[2].semilogx(ns, us, "o-", ms=3, label=label)
        tot_created = [c * n for c, n in zip(created, ns)]
        md.append(f"| {dist} | {order} | {locate} | {ns[-1]} | {created[-1]:.2f} | {deleted[-1]:.2f} | "
                  f"{tets[-1] / ns[-1]:.3f} | {walk[-1]:.2f} | {us[-1]:.2f} | {slope(ns, t):.2f} | "
                  f"{slope(ns, tot_created):.3f} |")
    axes[0].axhline(CREATED_PER_POINT, color="k", ls=":", label="27.07 (limit, uniform order)")
    axes[0].axhline(DELETED_PER_POINT, color="gray", ls=":", label="20.30")
    axes[0].set(xlabel="n", ylabel="per point", title="cube: tetrahedra created / deleted per point")
    n = np.array([1e3, 1e5])
    axes[1].loglog(n, 1e-6 * n * np.log(n) / np.log(1e3), "k:", label=r"$\propto n \log n$")
    axes[1].set(xlabel="n", ylabel="seconds", title="time (log–log, fitted slopes)")
    axes[2].set(xlabel="n", ylabel="µs per point", title="time per point")
    for ax in axes:
        ax.legend(fontsize=6)
        ax.grid(True, which="both", alpha=0.3)
    save(fig, out, "scaling")
    md.append("")


def plot_loglog_suite(inp, out, md, suite, key, title, ylabel, per_point, ref):
    rows = read(os.path.join(inp, f"{suite}.csv"))
    if rows is None:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    md.append(f"## {suite}: {title}\n")
    md.append(f"| dist | order | n range | {key}{'/n' if per_point else ''} at largest n | fitted slope |")
    md.append("|---|---|---|---|---|")
    for (dist, order), rs in sorted(group(rows, "dist", "order").items()):
        ns, ys = mean_by_n(rs, key)
        if per_point:
            ys = [y / n for y, n in zip(ys, ns)]
        ys_plot = [max(y, 1e-3) for y in ys]
        s = slope(ns, ys_plot)
        ax.loglog(ns, ys_plot, "o-", ms=3, label=f"{dist} {order} (slope {s:.2f})")
        md.append(f"| {dist} | {order} | {ns[0]}–{ns[-1]} | {ys[-1]:.3g} | {s:.2f} |")
    for exponent, label in ref:
        n = np.array([min(int(r["points"]) for r in rows), max(int(r["points"]) for r in rows)], float)
        base = np.median([num(r, key) / (int(r["points"]) if per_point else 1) for r in rows])
        ax.loglog(n, base * (n / n[0]) ** exponent, "k:", lw=1, label=label)
    ax.set(xlabel="n", ylabel=ylabel, title=title)
    ax.legend(fontsize=6)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, out, suite)
    md.append("")


def summarize_degenerate(inp, md):
    rows = read(os.path.join(inp, "degenerate.csv"))
    if rows is None:
        return
    md.append("## degenerate (regression)\n")
    md.append("| dist | n | runs | all valid | distinct hashes | tets | perturbations (min–max) | "
              "insphere exact-stage calls (max) |")
    md.append("|---|---|---|---|---|---|---|---|")
    stage_cols = [c for c in rows[0] if c.startswith("insphere_") and not c.endswith("filter")]
    for (dist, n), rs in sorted(group(rows, "dist", "n").items(), key=lambda kv: (kv[0][0], int(kv[0][1]))):
        hashes = {r["hash"] for r in rs}
        pert = [int(r["perturbations"]) for r in rs]
        exact = max(sum(int(r[c]) for c in stage_cols) for r in rs)
        md.append(f"| {dist} | {rs[0]['points']} | {len(rs)} | {all(r['valid'] == '1' for r in rs)} | "
                  f"{len(hashes)} | {rs[0]['tets']} | {min(pert)}–{max(pert)} | {exact} |")
    md.append(f"\n(insphere stages counted as exact: {', '.join(stage_cols)})\n")


# The goals for cavity's CPU time over CGAL's (order + triangulation against range
# insertion): half on uniform points, 0.8 on the grid and the sphere.
PEER_GOALS = {"cube": 0.5, "grid": 0.8, "sphere": 0.8}
PEER_COLORS = {"cube": "C0", "grid": "C1", "sphere": "C2", "cospherical": "C3"}


def plot_peers(inp, out, md):
    rows = read(os.path.join(inp, "peers.csv"))
    if rows is None:
        return
    peers = [p for p in ("cgal", "tetgen") if any(r[f"{p}_status"] == "ok" for r in rows)]
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5))
    md.append("## peers (cavity against CGAL and TetGen)\n")
    md.append("Ratios are cavity / peer, median over seeds (min–max in brackets); CPU seconds are "
              "process CPU time. TetGen's time is its whole process (reading .node, writing .ele); "
              "`tetgen Delaunay` is the ratio to TetGen's own Delaunay phase.\n")
    md.append("| dist | n | cavity s | CGAL s | time cavity/CGAL | goal | memory cavity/CGAL | "
              "TetGen s | time cavity/TetGen | time cavity/TetGen Delaunay | memory cavity/TetGen | "
              "tets cavity / CGAL / TetGen |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    def spread(values):
        if not values:
            return "—"
        return f"{np.median(values):.2f} [{min(values):.2f}–{max(values):.2f}]"

    for (dist,), rs in sorted(group(rows, "dist").items()):
        by_n = defaultdict(list)
        for r in rs:
            by_n[int(r["points"])].append(r)
        ns = sorted(by_n)
        for ax, peer, key in ((axes[0], "cgal", "time_ratio"), (axes[1], "tetgen", "time_ratio"),
                              (axes[2], "cgal", "memory_ratio")):
            if peer not in peers:
                continue
            xs, med, lo, hi = [], [], [], []
            for n in ns:
                v = [float(r[f"{peer}_{key}"]) for r in by_n[n] if r[f"{peer}_status"] == "ok"]
                if v:
                    xs.append(n)
                    med.append(float(np.median(v)))
                    lo.append(med[-1] - min(v))
                    hi.append(max(v) - med[-1])
            if xs:
                ax.errorbar(xs, med, yerr=[lo, hi], fmt="o-", ms=4, capsize=3, label=dist,
                            color=PEER_COLORS.get(dist))
        for n in ns:
            b = by_n[n]

            def vals(col, peer=None):
                return [float(r[col]) for r in b if peer is None or r[f"{peer}_status"] == "ok"]

            tg_delaunay = [float(r["cavity_s"]) / float(r["tetgen_delaunay_s"]) for r in b
                           if r["tetgen_status"] == "ok" and r["tetgen_delaunay_s"] not in ("-", "0")]
            tets = " / ".join(str(int(np.median(vals(f"{e}_tets", None if e == "cavity" else e))))
                              if vals(f"{e}_tets", None if e == "cavity" else e) else "—"
                              for e in ("cavity", "cgal", "tetgen"))
            md.append(f"| {dist} | {n} | {np.median(vals('cavity_s')):.3g} | "
                      f"{np.median(vals('cgal_s', 'cgal')) if vals('cgal_s', 'cgal') else float('nan'):.3g} | "
                      f"{spread(vals('cgal_time_ratio', 'cgal'))} | {PEER_GOALS.get(dist, '—')} | "
                      f"{spread(vals('cgal_memory_ratio', 'cgal'))} | "
                      f"{np.median(vals('tetgen_s', 'tetgen')) if vals('tetgen_s', 'tetgen') else float('nan'):.3g} | "
                      f"{spread(vals('tetgen_time_ratio', 'tetgen'))} | {spread(tg_delaunay)} | "
                      f"{spread(vals('tetgen_memory_ratio', 'tetgen'))} | {tets} |")
    for goal in sorted(set(PEER_GOALS.values())):
        named = ", ".join(d for d, g in PEER_GOALS.items() if g == goal)
        axes[0].axhline(goal, color="k", ls="--", lw=1, label=f"goal {named}: {goal}")
    axes[0].set(title="CPU time, cavity / CGAL")
    axes[1].set(title="CPU time, cavity / TetGen (whole process)")
    axes[2].set(title="peak memory, cavity / CGAL (each in its own process)")
    for ax in axes:
        ax.set_xscale("log")
        ax.axhline(1, color="gray", lw=0.8)
        ax.set(xlabel="n (points)", ylabel="ratio")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    for ax, peer in ((axes[0], "cgal"), (axes[1], "tetgen"), (axes[2], "cgal")):
        if peer not in peers:
            ax.text(0.5, 0.5, f"{peer} unavailable", transform=ax.transAxes, ha="center")
    save(fig, out, "peers")
    md.append("")


def main():
    inp, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    md = ["# Measured summary (generated by results/plot.py; do not edit)\n",
          f"Input tables: `{inp}`.\n"]
    plot_jtets(inp, out, md)
    plot_creation(inp, out, md)
    plot_scaling(inp, out, md)
    plot_loglog_suite(inp, out, md, "quadratic", "created", "quadratic families: tetrahedra created",
                      "tetrahedra created", False, [(2, "slope 2")])
    plot_loglog_suite(inp, out, md, "walk", "walk_steps", "walk steps per insertion", "walk steps / n",
                      True, [(1 / 3, "slope 1/3"), (0, "slope 0")])
    plot_loglog_suite(inp, out, md, "adversarial", "created", "grid: tetrahedra created per point",
                      "created / n", True, [(0, "slope 0 (linear total)"), (0.5, "slope 1/2 (n^1.5 total)")])
    summarize_degenerate(inp, md)
    plot_peers(inp, out, md)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(md) + "\n")


if __name__ == "__main__":
    main()
