"""Helpers every section uses: the chapter's constants, reading tables, formatting, fits and the
bootstrap over seeds.
"""
import csv
import math
import os
import random
from collections import defaultdict


CREATED_PER_POINT = 96 * math.pi**2 / 35       # 27.07, uniform order (backward analysis)
DELETED_PER_POINT = 72 * math.pi**2 / 35       # 20.30
TETS_PER_POINT = 24 * math.pi**2 / 35          # 6.768 (Miles)
CONFLICT_SLOPE = 3 * CREATED_PER_POINT         # 81.21 conflicts per point per unit of ln n
Z95 = 1.959964

F_CONST = 4 * math.pi**2 / 35                  # F_j/n -> F_CONST (j+1)(j+2)(j+3), Poisson

BOOTSTRAP_RESAMPLES = 2000


def read(path):
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def mean(values):
    return sum(values) / len(values)


def fmt(x, digits=1):
    return f"{x:,.{digits}f}".replace(",", " ")


def loglog_slope(xs, ys):
    """Least-squares slope of ln y against ln x."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-9)) for y in ys]
    mx, my = mean(lx), mean(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den > 0 else float("nan")


def group_rows(rows, *keys):
    groups = defaultdict(list)
    for r in rows:
        groups[tuple(r[k] for k in keys)].append(r)
    return groups


def median(values):
    v = sorted(values)
    return (v[(len(v) - 1) // 2] + v[len(v) // 2]) / 2


def spread(values, digits=2):
    return f"{median(values):.{digits}f} [{min(values):.{digits}f}–{max(values):.{digits}f}]"


def span(values, digits=2):
    lo, hi = min(values), max(values)
    return f"{lo:.{digits}f}" if f"{lo:.{digits}f}" == f"{hi:.{digits}f}" else f"{lo:.{digits}f}–{hi:.{digits}f}"


def interval(value, lo, hi, digits=1):
    return f"{fmt(value, digits)} [{fmt(lo, digits)}, {fmt(hi, digits)}]"


def seed_bootstrap(groups, statistic, resamples=BOOTSTRAP_RESAMPLES, seed=54):
    """Percentile 95 % interval of statistic(groups) when each group's runs (one per seed) are
    resampled with replacement: the seeds are the independent replicates. `groups` maps a key
    (a size) to its list of per-seed values; deterministic (fixed generator seed)."""
    rng = random.Random(seed)
    values = []
    for _ in range(resamples):
        sample = {k: [v[rng.randrange(len(v))] for _ in v] for k, v in groups.items()}
        values.append(statistic(sample))
    values.sort()
    lo = values[int(0.025 * (resamples - 1))]
    hi = values[int(math.ceil(0.975 * (resamples - 1)))]
    return statistic(groups), lo, hi


def least_squares(columns, ys):
    """Coefficients of ys ~ Σ_k c_k columns[k] (normal equations; a handful of rows)."""
    m = len(columns)
    a = [[sum(columns[i][r] * columns[j][r] for r in range(len(ys))) for j in range(m)]
         for i in range(m)]
    b = [sum(columns[i][r] * ys[r] for r in range(len(ys))) for i in range(m)]
    for i in range(m):  # Gaussian elimination with partial pivoting
        p = max(range(i, m), key=lambda r: abs(a[r][i]))
        a[i], a[p], b[i], b[p] = a[p], a[i], b[p], b[i]
        for r in range(i + 1, m):
            f = a[r][i] / a[i][i]
            a[r] = [x - f * y for x, y in zip(a[r], a[i])]
            b[r] -= f * b[i]
    x = [0.0] * m
    for i in reversed(range(m)):
        x[i] = (b[i] - sum(a[i][j] * x[j] for j in range(i + 1, m))) / a[i][i]
    return x


def chi2_sf(x, k):
    """P(χ²_k ≥ x): the regularized upper incomplete gamma Q(k/2, x/2), by its series below
    a + 1 and by Lentz's continued fraction above (Numerical Recipes §6.2)."""
    if x != x or k <= 0:
        return float("nan")
    if x == math.inf:
        return 0.0
    a, y = k / 2, x / 2
    if y <= 0:
        return 1.0
    log_front = a * math.log(y) - y - math.lgamma(a)
    if y < a + 1:
        term = total = 1 / a
        n = a
        while abs(term) > 1e-16 * abs(total):
            n += 1
            term *= y / n
            total += term
        return max(0.0, 1 - total * math.exp(log_front))
    tiny = 1e-300
    b = y + 1 - a
    c, d = 1 / tiny, 1 / b
    h = d
    i = 1
    while True:
        an = -i * (i - a)
        b += 2
        d = an * d + b
        d = tiny if abs(d) < tiny else d
        c = b + an / c
        c = tiny if abs(c) < tiny else c
        d = 1 / d
        delta = d * c
        h *= delta
        i += 1
        if abs(delta - 1) < 1e-16 or i > 10000:
            break
    return math.exp(log_front) * h
