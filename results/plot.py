#!/usr/bin/python3
"""Plots and summary tables from the experiment CSVs (cavity experiment ... --out IN_DIR).

Usage: /usr/bin/python3 results/plot.py IN_DIR OUT_DIR [PAPER_DIR]
Writes OUT_DIR/*.png and *.svg, and OUT_DIR/summary.md with every number the report quotes.
Suites whose CSV is missing are skipped. Run with Debian's python3-matplotlib.
"""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

# The estimators the report's text uses, so plots and text cannot disagree.
from reporting.common import Z95, seed_bootstrap
from reporting.exercises import extend_table
from reporting.propositions import brio_estimates, creation_dir
from reporting.theorem import fit_limit, fit_log, fit_sizes, timed_engine
from reporting.walking import walk_rounds

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Derived constants (docs experiments.md §1.3): Poisson–Delaunay in 3D.
TETS_PER_POINT = 24 * math.pi**2 / 35          # 6.768
CREATED_PER_POINT = 96 * math.pi**2 / 35       # 27.07
DELETED_PER_POINT = CREATED_PER_POINT - TETS_PER_POINT  # 20.30
F_CONST = 4 * math.pi**2 / 35                  # F_j/n -> F_CONST (j+1)(j+2)(j+3)
# Conflicts created (Σj) per point: Σ_j j E[h_j]/n = 81.21 per unit of ln n; the additive constant
# -2.26 holds for an unbounded Poisson process only (a bounded domain loses conflicts at its
# boundary), so it is drawn as a reference, not as the prediction for a cube.
CONFLICT_SLOPE = 3 * CREATED_PER_POINT         # 81.21
POISSON_CONFLICT_OFFSET = -2.256
LINE_STYLES = ["-", "--", "-.", ":"]
COLOURS = plt.get_cmap("tab20").colors


def read(path):
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(row, key):
    return float(row[key])


def save(fig, out, name):
    # No date and a fixed id salt: a figure drawn from the same tables is the same file, so the
    # history shows only plots whose data changed.
    matplotlib.rcParams["svg.hashsalt"] = "cavity"
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out, f"{name}.{ext}"), dpi=110, bbox_inches="tight",
                    metadata={"Date": None} if ext == "svg" else None)
    plt.close(fig)


def finish(fig, axes, out, name, md, legend_size=7):
    """Legends and grids on every panel, the figure saved, and the summary section closed."""
    for ax in axes:
        ax.legend(fontsize=legend_size)
        ax.grid(True, which="both", alpha=0.3)
    save(fig, out, name)
    md.append("")


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
    finish(fig, axes, out, "jtets", md, legend_size=7)
    meta = read(os.path.join(inp, "jtets.csv"))
    for r in meta:
        if r["closed_form_match"] != "-":
            md.append(f"- skew-lines n={r['n']}: pencil sweep equals the closed form: "
                      f"{'yes' if r['closed_form_match'] == '1' else 'NO'} ({r['time_s']} s)")
    md.append("")


def plot_creation(inp, out, md):
    rows = read(os.path.join(inp, "creation.j.csv"))
    runs = read(os.path.join(inp, "creation.csv"))
    if rows is None or runs is None or "created_sd" not in rows[0]:
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
        # The point sets pooled: q̂_j = Σ created / (R Σ f_j); each set's created count per order
        # has its own standard deviation over the orders (the orders are independent, the
        # tetrahedra of one order are not).
        pooled = defaultdict(lambda: [0.0, 0.0, 0.0, 0.0])
        for r in rs:
            acc = pooled[int(r["j"])]
            acc[0] += num(r, "f_j")
            acc[1] += num(r, "created")
            acc[2] += num(r, "created_sd") ** 2 / R
            acc[3] = num(r, "q_uniform")
        js, y, err = [], [], []
        for j, (f, c, variance, q0) in sorted(pooled.items()):
            if j == 0 or f * R * q0 < 100 or variance == 0:
                continue
            q = c / (R * f)
            se = math.sqrt(variance) / f
            js.append(j)
            y.append(q * j**4)
            err.append(Z95 * se * j**4)
            z = (q - q0) / se
            if j in (1, 2, 3, 4, 6, 8, 12, 16, 24, 32):
                md.append(f"| {order} | {j} | {int(f)} | {int(c)} | {q:.3e} | {q0:.3e} | {z:+.2f} | {q * j**4:.1f} |")
        style = "o" if order == "random" else "s"
        ax.errorbar(js, y, yerr=err, fmt=style, ms=3, capsize=2,
                    label=f"{order} order (measured, 95 % interval)")
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


def conflict_rows(rows):
    """Rows that counted conflicts (the column exists and holds a number)."""
    return [r for r in rows if r.get("conflicts", "-") not in ("-", "", None)]


def plot_conflicts(ax, rows, md):
    """Σj/n against n with the seeds' range, and Theorem 5.4's 81.2 per unit of ln n."""
    counted = conflict_rows(rows)
    if not counted:
        ax.set_visible(False)
        return
    md.append("")
    md.append("Conflicts created (Σj over created solid tetrahedra, counted exactly by the full "
              "conflict graph), per point; mean and range over seeds; slope per unit of ln n "
              "between consecutive sizes against the predicted 81.21:\n")
    md.append("| dist | order | n | seeds | Σj/n mean | min | max | ghost conflicts/n | live max/n | "
              "slope vs ln n |")
    md.append("|---|---|---|---|---|---|---|---|---|---|")
    for k, ((dist, order), rs) in enumerate(sorted(group(counted, "dist", "order").items())):
        by_n = defaultdict(list)
        for r in rs:
            by_n[int(r["points"])].append(r)
        ns = sorted(by_n)
        means, lows, highs = [], [], []
        for i, n in enumerate(ns):
            v = [num(r, "conflicts_per_point") for r in by_n[n]]
            ghost = np.mean([num(r, "ghost_conflicts") / n for r in by_n[n]])
            live = np.mean([num(r, "live_conflicts_max") / n for r in by_n[n]])
            means.append(float(np.mean(v)))
            lows.append(min(v))
            highs.append(max(v))
            per_ln = ((means[-1] - means[-2]) / math.log(n / ns[i - 1])) if i > 0 else float("nan")
            md.append(f"| {dist} | {order} | {n} | {len(v)} | {means[-1]:.1f} | {lows[-1]:.1f} | "
                      f"{highs[-1]:.1f} | {ghost:.2f} | {live:.2f} | "
                      f"{'-' if math.isnan(per_ln) else f'{per_ln:.1f}'} |")
        m = np.asarray(means)
        ax.errorbar(ns, means, yerr=[m - np.asarray(lows), np.asarray(highs) - m], capsize=2,
                    color=COLOURS[k % len(COLOURS)], ls=LINE_STYLES[k % len(LINE_STYLES)],
                    marker="os^v"[k % 4], ms=3, label=f"{dist}, {order} order")
    n = np.geomspace(min(int(r["points"]) for r in counted), max(int(r["points"]) for r in counted))
    ax.semilogx(n, CONFLICT_SLOPE * (np.log(n) + POISSON_CONFLICT_OFFSET), "k:", lw=1,
                label=r"unbounded Poisson: $81.2(\ln n - 2.26)$")
    ax.set(xlabel="n", ylabel=r"$\Sigma j / n$",
           title="Theorem 5.4: conflicts created per point\n(slope 81.2 per unit of ln n predicted)")


def plot_scaling(inp, out, md):
    rows = read(os.path.join(inp, "scaling.csv"))
    if rows is None:
        return
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
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
        k = len(axes[1].get_lines())
        axes[1].loglog(ns, t, color=COLOURS[k % len(COLOURS)], ls=LINE_STYLES[k % len(LINE_STYLES)],
                       marker="o", ms=3, label=f"{label} (slope {slope(ns, t):.2f})")
        tot_created = [c * n for c, n in zip(created, ns)]
        md.append(f"| {dist} | {order} | {locate} | {ns[-1]} | {created[-1]:.2f} | {deleted[-1]:.2f} | "
                  f"{tets[-1] / ns[-1]:.3f} | {walk[-1]:.2f} | {us[-1]:.2f} | {slope(ns, t):.2f} | "
                  f"{slope(ns, tot_created):.3f} |")
    axes[0].axhline(CREATED_PER_POINT, color="k", ls=":", label="27.07 (limit, uniform order)")
    axes[0].axhline(DELETED_PER_POINT, color="gray", ls=":", label="20.30")
    axes[0].set(xlabel="n", ylabel="per point", title="cube: tetrahedra created / deleted per point")
    n = np.array([1e3, 1e5])
    axes[1].loglog(n, 1e-6 * n * np.log(n) / np.log(1e3), "k:", label=r"$\propto n \log n$")
    axes[1].set(xlabel="n", ylabel="seconds",
                title=f"time of the {timed_engine(inp, 'scaling')} engine (log–log, fitted slopes;\n"
                      "noisy under load)")
    plot_conflicts(axes[2], rows, md)
    finish(fig, axes, out, "scaling", md, legend_size=6)


def plot_loglog_suite(inp, out, md, suite, key, title, ylabel, per_point, ref):
    rows = read(os.path.join(inp, f"{suite}.csv"))
    if rows is None:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    md.append(f"## {suite}: {title}\n")
    md.append(f"| dist | order | n range | {key}{'/n' if per_point else ''} at largest n | fitted slope |")
    md.append("|---|---|---|---|---|")
    several = len({r.get("locate", "-") for r in rows}) > 1
    for k, ((dist, order, locate), rs) in enumerate(
            sorted(group(rows, "dist", "order", "locate").items())):
        ns, ys = mean_by_n(rs, key)
        if per_point:
            ys = [y / n for y, n in zip(ys, ns)]
        ys_plot = [max(y, 1e-3) for y in ys]
        s = slope(ns, ys_plot)
        name = f"{dist} {order}" + (f" {locate}" if several else "")
        ax.loglog(ns, ys_plot, color=COLOURS[k % len(COLOURS)], ls=LINE_STYLES[k % len(LINE_STYLES)],
                  marker="o", ms=3, label=f"{name} (slope {s:.2f})")
        md.append(f"| {dist} | {order}{' ' + locate if several else ''} | {ns[0]}–{ns[-1]} | "
                  f"{ys[-1]:.3g} | {s:.2f} |")
    for exponent, label in ref:
        n = np.array([min(int(r["points"]) for r in rows), max(int(r["points"]) for r in rows)], float)
        base = np.median([num(r, key) / (int(r["points"]) if per_point else 1) for r in rows])
        ax.loglog(n, base * (n / n[0]) ** exponent, "k:", lw=1, label=label)
    ax.set(xlabel="n", ylabel=ylabel, title=title)
    ax.legend(fontsize=6)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, out, suite)
    md.append("")


def plot_walk_rounds(inp, out, md):
    rows = read(os.path.join(inp, "walk.csv"))
    if rows is None:
        return
    rounds = walk_rounds(rows)
    if not rounds:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    md.append("## walk: the first walk of each BRIO round\n")
    md.append("| order | n | first walk mean | first walk max | other insertions |")
    md.append("|---|---|---|---|---|")
    for k, (order, by_n) in enumerate(sorted(rounds.items())):
        ns = sorted(by_n)
        ax.loglog(ns, [by_n[n][0] for n in ns], color=COLOURS[2 * k], ls=LINE_STYLES[k], marker="o",
                  ms=3, label=f"{order}: first walk of a round (mean)")
        ax.loglog(ns, [by_n[n][1] for n in ns], color=COLOURS[2 * k + 1], ls=LINE_STYLES[k],
                  marker="^", ms=3, label=f"{order}: first walk of a round (largest)")
        for n in ns:
            md.append(f"| {order} | {n} | {by_n[n][0]:.2f} | {by_n[n][1]:.0f} | {by_n[n][2]:.2f} |")
    n = np.array([min(min(v) for v in rounds.values()), max(max(v) for v in rounds.values())], float)
    ax.loglog(n, 10 * (n / n[0]) ** (1 / 3), "k:", lw=1, label="slope 1/3 (a walk across the domain)")
    ax.set(xlabel="n", ylabel="walk steps", title="§5.5: the walk that starts each BRIO round")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, out, "walk_rounds")
    md.append("")


def summarize_degenerate(inp, md):
    rows = read(os.path.join(inp, "degenerate.csv"))
    if rows is None:
        return
    md.append("## degenerate (regression)\n")
    md.append("| dist | n | runs | all valid | distinct hashes | tets | perturbations (min–max) | "
              "insphere exact-stage calls (max) |")
    md.append("|---|---|---|---|---|---|---|---|")
    # Beyond the floating-point filters (static, from files that count it, and semi-static).
    stage_cols = [c for c in rows[0]
                  if c.startswith("insphere_") and not c.endswith(("static", "filter"))]
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


FAMILY_COLORS = {"hull-faces": "C0", "nested-boxes": "C1", "terrain": "C2", "voxel-grid": "C3"}


def plot_giftwrap(inp, out, md):
    rows = read(os.path.join(inp, "giftwrap.csv"))
    if rows is None:
        return
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5))
    md.append("## giftwrap (§5.6: gift-wrapping O(nh) against Bowyer–Watson)\n")
    md.append("| dist | n | h | h/n | apex tests/(n h) | insphere/(n h) | gift-wrap s | Bowyer–Watson s | "
              "time ratio | BW predicates/n | predicate ratio GW/BW | same_tets |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for k, ((dist,), rs) in enumerate(sorted(group(rows, "dist").items())):
        c = f"C{k}"
        rs = sorted(rs, key=lambda r: int(r["points"]))
        ns = [int(r["points"]) for r in rs]
        nh = [n * num(r, "tets") for n, r in zip(ns, rs)]
        apex = [num(r, "apex_orient_tests") for r in rs]
        gw = [num(r, "gw_s") for r in rs]
        bw = [num(r, "bw_s") for r in rs]
        axes[0].loglog(nh, apex, "o-", ms=3, color=c,
                       label=f"{dist} apex orient3d (slope {slope(nh, apex):.3f})")
        axes[0].loglog(nh, [num(r, "gw_insphere_calls") for r in rs], "s--", ms=3, color=c,
                       label=f"{dist} insphere")
        axes[1].loglog(ns, gw, "o-", ms=3, color=c, label=f"{dist} gift-wrap (slope {slope(ns, gw):.2f})")
        axes[1].loglog(ns, bw, "s--", ms=3, color=c,
                       label=f"{dist} Bowyer–Watson (slope {slope(ns, bw):.2f})")
        axes[2].semilogx(ns, [num(r, "gw_over_bw_predicates") for r in rs], "o-", ms=3, color=c,
                         label=dist)
        for r in rs:
            md.append(f"| {dist} | {r['points']} | {r['tets']} | {num(r, 'tets') / num(r, 'points'):.2f} | "
                      f"{num(r, 'apex_per_nh'):.3f} | {num(r, 'insphere_per_nh'):.3f} | {num(r, 'gw_s'):.3g} | "
                      f"{num(r, 'bw_s'):.3g} | {num(r, 'gw_over_bw_time'):.0f} | "
                      f"{num(r, 'bw_predicates_per_point'):.1f} | {num(r, 'gw_over_bw_predicates'):.0f} | "
                      f"{r['same_tets']} |")
        md.append(f"| {dist} | fitted slopes vs n: gift-wrap time {slope(ns, gw):.2f}, Bowyer–Watson time "
                  f"{slope(ns, bw):.2f}, apex tests {slope(ns, apex):.2f} | | | | | | | | | | |")
    lo = min(int(r["points"]) * num(r, "tets") for r in rows)
    hi = max(int(r["points"]) * num(r, "tets") for r in rows)
    axes[0].loglog([lo, hi], [lo, hi], "k:", lw=1, label="= n h")
    axes[0].set(xlabel="n h", ylabel="calls", title="gift-wrapping: predicate calls against n h")
    axes[1].set(xlabel="n", ylabel="seconds", title="time, same points")
    axes[2].set(xlabel="n", ylabel="ratio", title="predicate calls, gift-wrap / Bowyer–Watson")
    for ax in axes:
        ax.legend(fontsize=6)
        ax.grid(True, which="both", alpha=0.3)
    save(fig, out, "giftwrap")
    same = sum(r["same_tets"] == "1" for r in rows)
    md.append(f"\n- same tetrahedra as Bowyer–Watson in {same} of {len(rows)} runs\n")


def plot_deletion(inp, out, md):
    rows = read(os.path.join(inp, "deletion.csv"))
    per = read(os.path.join(inp, "deletion.j.csv"))
    if rows is None or per is None:
        return
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5))
    md.append("## deletion (§5.6: vertex deletion by gift-wrapping the star)\n")
    md.append("| dist | n | deletions (hull) | mean degree | apex tests/deletion | insphere/deletion | "
              "apex/Σd² | created/deletion | µs/deletion | rebuild s | equal_rebuild |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for (dist,), rs in sorted(group(rows, "dist").items()):
        by_n = group(rs, "n")
        ns = sorted(int(n) for (n,) in by_n)
        for n in ns:
            b = by_n[(str(n),)]

            def mean(col):
                return float(np.mean([num(r, col) for r in b]))
            md.append(f"| {dist} | {b[0]['points']} | {int(sum(num(r, 'deletions') for r in b))} "
                      f"({int(sum(num(r, 'hull_deletions') for r in b))}) | {mean('mean_degree'):.2f} | "
                      f"{mean('apex_per_deletion'):.0f} | {mean('insphere_per_deletion'):.0f} | "
                      f"{mean('apex_per_degree_sq'):.3f} | {mean('created_per_deletion'):.1f} | "
                      f"{mean('us_per_deletion'):.0f} | {mean('rebuild_s'):.3g} | "
                      f"{all(r['equal_rebuild'] == '1' for r in b)} |")
        apex_n = [float(np.mean([num(r, "apex_per_deletion") for r in by_n[(str(n),)]])) for n in ns]
        axes[2].semilogx(ns, apex_n, "o-", ms=3, label=f"{dist} (slope {slope(ns, apex_n):.2f})")
    md.append("")
    md.append("| dist | deletions | degree range | fitted slope of apex tests vs degree | "
              "apex tests / ((d − 3) · facets wrapped) | facets wrapped / d (d ≤ 10, d ≥ 18) |")
    md.append("|---|---|---|---|---|---|")
    for (dist,), rs in sorted(group(per, "dist").items()):
        rs = [r for r in rs if num(r, "apex_orient_tests") > 0]
        d = np.array([num(r, "degree") for r in rs])
        a = np.array([num(r, "apex_orient_tests") for r in rs])
        f = np.array([num(r, "facets_wrapped") for r in rs])
        axes[0].loglog(d, a, ".", ms=2, alpha=0.4, label=f"{dist} (slope {slope(d, a):.2f})")
        axes[1].loglog(d * f, a, ".", ms=2, alpha=0.4, label=dist)
        identity = a / ((d - 3) * f)
        small, large = f[d <= 10] / d[d <= 10], f[d >= 18] / d[d >= 18]
        md.append(f"| {dist} | {len(rs)} | {int(min(d))}–{int(max(d))} | {slope(d, a):.2f} | "
                  f"{identity.min():.3f}–{identity.max():.3f} | "
                  f"{small.mean() if len(small) else float('nan'):.2f}, "
                  f"{large.mean() if len(large) else float('nan'):.2f} |")
    d = np.array([4, max(num(r, "degree") for r in per)])
    axes[0].loglog(d, d**2, "k:", lw=1, label="d²")
    hi = max(num(r, "degree") * num(r, "facets_wrapped") for r in per)
    axes[1].loglog([4, hi], [4, hi], "k:", lw=1, label="= d · facets")
    axes[0].set(xlabel="degree d of the deleted vertex", ylabel="apex orient3d tests",
                title="work per deletion against the degree")
    axes[1].set(xlabel="d · facets wrapped", ylabel="apex orient3d tests",
                title="O(n h) inside the cavity: n = d, h ≈ facets")
    axes[2].set(xlabel="n", ylabel="apex tests per deletion", title="work per deletion against n")
    for ax in axes:
        ax.legend(fontsize=6)
        ax.grid(True, which="both", alpha=0.3)
    save(fig, out, "deletion")
    equal = sum(r["equal_rebuild"] == "1" for r in rows)
    md.append(f"\n- equal to the rebuilt triangulation in {equal} of {len(rows)} runs "
              f"({int(sum(num(r, 'deletions') for r in rows))} deletions)\n")


def summarize_cdt_validity(inp, md):
    """Every CDT the validator checked, from the cdt and cdtvalid suites."""
    checked = []
    for suite in ("cdt", "cdtvalid"):
        rows = read(os.path.join(inp, f"{suite}.csv")) or []
        checked += [(suite, r) for r in rows if r["valid"] != "-"]
    if not checked:
        return
    md.append("## cdt validity (independent validator, suites cdt and cdtvalid)\n")
    md.append("| suite | family | n (input) | seed | vertices | polygons | flips | validate s | valid | problems |")
    md.append("|---|---|---|---|---|---|---|---|---|---|")
    for suite, r in checked:
        md.append(f"| {suite} | {r['dist']} | {r['points']} | {r['seed']} | {r['vertices']} | "
                  f"{r['polygons']} | {r['flips']} | {num(r, 'validate_s'):.3g} | {r['valid']} | "
                  f"{r['cdt_problems']} |")
    bad = [r for _, r in checked if r["valid"] != "1"]
    md.append(f"\n- validated {len(checked)} CDTs: {len(checked) - len(bad)} valid, {len(bad)} invalid"
              + "".join(f"; invalid: {r['dist']} n={r['n']} seed={r['seed']} ({r['cdt_problems']} problems)"
                        for r in bad) + "\n")


def plot_cdt(inp, out, md):
    rows = read(os.path.join(inp, "cdt.csv"))
    per = read(os.path.join(inp, "cdt.j.csv")) or []
    if rows is None:
        return
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.5))
    md.append("## cdt (§5.8: polygon insertion by flips, Propositions 5.5–5.6)\n")
    md.append("| family | n (input) | vertices n | polygons | protection points | flips | flips/n² | "
              "max flips/m² | polygons with flips ≥ m² | max m | max events/(m² ln m) | events/(n² ln n) | "
              "DFS visits/|R| | insert s | valid |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    slopes = []
    for (family,), rs in sorted(group(rows, "dist").items()):
        color = FAMILY_COLORS.get(family)
        rs = sorted(rs, key=lambda r: (int(r["n"]), int(r["seed"])))
        n = [num(r, "vertices") for r in rs]
        flips = [max(num(r, "flips"), 0.5) for r in rs]
        # Slopes from 250 input points up: the smallest PLCs (the validated ones) can need no flip.
        fit = [r for r in rs if int(r["n"]) >= 250 and num(r, "flips") > 0]
        fn = [num(r, "vertices") for r in fit]
        fs = slope(fn, [num(r, "flips") for r in fit])
        axes[2].loglog(n, flips, "o", ms=4, color=color, label=f"{family} (slope {fs:.2f})")
        slopes.append(f"- {family}: fitted slope of all flips vs n {fs:.2f}, of events "
                      f"{slope(fn, [num(r, 'events_queued') for r in fit]):.2f}, of insertion time "
                      f"{slope(fn, [num(r, 'insert_s') for r in fit]):.2f} "
                      f"(n = {int(min(fn))}–{int(max(fn))} vertices)")
        for r in rs:
            md.append(f"| {family} | {r['points']} | {r['vertices']} | {r['polygons']} | "
                      f"{r['protection_points']} | {r['flips']} | {num(r, 'flips_per_n2'):.2e} | "
                      f"{r['max_flips_per_m2']} | {r['polygons_at_or_over_m2']} | {r['max_m']} | "
                      f"{r['max_events_per_m2_log_m']} | {num(r, 'events_per_n2_log_n'):.2e} | "
                      f"{num(r, 'search_per_region_tet'):.2f} | {num(r, 'insert_s'):.3g} | {r['valid']} |")
    md.append("")
    md += slopes
    lo = min(num(r, "vertices") for r in rows)
    hi = max(num(r, "vertices") for r in rows)
    axes[2].loglog([lo, hi], [lo**2, hi**2], "k:", lw=1, label="n² (Prop. 5.6 bound)")
    for (family,), ps in sorted(group(per, "dist").items()):
        ps = [p for p in ps if num(p, "m") > 0]
        if not ps:
            continue
        color = FAMILY_COLORS.get(family)
        m = np.array([num(p, "m") for p in ps])
        f = np.array([num(p, "flips") for p in ps])
        e = np.array([num(p, "events_queued") for p in ps])
        axes[0].loglog(m, np.maximum(f, 0.5), ".", ms=3, alpha=0.5, color=color, label=family)
        axes[1].loglog(m * m * np.log(np.maximum(m, 2)), np.maximum(e, 0.5), ".", ms=3, alpha=0.5,
                       color=color, label=family)
        axes[3].loglog([max(num(p, "region_tets"), 0.5) for p in ps],
                       [max(num(p, "search_visited"), 0.5) for p in ps], ".", ms=3, alpha=0.5,
                       color=color, label=family)
    if per:
        m = np.array([2, max(num(p, "m") for p in per)])
        axes[0].loglog(m, m * m, "k:", lw=1, label="m² (Prop. 5.5 bound)")
        axes[1].loglog(m * m * np.log(m), m * m * np.log(m), "k:", lw=1, label="= m² ln m")
        md.append("")
        nonempty = [p for p in per if num(p, "m") > 0]
        ratio = [num(p, "flips") / num(p, "m") ** 2 for p in nonempty]
        ev = [num(p, "events_queued") / (num(p, "m") ** 2 * math.log(num(p, "m"))) for p in nonempty
              if num(p, "m") >= 2]
        below = sum(p["flips_below_m2"] == "1" for p in per)
        md.append(f"- polygons inserted: {len(per)}; with a nonempty region R: {len(nonempty)}; "
                  f"flips < m² on {below} of {len(per)}")
        if ratio:
            md.append(f"- flips/m² over polygons with R nonempty: median {np.median(ratio):.3f}, "
                      f"max {max(ratio):.3f}; events/(m² ln m): median {np.median(ev):.3f}, max {max(ev):.3f}")
        for (family,), ps in sorted(group(nonempty, "dist").items()):
            m = [num(p, "m") for p in ps]
            f = [max(num(p, "flips"), 0.5) for p in ps]
            md.append(f"- {family}: m up to {int(max(m))}, fitted slope of flips vs m "
                      f"{slope(m, f):.2f} (flips ≥ 1 only: "
                      f"{slope([a for a, b in zip(m, f) if b >= 1], [b for b in f if b >= 1]):.2f})")
    else:
        md.append("\n- no per-polygon records in cdt.j.csv\n")
    axes[0].set(xlabel="m (vertices of the region R)", ylabel="flips", title="per polygon: flips against m")
    axes[1].set(xlabel="m² ln m", ylabel="events queued", title="per polygon: events against m² ln m")
    axes[2].set(xlabel="n (vertices, after protection)", ylabel="flips, all polygons",
                title="per PLC: flips against n")
    axes[3].set(xlabel="|R| (tetrahedra crossing the polygon)", ylabel="tetrahedra visited",
                title="per polygon: depth-first search against |R|")
    finish(fig, axes, out, "cdt", md, legend_size=6)


def plot_brio(inp, out, md):
    est = brio_estimates(inp)
    if not est:
        return
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.4))
    md.append("## brio (Proposition 5.3 at large n)\n")
    md.append("| ratio | j | q̂_j | 95 % half-width | 1/C(j+4,4) | j^4 q̂_j |")
    md.append("|---|---|---|---|---|---|")
    for k, (key, e) in enumerate(sorted(est.items(), key=lambda kv: -kv[1]["ratio"])):
        rows = [r for r in e["rows"] if r[0] <= 64]
        j = np.array([r[0] for r in rows], float)
        q = np.array([r[1] for r in rows])
        se = np.array([r[2] for r in rows])
        q0 = np.array([r[3] for r in rows])
        style = dict(color=COLOURS[2 * k % len(COLOURS)], ls=LINE_STYLES[k % len(LINE_STYLES)],
                     marker="os^v"[k % 4], ms=3, capsize=2)
        label = f"BRIO ratio {e['ratio']:g}"
        axes[0].errorbar(j, j**4 * q, yerr=Z95 * j**4 * se, label=label, **style)
        axes[1].errorbar(j, q / q0 - 1, yerr=Z95 * se / q0, label=label, **style)
        for jj, qq, ss, qu in rows:
            if jj in (1, 2, 4, 8, 16, 32, 64):
                md.append(f"| {e['ratio']:g} | {jj} | {qq:.4e} | {Z95 * ss:.1e} | {qu:.4e} | "
                          f"{jj**4 * qq:.2f} |")
    jj = np.arange(1, 65)
    axes[0].plot(jj, 24 * jj**4 / ((jj + 1) * (jj + 2) * (jj + 3) * (jj + 4)), "k-", lw=1,
                 label=r"uniform: $j^4/\binom{j+4}{4}$")
    axes[0].axhline(24, color="g", ls="--", lw=1, label="Prop. 5.2 bound 4! = 24")
    axes[0].axhline(385, color="r", ls="--", lw=1, label="Prop. 5.3 bound 385")
    axes[0].set(xscale="log", yscale="log", xlabel="j", ylabel=r"$j^4 \hat q_j$",
                title="BRIO: creation probability of a j-tetrahedron (95 % intervals)")
    axes[1].axhline(0, color="k", lw=1)
    axes[1].set(xscale="log", xlabel="j", ylabel=r"$\hat q_j / q_j^{\rm uniform} - 1$",
                title="BRIO's departure from the uniform order")
    finish(fig, axes, out, "brio", md, legend_size=7)


def plot_theorem(inp, out, md, paper=None):
    """Theorem 5.4 from counters: Σj/n with its fit, created and deleted per point against their
    limits, walk steps; 95 % bootstrap bands over seeds. The paper tier's table when present."""
    source = paper if paper and read(os.path.join(paper, "theorem.csv")) else inp
    rows = read(os.path.join(source, "theorem.csv"))
    if rows is None:
        return
    md.append(f"## theorem (Theorem 5.4 at scale; tables from `{source}`)\n")
    md.append("| dist | n | seeds | quantity | mean | 95 % low | 95 % high |")
    md.append("|---|---|---|---|---|---|---|")
    fig, axes = plt.subplots(1, 3, figsize=(17, 5))
    keys = [("conflicts_per_point", r"$\Sigma j / n$"), ("created_per_point", "created / n"),
            ("deleted_per_point", "deleted / n"), ("location_per_point", "location steps / n")]
    for r in rows:  # point location's work: walk steps, or the conflict graph's moves
        r["location_per_point"] = str((num(r, "walk_steps") + num(r, "redistribution_steps")) /
                                      num(r, "points"))
    for k, ((dist,), rs) in enumerate(sorted(group(rows, "dist").items())):
        colour = COLOURS[(2 * k) % len(COLOURS)]
        by = {key: defaultdict(list) for key, _ in keys}
        for r in rs:
            for key, _ in keys:
                by[key][int(r["points"])].append(num(r, key))
        bands = {}
        for key, label in keys:
            ns = sorted(by[key])
            stats = [seed_bootstrap({n: by[key][n]}, lambda g, n=n: float(np.mean(g[n]))) for n in ns]
            bands[key] = (ns, stats)
            for n, (m, lo, hi) in zip(ns, stats):
                md.append(f"| {dist} | {n} | {len(by[key][n])} | {key} | {m:.4g} | {lo:.4g} | {hi:.4g} |")
        style = dict(color=colour, ls=LINE_STYLES[k % len(LINE_STYLES)], marker="os^v"[k % 4], ms=3)
        for ax, key in ((axes[0], "conflicts_per_point"), (axes[2], "location_per_point")):
            ns, stats = bands[key]
            ax.plot(ns, [m for m, _, _ in stats], label=dist, **style)
            ax.fill_between(ns, [lo for _, lo, _ in stats], [hi for _, _, hi in stats], color=colour,
                            alpha=0.25)
        for key, ls in (("created_per_point", "-"), ("deleted_per_point", "--")):
            ns, stats = bands[key]
            axes[1].errorbar(ns, [m for m, _, _ in stats],
                             yerr=[[m - lo for m, lo, _ in stats], [hi - m for m, _, hi in stats]],
                             color=colour, ls=ls, marker="os^v"[k % 4], ms=3, capsize=2,
                             label=f"{dist}, {'created' if key.startswith('created') else 'deleted'}")
        conflicts = by["conflicts_per_point"]
        fitted = fit_sizes(conflicts)
        if fitted:
            a, b, c = fit_log({n: conflicts[n] for n in fitted})
            n = np.geomspace(min(conflicts), max(conflicts))
            axes[0].plot(n, a * np.log(n) + b + c * n ** (-1 / 3), color=colour, lw=0.8, ls=":",
                         label=f"{dist} fit: {a:.1f} ln n {b:+.0f} {c:+.0f} n^(-1/3)")
            for key in ("created_per_point", "deleted_per_point"):
                A, B, C = fit_limit({m: by[key][m] for m in fitted})
                axes[1].plot(n, A + B * n ** (-1 / 3) + C * n ** (-2 / 3), color=colour, lw=0.6, ls=":")
    ns_all = sorted({int(r["points"]) for r in rows})
    n = np.geomspace(ns_all[0], ns_all[-1])
    axes[0].plot(n, CONFLICT_SLOPE * (np.log(n) + POISSON_CONFLICT_OFFSET), "k--", lw=1,
                 label=r"unbounded Poisson: $81.2(\ln n - 2.26)$")
    axes[0].set(xscale="log", xlabel="n", ylabel=r"$\Sigma j / n$",
                title="Theorem 5.4: conflicts created per point\n(95 % bootstrap bands over seeds)")
    axes[1].axhline(CREATED_PER_POINT, color="k", lw=1, label=f"created limit {CREATED_PER_POINT:.2f}")
    axes[1].axhline(DELETED_PER_POINT, color="k", lw=1, ls="--", label=f"deleted limit {DELETED_PER_POINT:.2f}")
    axes[1].set(xscale="log", xlabel="n", ylabel="tetrahedra per point",
                title="tetrahedra created and deleted per point\n(dotted: fits A + B n^(-1/3) + C n^(-2/3))")
    locate = ", ".join(sorted({r["locate"] for r in rows}))
    axes[2].set(xscale="log", xlabel="n", ylabel="location steps per point",
                title=f"point location's work per point ({locate})\nwalk steps or points moved between cells")
    finish(fig, axes, out, "theorem", md, legend_size=7)


def plot_locality(inp, out, md):
    rows = read(os.path.join(inp, "locality.csv"))
    if rows is None:
        return
    md.append("## locality (§5.3, simulated LRU caches)\n")
    line_cols = [k for k in rows[0] if k.startswith("line_misses_")]
    page_cols = [k for k in rows[0] if k.startswith("page_misses_")]
    ns = sorted({int(r["points"]) for r in rows})
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    md.append("| n | order | seeds | pages / insertion | " + " | ".join(line_cols + page_cols) + " |")
    md.append("|---|---|---|---|" + "---|" * len(line_cols + page_cols))
    for k, ((order,), rs) in enumerate(sorted(group(rows, "order").items())):
        colour = COLOURS[(2 * k) % len(COLOURS)]
        for n in ns:
            at = [r for r in rs if int(r["points"]) == n]
            if at:
                md.append(f"| {n} | {order} | {len(at)} | "
                          f"{np.mean([num(r, 'pages_per_insertion') for r in at]):.2f} | " +
                          " | ".join(f"{np.mean([num(r, c) for r in at]):.4g}" for c in line_cols + page_cols) + " |")
        big = [r for r in rs if int(r["points"]) == ns[-1]]
        for cols, block, ls, what in ((line_cols, 64, "--", "lines"), (page_cols, 4096, "-", "pages")):
            sizes = [int(c.split("_")[-1]) * block for c in cols]
            misses = [float(np.mean([num(r, c) for r in big])) for c in cols]
            axes[0].plot(sizes, misses, color=colour, ls=ls, marker="os^v"[k % 4], ms=4,
                         label=f"{order}: {what} missed")
        n_of, pages = mean_by_n(rs, "pages_per_insertion")
        axes[1].plot(n_of, pages, color=colour, ls=LINE_STYLES[k % len(LINE_STYLES)],
                     marker="os^v"[k % 4], ms=4, label=f"{order}")
    # First accesses miss in every cache, so every value is positive.
    axes[0].set(xscale="log", yscale="log", xlabel="LRU cache size (bytes)",
                ylabel="misses per insertion", title=f"§5.3: misses per insertion at n = {ns[-1]}")
    axes[1].set(xscale="log", yscale="log", xlabel="n", ylabel="distinct 4 KiB pages per insertion",
                title="working set of one insertion")
    finish(fig, axes, out, "locality", md, legend_size=7)


def plot_extend(inp, out, md):
    """Exercise 2: the work of inserting T into Del S against the bound t² + t s², and against
    building S ∪ T from scratch."""
    table = extend_table(inp)
    if table is None:
        return
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.5))
    md.append("## extend (Exercise 2: T inserted into a given Del S)\n")
    md.append("| S | s | t | created | conflicts | ± 95 % | work/(t²+ts²) | after S / scratch |")
    md.append("|---|---|---|---|---|---|---|---|")
    k = 0
    for dist in sorted(table):
        cells = table[dist]
        ss = sorted({s for s, _ in cells})
        ts = sorted({t for _, t in cells})
        for i, t in enumerate(ts):
            ratio = [cells[(s, t)]["work"] / cells[(s, t)]["bound"] for s in ss]
            axes[0].loglog(ss, ratio, marker="o", ms=3, color=COLOURS[k % len(COLOURS)],
                           ls=LINE_STYLES[i % len(LINE_STYLES)], label=f"{dist}, t = {t}")
            k += 1
        t = ts[-1]
        work = np.array([cells[(s, t)]["work"] for s in ss])
        ci = np.array([cells[(s, t)]["ci"] for s in ss])
        scratch = np.array([cells[(s, t)]["scratch"] for s in ss])
        axes[1].errorbar(ss, work / scratch, yerr=ci / scratch, marker="o", ms=3, capsize=2,
                         label=f"{dist}, t = {t}")
        for (s, t), c in sorted(cells.items()):
            md.append(f"| {dist} | {s} | {t} | {c['created']:.0f} | {c['conflicts']:.0f} | "
                      f"{c['ci']:.0f} | {c['work'] / c['bound']:.3g} | "
                      f"{c['work'] / c['scratch']:.2f} |")
    axes[1].axhline(1, color="k", ls=":", lw=1, label="= the whole construction from scratch")
    axes[1].set_xscale("log")
    sizes = sorted({s for cells in table.values() for s, _ in cells})
    for ax in axes:
        ax.set_xticks(sizes, [str(s) for s in sizes])
        ax.minorticks_off()
    axes[0].set(xlabel="s (points of S)", ylabel="work / (t² + t s²)",
                title="inserting T into Del S, against the bound (work: created + conflicts)")
    axes[1].set(xlabel="s (points of S)", ylabel="work after S / work from scratch",
                title="an adversary's S against a uniform order of S ∪ T")
    finish(fig, axes, out, "extend", md, legend_size=6)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    inp, out = sys.argv[1], sys.argv[2]
    paper = sys.argv[3] if len(sys.argv) == 4 else None
    os.makedirs(out, exist_ok=True)
    md = ["# Measured summary (generated by results/plot.py; do not edit)\n",
          f"Input tables: `{inp}`.\n"]
    plot_jtets(inp, out, md)
    plot_creation(creation_dir(inp, paper), out, md)
    plot_brio(inp, out, md)
    plot_scaling(inp, out, md)
    plot_theorem(inp, out, md, paper)
    plot_locality(inp, out, md)
    plot_loglog_suite(inp, out, md, "quadratic", "created", "quadratic families: tetrahedra created",
                      "tetrahedra created", False, [(2, "slope 2")])
    plot_loglog_suite(inp, out, md, "walk", "walk_steps", "walk steps per insertion", "walk steps / n",
                      True, [(1 / 3, "slope 1/3"), (0, "slope 0")])
    plot_walk_rounds(inp, out, md)
    plot_loglog_suite(inp, out, md, "adversarial", "created", "grid: tetrahedra created per point",
                      "created / n", True, [(0, "slope 0 (linear total)"), (0.5, "slope 1/2 (n^1.5 total)")])
    plot_extend(inp, out, md)
    summarize_degenerate(inp, md)
    plot_peers(inp, out, md)
    plot_giftwrap(inp, out, md)
    plot_deletion(inp, out, md)
    plot_cdt(inp, out, md)
    summarize_cdt_validity(inp, md)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(md) + "\n")


if __name__ == "__main__":
    main()
