"""The engine against degenerate input and its peers, and what the quick tier cost."""
import os
import re

from .common import fmt, group_rows, median, read, spread


PEER_GOALS = {"cube": 0.5, "grid": 0.8, "sphere": 0.8}  # cavity/CGAL CPU time, issue 4


def cost_section(inp):
    rows = read(os.path.join(inp, "cost.csv"))
    if rows is None:
        return None
    total = sum(int(r["wall_s"]) for r in rows)
    loads = [float(r["load_average"]) for r in rows]
    cpu = ""
    meta = os.path.join(inp, "scaling.meta.json")
    if os.path.exists(meta):
        found = re.search(r'"cpu":\s*"([^"]*)"', open(meta).read())
        cpu = f" ({found.group(1)})" if found else ""
    parts = ", ".join(f"{r['suite']} {r['wall_s']} s" for r in rows)
    # Tables measured apart from that run (a suite added or rerun alone) have no wall time here.
    timed = {r["suite"] for r in rows}
    apart = sorted(name[:-len(".meta.json")] for name in os.listdir(inp)
                   if name.endswith(".meta.json") and name[:-len(".meta.json")] not in timed)
    return (f"**Cost (generated).** The last run of `scripts/experiments-quick.sh` took "
            f"{total // 60} min {total % 60} s wall on this machine{cpu}, with a load average of "
            f"{min(loads):.1f}–{max(loads):.1f} at the ends of its suites (other jobs share the "
            f"machine, so wall times are upper bounds): {parts}."
            + (f" Measured apart from that run, so not in this sum: {', '.join(apart)}."
               if apart else "")
            + " The full tier (`--tier full`) is not run here. The paper tier's cost is in the "
            "theorem section.")


def degenerate_section(inp):
    rows = read(os.path.join(inp, "degenerate.csv"))
    if rows is None:
        return None
    sets = group_rows(rows, "dist", "points")
    valid = sum(r["valid"] == "1" for r in rows)
    one_hash = sum(len({r["hash"] for r in rs}) == 1 for rs in sets.values())
    variants = sorted({len(rs) for rs in sets.values()})
    most = max(rows, key=lambda r: int(r["perturbations"]))
    none = sorted({d for (d, _), rs in sets.items() if all(int(r["perturbations"]) == 0 for r in rs)})
    out = [f"*Measured (generated).* {len(sets)} point sets ({', '.join(sorted({d for d, _ in sets}))}; "
           f"{', '.join(sorted({n for _, n in sets}, key=int))} points), each under "
           f"{', '.join(str(v) for v in variants)} variants (orders × locators × storages): "
           f"{valid} of {len(rows)} outputs pass exact validation, and {one_hash} of {len(sets)} "
           "inputs give one canonical hash across all their variants. Perturbation tie-breaks: "
           f"up to {fmt(int(most['perturbations']), 0)} ({most['dist']}, {most['points']} points)"
           + (f"; none on {', '.join(none)}" if none else "") + "."]
    out.append("")
    ok = valid == len(rows) and one_hash == len(sets)
    out.append("*Verdict (computed).* " + ("Every output is exactly valid and the same triangulation "
               "for every order, locator and storage." if ok else
               "Some outputs are invalid or differ between variants: see `degenerate.csv`."))
    return "\n".join(out)


def peers_section(inp):
    rows = read(os.path.join(inp, "peers.csv"))
    if rows is None:
        return None
    out = ["| input | n | time cavity/CGAL | goal | met? | memory cavity/CGAL | time cavity/TetGen "
           "(whole process / Delaunay phase) | tetrahedra cavity / CGAL / TetGen |",
           "|---|---|---|---|---|---|---|---|"]
    summary = []
    for (dist,), rs in sorted(group_rows(rows, "dist").items(), key=lambda kv: list(PEER_GOALS).index(kv[0][0])
                              if kv[0][0] in PEER_GOALS else 9):
        n = max(int(r["points"]) for r in rs)
        at = [r for r in rs if int(r["points"]) == n]
        cg = [r for r in at if r["cgal_status"] == "ok"]
        tg = [r for r in at if r["tetgen_status"] == "ok"]
        time_cgal = [float(r["cgal_time_ratio"]) for r in cg]
        goal = PEER_GOALS.get(dist)
        met = "—" if goal is None or not time_cgal else ("yes" if median(time_cgal) <= goal else "no")
        tg_whole = [float(r["tetgen_time_ratio"]) for r in tg]
        tg_phase = [float(r["cavity_s"]) / float(r["tetgen_delaunay_s"]) for r in tg
                    if r["tetgen_delaunay_s"] not in ("-", "0")]
        tets = " / ".join(str(int(median([float(r[f"{e}_tets"]) for r in sel]))) if sel else "—"
                          for e, sel in (("cavity", at), ("cgal", cg), ("tetgen", tg)))
        out.append(f"| {dist} | {n} | {spread(time_cgal) if time_cgal else '—'} | {goal or '—'} | {met} | "
                   f"{median([float(r['cgal_memory_ratio']) for r in cg]):.2f} | "
                   + (f"{median(tg_whole):.2f} / {median(tg_phase):.2f}" if tg_whole and tg_phase else "—")
                   + f" | {tets} |")
        if time_cgal:
            summary.append((dist, median(time_cgal), goal))
    seeds = len({r["seed"] for r in rows})
    out.append("")
    out.append(f"Median over {seeds} seeds [min–max] at each input's largest n; every size is in "
               "`summary.md`.")
    out.append("")
    met = [f"{d} ({t:.2f} against {g})" for d, t, g in summary if g is not None and t <= g]
    missed = [f"{d} ({t:.2f} against {g})" for d, t, g in summary if g is not None and t > g]
    out.append("*Verdict (computed).* Goal met on " + (", ".join(met) if met else "no input")
               + "; missed on " + (", ".join(missed) if missed else "no input")
               + ". The times were taken on a shared 2-core machine under load, so single runs "
               "vary; the spread is in the brackets.")
    return "\n".join(out)
