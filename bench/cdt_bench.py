"""cavity cdt beside TetGen on real closed surface meshes; writes results/cdt/cdt.csv and README.md.

The models are the ones Debian packages ship (none of them written on this project): CGAL's data
meshes (libcgal-demo, data.tar.gz: data/meshes/) and OpenSCAD's test STL files
(openscad-testing-data); and, unless --no-render, the solids of OpenSCAD's 3D test scripts in that
package rendered to STL by Debian's `openscad` (constructive solid geometry: spheres, cones and
extrusions cut by one another, the kind of model CAD users bring, and a corpus no tuning of cavity
looked at before it was added). Nothing is copied into the repository: the script reads them from
the installed packages, or from --models. Each model is read here only to classify it (closed: every
edge in exactly two facets, no facet repeating a vertex) and to convert it to a TetGen .poly;
`cavity cdt` is given the original file, which it reads itself.

Per model and tool (cavity cdt, cavity cdt --protect, tetgen -p, tetgen -pY), one CSV row: status
(meshed / refused / timeout / crashed), the first line of the reason, wall and CPU seconds, Steiner
points, tetrahedra, and `cavity check --poly` on the output. A model is meshed --repeat times by
every tool, the tools taking turns, and the row keeps every time and their median: one slow run
of one tool must not decide a ratio of totals. TetGen's output is checked against the PLC
it conforms to: its output points with its output boundary triangles (the .1.face file), the
same kind of PLC that `cavity cdt` writes as PREFIX.poly.

Run it through bench/run_cdt_bench.sh, which installs the packages and builds cavity.
"""
import argparse
import csv
import hashlib
import io
import os
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tarfile
import tempfile
import time
from collections import Counter

CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
OPENSCAD_DATA = "/usr/share/openscad"
EXTENSIONS = (".off", ".stl", ".obj", ".ply")
TOOLS = ["cavity", "cavity --protect", "tetgen -p", "tetgen -pY"]
# OpenSCAD's test scripts whose solids are rendered (the 2D, import and export tests make none).
RENDERED_SCRIPTS = ("testdata/scad/3D", "testdata/scad/bugs", "testdata/scad/misc")
# A script's render is limited in CPU seconds, which the machine's load does not change: with a
# 30 s wall limit, issue267-normalization-crash (30.1 s of CPU) rendered in one run and not the next.
# The wall limit only stops a render that hangs.
RENDER_CPU_LIMIT = 120
RENDER_WALL_LIMIT = 900


class MeshError(Exception):
    pass


# ---------------------------------------------------------------- readers (classification only)

def _tokens_no_comments(text):
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            yield line


def read_off(data):
    lines = list(_tokens_no_comments(data.decode("latin-1")))
    if not lines:
        raise MeshError("empty file")
    head = lines[0].split()
    if not head[0].endswith("OFF"):
        raise MeshError("no OFF header")
    if head[0] not in ("OFF", "COFF", "NOFF", "CNOFF"):  # colours and normals follow x y z
        raise MeshError(f"unsupported OFF variant {head[0]}")
    if len(head) > 1:  # "OFF nv nf ne" on one line
        counts, body = head[1:], lines[1:]
    elif len(lines) > 1:
        counts, body = lines[1].split(), lines[2:]
    else:
        raise MeshError("no OFF counts")
    try:
        nv, nf = int(counts[0]), int(counts[1])
    except (IndexError, ValueError):
        raise MeshError("bad OFF counts")
    if len(body) < nv + nf:
        raise MeshError("truncated OFF")
    verts = [tuple(float(x) for x in body[k].split()[:3]) for k in range(nv)]
    faces = []
    for k in range(nv, nv + nf):
        w = body[k].split()
        n = int(w[0])
        faces.append([int(x) for x in w[1:1 + n]])
    return verts, faces


def read_stl(data):
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if 84 + 50 * n == len(data):
            verts, faces = [], []
            for k in range(n):
                v = struct.unpack_from("<12f", data, 84 + 50 * k)
                f = []
                for j in range(3):
                    verts.append(v[3 + 3 * j:6 + 3 * j])
                    f.append(len(verts) - 1)
                faces.append(f)
            return weld(verts, faces)
    text = data.decode("latin-1")
    if not text.lstrip().startswith("solid"):
        raise MeshError("neither ASCII nor binary STL")
    verts, faces, cur = [], [], []
    for line in text.splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "vertex":
            if len(w) != 4:
                raise MeshError("bad STL vertex line")
            verts.append(tuple(float(x) for x in w[1:4]))
            cur.append(len(verts) - 1)
        elif w[0] == "endloop":
            faces.append(cur)
            cur = []
    if not faces:
        raise MeshError("no facets")
    return weld(verts, faces)


def weld(verts, faces):
    """STL lists each triangle's corners: identical coordinates are one vertex."""
    index, out = {}, []
    remap = []
    for v in verts:
        if v not in index:
            index[v] = len(out)
            out.append(v)
        remap.append(index[v])
    return out, [[remap[i] for i in f] for f in faces]


def read_obj(data):
    verts, faces = [], []
    for line in data.decode("latin-1").splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            verts.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "f":
            f = []
            for t in w[1:]:
                i = int(t.split("/")[0])
                f.append(i - 1 if i > 0 else len(verts) + i)
            faces.append(f)
    return verts, faces


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}


def read_ply(data):
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise MeshError("no PLY header")
    header = data[:end].decode("latin-1").splitlines()
    body = data[data.index(b"\n", end) + 1:]
    fmt, elements = None, []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            elements[-1][2].append(w[1:])
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise MeshError(f"unsupported PLY format {fmt}")
    verts, faces = [], []
    if fmt == "ascii":
        words = body.decode("latin-1").split()
        pos = 0

        def take(_t):
            nonlocal pos
            pos += 1
            return float(words[pos - 1])
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        pos = 0

        def take(t):
            nonlocal pos
            code = order + PLY_TYPES[t]
            v = struct.unpack_from(code, body, pos)[0]
            pos += struct.calcsize(code)
            return v
    for name, count, props in elements:
        for _ in range(count):
            row = {}
            for p in props:
                if p[0] == "list":
                    n = int(take(p[1]))
                    row[p[3]] = [int(take(p[2])) for _ in range(n)]
                else:
                    row[p[1]] = take(p[0])
            if name == "vertex":
                verts.append((row["x"], row["y"], row["z"]))
            elif name == "face":
                faces.append(row.get("vertex_indices", row.get("vertex_index")))
    return verts, faces


def read_mesh(path):
    data = open(path, "rb").read()
    ext = os.path.splitext(path)[1].lower()
    try:
        return {".off": read_off, ".stl": read_stl, ".obj": read_obj, ".ply": read_ply}[ext](data)
    except (ValueError, IndexError, KeyError, struct.error, TypeError) as e:
        raise MeshError(f"unreadable ({type(e).__name__})")


def classify(verts, faces):
    """'' for a closed mesh, else why not: the script's own combinatorial test."""
    if not faces:
        return "no facets"
    edges = Counter()
    for f in faces:
        if len(f) < 3 or len(set(f)) != len(f):
            return "a facet repeats a vertex"
        if any(i < 0 or i >= len(verts) for i in f):
            return "a facet index out of range"
        for a, b in zip(f, f[1:] + f[:1]):
            edges[(min(a, b), max(a, b))] += 1
    if any(c == 1 for c in edges.values()):
        return "open (boundary edges)"
    if any(c > 2 for c in edges.values()):
        return "non-manifold edges"
    return ""


def write_poly(path, verts, faces):
    """TetGen .poly of the mesh's facets, 1-based, unreferenced vertices dropped."""
    used = sorted({i for f in faces for i in f})
    renum = {old: k + 1 for k, old in enumerate(used)}
    with open(path, "w") as out:
        out.write(f"{len(used)} 3 0 0\n")
        for old in used:
            x, y, z = verts[old]
            out.write(f"{renum[old]} {x!r} {y!r} {z!r}\n")
        out.write(f"{len(faces)} 0\n")
        for f in faces:
            out.write("1\n" + f"{len(f)} " + " ".join(str(renum[i]) for i in f) + "\n")
        out.write("0\n0\n")
    return len(used)


# ---------------------------------------------------------------- corpus

def render_scripts(work):
    """OpenSCAD's 3D test scripts rendered to STL, two at a time: (name, path) of each rendered
    solid, and (name, path, reason) of each script that made none."""
    scripts = sorted(os.path.join(r, f) for d in RENDERED_SCRIPTS
                     for r, _, fs in os.walk(os.path.join(OPENSCAD_DATA, d)) for f in fs if f.endswith(".scad"))

    def render(script):
        rel = os.path.relpath(script, os.path.join(OPENSCAD_DATA, "testdata/scad"))
        name = "openscad-render/" + rel[:-len(".scad")] + ".stl"
        out = os.path.join(work, name)
        os.makedirs(os.path.dirname(out), exist_ok=True)
        try:
            # In the script's folder: scripts include and import files beside them.
            # util-linux's prlimit sets the CPU limit (SIGXCPU, then SIGKILL a second later) and
            # runs openscad; a preexec_fn would not be safe from these two threads.
            cpu = f"--cpu={RENDER_CPU_LIMIT}:{RENDER_CPU_LIMIT + 1}"
            r = subprocess.run(["prlimit", cpu, "openscad", "-o", out, script],
                               cwd=os.path.dirname(script), stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, timeout=RENDER_WALL_LIMIT)
            code = r.returncode
            if code == -signal.SIGXCPU or code == -signal.SIGKILL:
                code = "CPU limit"
        except subprocess.TimeoutExpired:
            code = "timeout"
        if code == 0 and os.path.isfile(out) and os.path.getsize(out) > 0:
            return name, out, ""
        return name, out, f"openscad made no solid of the script (exit {code})"

    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(render, scripts))
    return [(n, p) for n, p, why in results if not why], [r for r in results if r[2]]


def shipped_test_meshes():
    """The mesh files of openscad-testing-data, as its package lists them: the `openscad` package
    (installed to render the scripts) puts example meshes in the same folder, which are not part
    of the corpus."""
    r = subprocess.run(["dpkg-query", "-L", "openscad-testing-data"], capture_output=True, text=True)
    if r.returncode != 0:
        return []
    return sorted(p for p in r.stdout.splitlines()
                  if p.startswith(OPENSCAD_DATA + "/") and p.lower().endswith(EXTENSIONS) and os.path.isfile(p))


def collect(extra, limit_faces, include_open, rendered_scripts):
    """(name, path, facets, points or None, reason-not-run) per model, duplicates by content dropped."""
    work = tempfile.mkdtemp(prefix="cdt-bench-models-")
    sources, unrendered = [], []
    if rendered_scripts:
        sources, unrendered = render_scripts(work)
    if os.path.exists(CGAL_DATA):
        with tarfile.open(CGAL_DATA) as tar:
            for m in tar.getmembers():
                if m.isfile() and m.name.startswith("data/meshes/") and m.name.lower().endswith(EXTENSIONS):
                    dest = os.path.join(work, "cgal", os.path.basename(m.name))
                    os.makedirs(os.path.dirname(dest), exist_ok=True)
                    with tar.extractfile(m) as src, open(dest, "wb") as out:
                        shutil.copyfileobj(src, out)
                    sources.append(("cgal/" + os.path.basename(m.name), dest))
    for p in shipped_test_meshes():
        sources.append(("openscad/" + os.path.relpath(p, OPENSCAD_DATA), p))
    for e in extra:
        paths = [e] if os.path.isfile(e) else [os.path.join(r, f) for r, _, fs in sorted(os.walk(e))
                                                for f in sorted(fs) if f.lower().endswith(EXTENSIONS)]
        sources += [("extra/" + os.path.basename(p), p) for p in paths]
    seen, models = {}, [(name, path, 0, None, why) for name, path, why in unrendered]
    # Corpus by corpus, the shipped files first: a rendered solid that repeats a shipped STL file
    # is the duplicate, and the shipped corpora stay as they were before rendering was added.
    rank = {"cgal": 0, "openscad": 1, "openscad-render": 2}
    for name, path in sorted(sources, key=lambda s: (rank.get(s[0].split("/")[0], 3), s[0])):
        digest = hashlib.sha256(open(path, "rb").read()).hexdigest()
        if digest in seen:
            models.append((name, path, 0, None, f"same file as {seen[digest]}"))
            continue
        seen[digest] = name
        try:
            verts, faces = read_mesh(path)
            why = classify(verts, faces)
        except MeshError as e:
            models.append((name, path, 0, None, str(e)))
            continue
        if why and not include_open:
            models.append((name, path, len(faces), None, why))
        elif limit_faces and len(faces) > limit_faces:
            models.append((name, path, len(faces), None, f"over --max-faces ({len(faces)} facets)"))
        else:
            poly = os.path.join(work, "poly", hashlib.sha1(name.encode()).hexdigest()[:12] + ".poly")
            os.makedirs(os.path.dirname(poly), exist_ok=True)
            points = write_poly(poly, verts, faces)
            models.append((name, path, len(faces), (poly, points), ""))
    return work, models


# ---------------------------------------------------------------- running

def child_cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(cmd, cwd, timeout):
    """(exit status or None on timeout, wall seconds, output); the process group is ended on timeout."""
    start = time.monotonic()
    try:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             start_new_session=True)
    except OSError as e:
        return -1000, 0.0, f"could not run {cmd[0]}: {e.strerror}"
    try:
        out, _ = p.communicate(timeout=timeout)
        return p.returncode, time.monotonic() - start, out.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        return None, time.monotonic() - start, ""


def first_line(text, prefer=()):
    """The first line of the reason (with the preferred key), and the line after it when it ends in ':'."""
    # cavity's notes and warnings say what it did, not why it stopped
    lines = [ln.strip() for ln in text.splitlines()
             if ln.strip() and not ln.startswith(("cavity: note:", "cavity: warning:"))]
    at = 0
    for key in prefer:
        hits = [k for k, ln in enumerate(lines) if key in ln]
        if hits:
            at = hits[0]
            break
    if not lines:
        return ""
    line = lines[at]
    if line.endswith(":") and at + 1 < len(lines):
        line += " " + lines[at + 1]
    return line


def count_header(path):
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                return int(line[0])
    return 0


def check(cavity, poly, node, ele, cwd, timeout, exact=None):
    # With implicit Steiner points the exact mesh is the .node with the .exact side file.
    extra = ["--exact", exact] if exact and os.path.exists(os.path.join(cwd, exact)) else []
    rc, secs, out = run([cavity, "check", "--quiet", "--poly", poly, node, ele] + extra, cwd, timeout)
    if rc is None:
        return "check timeout", secs
    if rc == 0:
        return "valid", secs
    return "INVALID: " + first_line(out)[:200], secs


def timed(cmd, cwd, timeout):
    """run(), with the CPU seconds of the process and its children: (status, wall, cpu, output)."""
    before = child_cpu_seconds()
    rc, secs, out = run(cmd, cwd, timeout)
    return rc, secs, child_cpu_seconds() - before, out


def run_cavity(cavity, model, protect, d, timeout):
    """The CSV row, and the command that made the mesh (for the repeated timings)."""
    os.makedirs(d, exist_ok=True)
    cmd = [cavity, "cdt"] + (["--protect"] if protect else []) + [os.path.abspath(model), "-o", "out"]
    rc, secs, cpu, out = timed(cmd, d, timeout)
    row = {"runs": f"{secs:.3f}", "cpu_runs": f"{cpu:.3f}"}
    if rc is None:
        return dict(row, status="timeout", reason=f"over {timeout:g} s"), None
    if rc != 0:
        status = "refused" if rc == 1 else f"crashed (exit {rc})"
        reason = first_line(out, ("cavity:",)).replace(os.path.abspath(model), os.path.basename(model))
        return dict(row, status=status, reason=reason[:200]), None
    m = re.search(r"(\d+) points \((\d+) inserted for protection\)", out)
    k = re.search(r"(\d+) tetrahedra kept", out)
    rounding = re.search(r"(\d+) of the kept tetrahedra are inverted and (\d+) flat", out)
    row.update(status="meshed", reason="", steiner=m.group(2) if m else "?",
               tets=k.group(1) if k else str(count_header(os.path.join(d, "out.ele"))),
               rounded_bad=str(int(rounding.group(1)) + int(rounding.group(2))) if rounding else "")
    row["check"], row["check_seconds"] = check(cavity, "out.poly", "out.node", "out.ele", d, timeout,
                                               "out.exact")
    row["check_seconds"] = f"{row['check_seconds']:.3f}"
    return row, cmd


def tetgen_check_poly(d, stem):
    """The PLC TetGen's mesh conforms to: its output points and its output boundary triangles."""
    node, face = os.path.join(d, stem + ".node"), os.path.join(d, stem + ".face")
    with open(face) as f:
        rows = [ln.split("#", 1)[0].split() for ln in f]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    tris = [r[1:4] for r in rows[1:1 + n]]
    with open(node) as f:
        nodes = [ln for ln in f if ln.split("#", 1)[0].strip()]
    with open(os.path.join(d, "check.poly"), "w") as out:
        out.writelines(nodes)
        out.write(f"{len(tris)} 0\n")
        for t in tris:
            out.write("1\n3 " + " ".join(t) + "\n")
        out.write("0\n0\n")


def run_tetgen(tetgen, cavity, poly, points, switches, d, timeout):
    """The CSV row, and the command that made the mesh (for the repeated timings)."""
    os.makedirs(d, exist_ok=True)
    shutil.copy(poly, os.path.join(d, "in.poly"))
    # not quiet, line-buffered: the Debian build aborts on bad input (an uncaught int) without a word,
    # and the phase it was in and its warnings are the only clue
    cmd = ["stdbuf", "-oL", tetgen, switches, "in.poly"]
    rc, secs, cpu, out = timed(cmd, d, timeout)
    row = {"runs": f"{secs:.3f}", "cpu_runs": f"{cpu:.3f}"}
    if rc is None:
        return dict(row, status="timeout", reason=f"over {timeout:g} s"), None
    ele = os.path.join(d, "in.1.ele")
    if rc != 0 or not os.path.exists(ele):
        status = "refused" if rc in (0, 1, -6, 134) else f"crashed (exit {rc})"
        lines = [ln.strip() for ln in out.splitlines() if ln.strip()]
        said = [ln for ln in lines if re.match(r"(Warning|Error|!!)", ln)]
        phase = [ln for ln in lines if ln.endswith("...")]
        reason = (said[0] if said else "") + (f" (aborted in: {phase[-1]})" if phase else f" (exit {rc})")
        drc, _, dout = run(["stdbuf", "-oL", tetgen, "-d", "in.poly"], d, timeout)
        found = [ln.strip() for ln in dout.splitlines() if ln.strip().startswith("!!") or "Found" in ln]
        reason += "; tetgen -d: " + (found[0].lstrip("! ") if found else f"reports no intersection (exit {drc})")
        return dict(row, status=status, reason=reason.strip()[:200]), None
    nodes = count_header(os.path.join(d, "in.1.node"))
    row.update(status="meshed", reason="", steiner=str(nodes - points), tets=str(count_header(ele)))
    tetgen_check_poly(d, "in.1")
    row["check"], secs = check(cavity, "check.poly", "in.1.node", "in.1.ele", d, timeout)
    row["check_seconds"] = f"{secs:.3f}"
    return row, cmd


def median(values):
    """The median; of an even count, the mean of the middle two."""
    v = sorted(values)
    h = len(v) // 2
    return v[h] if len(v) % 2 else (v[h - 1] + v[h]) / 2


def retime(row, cmd, d, timeout):
    """One more timed run of the command that meshed; a run that no longer meshes is reported."""
    rc, secs, cpu, _ = timed(cmd, d, timeout)
    row["runs"] += f";{secs:.3f}"
    row["cpu_runs"] += f";{cpu:.3f}"
    if rc != 0:
        print(f"cdt_bench: warning: a repeated run of {' '.join(cmd)} in {d} ended with status {rc}",
              file=sys.stderr)


def settle(row):
    """The row's seconds and cpu_seconds: the medians of its runs."""
    for key, runs in (("seconds", "runs"), ("cpu_seconds", "cpu_runs")):
        row[key] = f"{median(float(t) for t in row[runs].split(';')):.3f}"


# ---------------------------------------------------------------- report

def fmt_row(r):
    if r["status"] == "meshed":
        ok = "valid" if r["check"] == "valid" else "**" + r["check"].split(":")[0] + "** (" + \
            r["check"].rsplit(": ", 1)[-1].replace("|", "\\|")[:70] + ")"
        rounded = (f", {r['rounded_bad']} inverted or flat when rounded"
                   if r.get("rounded_bad") not in (None, "", "0") else "")
        return f"{r['seconds']} s, +{r['steiner']}, {r['tets']} tets, {ok}{rounded}"
    if r["status"] == "timeout":
        return "timeout"
    reason = r["reason"].replace("|", "\\|")
    if len(reason) > 90:
        reason = reason[:87] + "..."
    return f"{r['status']}: {reason}"


def round_range(by, models, a, b):
    """The lowest and highest ratio of total wall times of tools a and b over the rounds of repeated
    runs; None with one round."""
    runs = [[[float(t) for t in by[(m, tool)]["runs"].split(";")] for m in models] for tool in (a, b)]
    rounds = min(len(r) for per_tool in runs for r in per_tool)
    if rounds < 2:
        return None
    ratios = sorted(sum(r[k] for r in runs[0]) / sum(r[k] for r in runs[1]) for k in range(rounds))
    return ratios[0], ratios[-1]


def round_spread(by, models, a, b):
    spread = round_range(by, models, a, b)
    return f"; round by round, from {spread[0]:.2f} to {spread[1]:.2f}" if spread else ""


def totals(by, models, a, b, column):
    """The sums of a CSV column over the given models for tools a and b: integers for Steiner
    points, seconds otherwise."""
    kind = int if column == "steiner" else float
    return tuple(sum(kind(by[(m, tool)][column]) for m in models) for tool in (a, b))


def report(rows, models, args, elapsed, load):
    run_names = [m[0] for m in models if m[3] is not None]
    skipped = [m for m in models if m[3] is None]
    by = {(r["model"], r["tool"]): r for r in rows}
    out = io.StringIO()
    p = lambda s="": out.write(s + "\n")  # noqa: E731
    p("# cavity cdt beside TetGen on real surface meshes\n")
    p(f"Made by `bench/run_cdt_bench.sh{(' ' + ' '.join(args.passed)) if args.passed else ''}` "
      f"(`bench/cdt_bench.py`; every number on this page is written by it from `cdt.csv`). "
      f"Models: the closed surface meshes shipped by the Debian packages libcgal-demo (CGAL's "
      f"`data/meshes/`, names `cgal/`) and openscad-testing-data (OpenSCAD's test STL files, "
      f"`openscad/`), read from the installed packages, none written on this project"
      + ("" if args.no_render else
         f"; and the solids of OpenSCAD's 3D test scripts in that package, rendered to STL by Debian's "
         f"`openscad` {package_version('openscad')} (`openscad-render/`: constructive solid geometry, spheres, "
         f"cones and extrusions cut by one another; a corpus added after the tuning of cavity's edge "
         f"protection, which looked only at the other two; a script whose render takes over "
         f"{RENDER_CPU_LIMIT} s of CPU is left out)")
      + "; duplicates by content and models that are not closed "
      "(every edge in exactly two facets)"
      + (f" and models over {args.max_faces} facets" if args.max_faces else "")
      + f" are left out (listed below). `cavity cdt` reads each file itself; TetGen {package_version('tetgen')} gets the "
      f"script's conversion to `.poly`. Time limit {args.timeout:g} s per run. Each tool meshed each model "
      f"it meshes {args.repeat} time{'s' if args.repeat > 1 else ''}, the tools taking turns; the times "
      f"are the medians of those runs, wall and CPU (user + system) seconds of the process, on a "
      f"2-core machine (load average at the start: {load}). The whole run took {elapsed:.0f} s.\n")
    p("Steiner points: for cavity, the points it inserted for edge protection (its summary line); for "
      "TetGen, points in its `.node` output minus points in the `.poly`. Tetrahedra: of the carved "
      "domain. Validation: `cavity check --poly` (exact) of the mesh against the PLC it conforms to: "
      "cavity's `PREFIX.poly`; for TetGen, its output points with its output boundary triangles "
      "(`.1.face`), so rounded Steiner points are checked as the doubles TetGen wrote. When cavity "
      "made implicit Steiner points (exact points on edges with no double point inside), its check "
      "reads them exactly from `PREFIX.exact` (`--exact`).\n")
    p("## Summary\n")
    p(f"{len(run_names)} models run; {len(skipped)} files left out.\n")
    p("| tool | meshed | valid (of meshed) | refused | timeout | crashed | Steiner points (all meshed) | "
      "median wall s (meshed) |")
    p("|---|---|---|---|---|---|---|---|")
    for tool in TOOLS:
        rs = [by[(m, tool)] for m in run_names if (m, tool) in by]
        meshed = [r for r in rs if r["status"] == "meshed"]
        times = sorted(float(r["seconds"]) for r in meshed)
        med = f"{times[len(times) // 2]:.3f}" if times else "–"
        steiner = sum(int(r["steiner"]) for r in meshed if r["steiner"].isdigit())
        p(f"| `{tool}` | {len(meshed)} of {len(rs)} | {sum(r['check'] == 'valid' for r in meshed)} | "
          f"{sum(r['status'] == 'refused' for r in rs)} | {sum(r['status'] == 'timeout' for r in rs)} | "
          f"{sum(r['status'].startswith('crashed') for r in rs)} | {steiner} | {med} |")
    p()
    exact = [r for r in rows if r["tool"].startswith("cavity") and r.get("rounded_bad", "") != ""]
    if exact:
        bad = sum(int(r["rounded_bad"]) for r in exact)
        p(f"- Meshes with implicit (exact) Steiner points: {len(exact)} runs of cavity, validated with "
          f"their `.exact` side file; rounding their points to doubles for the `.node` leaves "
          f"{bad} kept tetrahedra inverted or flat in all of them.")
    pairs = [("cavity --protect", "tetgen -p"), ("cavity", "tetgen -p"), ("cavity --protect", "tetgen -pY")]
    for a, b in pairs:
        both = [m for m in run_names if by.get((m, a), {}).get("status") == "meshed"
                and by.get((m, b), {}).get("status") == "meshed"]
        if not both:
            p(f"- `{a}` and `{b}` mesh no model in common.")
            continue
        sa, sb = totals(by, both, a, b, "steiner")
        ta, tb = totals(by, both, a, b, "seconds")
        ca, cb = totals(by, both, a, b, "cpu_seconds")
        p(f"- On the {len(both)} models both `{a}` and `{b}` mesh: Steiner points {sa} against {sb}; "
          f"total wall time {ta:.2f} s against {tb:.2f} s (ratio {ta / tb:.2f}{round_spread(by, both, a, b)}); "
          f"CPU time {ca:.2f} s against {cb:.2f} s (ratio {ca / cb:.2f}).")
        # TetGen recovers segments by flips and may stop short of a constrained Delaunay mesh; the
        # Steiner points of meshes that are one compare like with like.
        valid = [m for m in both if by[(m, a)]["check"] == "valid" and by[(m, b)]["check"] == "valid"]
        if a == "cavity --protect" and b == "tetgen -p" and valid and len(valid) < len(both):
            sa, sb = totals(by, valid, a, b, "steiner")
            p(f"  Of them, on the {len(valid)} where both meshes pass the exact check (a constrained "
              f"Delaunay tetrahedralization of the PLC): Steiner points {sa} against {sb}.")
    corpora = sorted({m.split("/")[0] for m in run_names})
    a, b = "cavity --protect", "tetgen -p"
    if len(corpora) > 1:
        p(f"\nBy corpus, `{a}` against `{b}` on the models both mesh, and on those of them where both "
          f"meshes pass the exact check (valid both):\n")
        p("| corpus | models | Steiner points | wall s | time ratio | valid both | Steiner points (valid both) |")
        p("|---|---|---|---|---|---|---|")
        for c in corpora:
            both = [m for m in run_names if m.split("/")[0] == c
                    and by.get((m, a), {}).get("status") == "meshed" and by.get((m, b), {}).get("status") == "meshed"]
            if not both:
                p(f"| `{c}/` | 0 | – | – | – | – | – |")
                continue
            valid = [m for m in both if by[(m, a)]["check"] == "valid" and by[(m, b)]["check"] == "valid"]
            sa, sb = totals(by, both, a, b, "steiner")
            va, vb = totals(by, valid, a, b, "steiner")
            ta, tb = totals(by, both, a, b, "seconds")
            spread = round_range(by, both, a, b)
            rounds = f" (rounds {spread[0]:.2f} to {spread[1]:.2f})" if spread else ""
            p(f"| `{c}/` | {len(both)} | {sa} against {sb} | {ta:.2f} against "
              f"{tb:.2f} | {ta / tb:.2f}{rounds} | {len(valid)} | {va} against {vb} |")
    reasons = Counter()
    for m in run_names:
        r = by.get((m, "cavity --protect"))
        if r and r["status"] == "refused":
            why = re.sub(r"^cavity: [^:\s]*(:\d+)?: ", "", r["reason"])
            # A minus sign after a digit joins two numbers ("edge 3-17"), it negates none.
            reasons[re.sub(r"(?<![\d.])-?\d+(\.\d+)?(e-?\d+)?", "N", why)[:110]] += 1
    if reasons:
        p("\nWhy `cavity cdt --protect` refused (numbers replaced by N):\n")
        for why, n in reasons.most_common(8):
            p(f"- {n} × {why}")
    p("\n## Per model\n")
    p("Each cell: median wall seconds, +Steiner points, tetrahedra, validation; or the status and the first "
      "line of the reason.\n")
    p("| model | facets | " + " | ".join(f"`{t}`" for t in TOOLS) + " |")
    p("|---|---" + "|---" * len(TOOLS) + "|")
    for name, _, nf, poly, _ in models:
        if poly is None:
            continue
        p(f"| {name} | {nf} | " + " | ".join(fmt_row(by[(name, t)]) if (name, t) in by else "–"
                                             for t in TOOLS) + " |")
    p("\n## Left out\n")
    for why, n in Counter(re.sub(r"\(\d+ facets\)", "", m[4]).strip() if not m[4].startswith("same file")
                          else "duplicate of another model" for m in skipped).most_common():
        p(f"- {n} × {why}")
    p("\n" + ", ".join(f"{m[0]} ({m[4]})" for m in skipped) + ".")
    return out.getvalue()


def package_version(package):
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], capture_output=True, text=True)
        return out.stdout.strip() or "(version unknown)"
    except OSError:
        return "(version unknown)"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--timeout", type=float, default=120, help="seconds per run of a tool or check (default 120)")
    # No limit by default: the largest shipped closed model (88928 facets) takes cavity 7 s, and
    # leaving the large ones out would hide from the summary the models users bring most.
    ap.add_argument("--max-faces", type=int, default=0,
                    help="leave out models with more facets (default 0: no limit)")
    ap.add_argument("--limit", type=int, default=0, help="run only the first N models (by name; default all)")
    ap.add_argument("--tools", default=",".join(TOOLS),
                    help=f"comma-separated subset of: {', '.join(TOOLS)}")
    ap.add_argument("--models", action="append", default=[],
                    help="also a surface-mesh file or a directory of them (repeatable)")
    ap.add_argument("--all", action="store_true", help="also run models that are not closed")
    ap.add_argument("--no-render", action="store_true",
                    help="leave out the solids of OpenSCAD's test scripts (rendered by `openscad`)")
    ap.add_argument("--cavity", default="build/release/cli/cavity", help="the cavity binary")
    ap.add_argument("--tetgen", default="/usr/bin/tetgen", help="the TetGen binary")
    ap.add_argument("--out", default="results/cdt", help="where cdt.csv and README.md are written")
    ap.add_argument("--keep", action="store_true", help="keep the work directory (printed) with every output")
    ap.add_argument("--repeat", type=int, default=5,
                    help="times each tool meshes each model it meshes, the tools taking turns; the "
                         "report gives the medians (default 5)")
    args = ap.parse_args()
    args.passed = sys.argv[1:]
    if args.cavity == ap.get_default("cavity") and "--cavity" in args.passed:  # as the wrapper passes it
        k = args.passed.index("--cavity")
        del args.passed[k:k + 2]
    tools = [t.strip() for t in args.tools.split(",")]
    for t in tools:
        if t not in TOOLS:
            ap.error(f"unknown tool {t!r} in --tools (known: {', '.join(TOOLS)})")
    for b in (args.cavity, args.tetgen):
        if not os.access(b, os.X_OK):
            sys.exit(f"cdt_bench: {b} is not an executable (build cavity, install tetgen: bench/run_cdt_bench.sh)")
    if not os.path.exists(CGAL_DATA) and not os.path.isdir(OPENSCAD_DATA) and not args.models:
        sys.exit("cdt_bench: no models: install libcgal-demo and openscad-testing-data, or give --models")
    if args.repeat < 1:
        ap.error("--repeat must be at least 1")
    if not args.no_render and shutil.which("openscad") is None:
        sys.exit("cdt_bench: no `openscad` to render OpenSCAD's test scripts: install Debian's openscad "
                 "(bench/run_cdt_bench.sh does), or pass --no-render")
    args.cavity = os.path.abspath(args.cavity)
    load = os.getloadavg()
    load = f"{load[0]:.1f}"
    start = time.monotonic()
    work, models = collect(args.models, args.max_faces, args.all, not args.no_render)
    runnable = [m for m in models if m[3] is not None]
    if args.limit:
        keep = {m[0] for m in runnable[:args.limit]}
        models = [m if m[3] is None or m[0] in keep else (m[0], m[1], m[2], None, "over --limit")
                  for m in models]
        runnable = [m for m in runnable if m[0] in keep]
    rows = []
    for k, (name, path, nf, (poly, points), _) in enumerate(runnable):
        base = os.path.join(work, "run", f"{k:03d}")
        made = []
        for tool in tools:
            d = os.path.join(base, tool.replace(" ", "").replace("-", "_"))
            if tool.startswith("cavity"):
                r, cmd = run_cavity(args.cavity, path, "--protect" in tool, d, args.timeout)
            else:
                r, cmd = run_tetgen(args.tetgen, args.cavity, poly, points, tool.split()[1].lstrip("-"), d,
                                    args.timeout)
            r.update(model=name, facets=nf, points=points, tool=tool)
            rows.append(r)
            made.append((r, cmd, d))
        # The tools take turns round by round, so a slow spell of the machine falls on all of them.
        for _ in range(args.repeat - 1):
            for r, cmd, d in made:
                if cmd is not None:
                    retime(r, cmd, d, args.timeout)
        for r, _, _ in made:
            settle(r)
            tool = r["tool"]
            print(f"[{k + 1}/{len(runnable)}] {name} {tool}: {r['status']} {r['seconds']} s "
                  f"{r.get('check', '')} {r.get('reason', '')[:100]}", file=sys.stderr, flush=True)
        if not args.keep:
            shutil.rmtree(base, ignore_errors=True)
    elapsed = time.monotonic() - start
    os.makedirs(args.out, exist_ok=True)
    fields = ["model", "facets", "points", "tool", "status", "reason", "seconds", "cpu_seconds", "steiner",
              "tets", "check", "check_seconds", "rounded_bad", "runs", "cpu_runs"]
    with open(os.path.join(args.out, "cdt.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, restval="")
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.out, "README.md"), "w") as f:
        f.write(report(rows, models, args, elapsed, load))
    if args.keep:
        print(f"cdt_bench: outputs kept in {work}", file=sys.stderr)
    else:
        shutil.rmtree(work, ignore_errors=True)
    print(f"cdt_bench: wrote {args.out}/cdt.csv and {args.out}/README.md ({elapsed:.0f} s)", file=sys.stderr)


if __name__ == "__main__":
    main()
