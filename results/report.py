#!/usr/bin/python3
"""Writes the generated sections of results/README.md from the experiment CSVs.

Usage: /usr/bin/python3 results/report.py IN_DIR README [PAPER_DIR]

PAPER_DIR holds the paper tier's tables (a long run, possibly merged part-way); the theorem
section uses them when present, else the quick tier's.

Each generated section sits between the lines
    <!-- BEGIN GENERATED name (results/report.py; do not edit) -->
    <!-- END GENERATED name -->
and is rewritten whole from the tables of the same run, so its text cannot disagree with the
plots. Sections whose tables are missing are left as they are. Every number in a generated
section is computed here; the only constants typed in are the chapter's predictions.

The sections are built in results/reporting/, one module per part of the chapter; plot.py takes
its estimators from there too, so plots and text use the same ones.
"""
import re
import sys

from reporting.engines import cost_section, degenerate_section, peers_section
from reporting.exercises import adversarial_section, extend_section
from reporting.propositions import brio_section, creation_dir, creation_section, jtets_section
from reporting.second_half import cdt_section, deletion_section, giftwrap_section
from reporting.theorem import quadratic_section, scaling_section, theorem_section
from reporting.walking import locality_section, walk_section

SECTIONS = {"creation": creation_section, "scaling": scaling_section, "brio": brio_section,
            "walk": walk_section, "adversarial": adversarial_section,
            "quadratic": quadratic_section, "locality": locality_section, "cost": cost_section,
            "jtets": jtets_section, "degenerate": degenerate_section, "peers": peers_section,
            "giftwrap": giftwrap_section, "deletion": deletion_section, "cdt": cdt_section,
            "extend": extend_section}


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    inp, readme = sys.argv[1], sys.argv[2]
    paper = sys.argv[3] if len(sys.argv) == 4 else None
    text = open(readme).read()
    builders = dict(SECTIONS)
    builders["theorem"] = lambda d: theorem_section(d, paper)
    builders["creation"] = lambda d: creation_section(creation_dir(d, paper))
    for name, build in builders.items():
        body = build(inp)
        if body is None:
            continue
        pattern = re.compile(r"(<!-- BEGIN GENERATED " + name + r" [^\n]*-->\n).*?(<!-- END GENERATED "
                             + name + r" -->)", re.S)
        if not pattern.search(text):
            sys.exit(f"report.py: {readme} has no generated section '{name}'")
        text = pattern.sub(lambda m: m.group(1) + body + "\n" + m.group(2), text)
    with open(readme, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
