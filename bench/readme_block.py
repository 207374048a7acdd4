"""Rewrites one marked item of the top README from a benchmark's own data.

An item sits between the lines "<!-- NAME:begin -->" and "<!-- NAME:end -->"; the report script
that owns it replaces the whole item, so the README's figures are never typed and always those of
the run the script summarised.
"""
import os
import sys


def replace_block(readme, name, item):
    """Replaces the text between NAME's markers in `readme` by `item` (one Markdown list item)."""
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    with open(readme) as f:
        text = f.read()
    if begin not in text or end not in text:
        sys.exit(f"{readme}: no {begin} ... {end} block to replace")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    with open(readme + ".tmp", "w") as f:
        f.write(head + begin + "\n" + item + "\n" + end + tail)
    os.replace(readme + ".tmp", readme)
