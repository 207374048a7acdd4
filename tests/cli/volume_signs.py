"""Counts the tetrahedra of a TetGen .node/.ele pair by the sign of their volume under the
right-hand rule, det[b-a, c-a, d-a], computed exactly over the rationals (independent of cavity's
predicates). Prints "positive negative flat"."""

import sys
from fractions import Fraction


def data_lines(path):
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                yield line


def read_node(path):
    lines = data_lines(path)
    header = next(lines)
    count = int(header[0])
    points = {}
    for fields in lines:
        if len(points) == count:
            break
        points[int(fields[0])] = [Fraction(float.fromhex(x) if "p" in x else float(x))
                                  for x in fields[1:4]]
    return points


def main(node_path, ele_path):
    points = read_node(node_path)
    lines = data_lines(ele_path)
    count = int(next(lines)[0])
    tally = {"positive": 0, "negative": 0, "flat": 0}
    for fields in lines:
        a, b, c, d = (points[int(i)] for i in fields[1:5])
        u, v, w = ([q[k] - a[k] for k in range(3)] for q in (b, c, d))
        det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
               u[2] * (v[0] * w[1] - v[1] * w[0]))
        tally["positive" if det > 0 else "negative" if det < 0 else "flat"] += 1
    assert sum(tally.values()) == count, (count, tally)
    print(tally["positive"], tally["negative"], tally["flat"])


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
