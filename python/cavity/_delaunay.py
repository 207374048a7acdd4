"""cavity.Delaunay: scipy.spatial.Delaunay's interface over cavity's exact triangulation.

The engine (construction, point location, vertex neighbours, incremental insertion, validation)
is the extension's Triangulation; what is plain arithmetic on its arrays (barycentric
transforms, the lifted hyperplanes) is numpy here, computed on first use and kept, as scipy does.
"""

from __future__ import annotations

import warnings
from typing import Any, Callable, Optional

import numpy as np

from . import _cavity

#: VTK's cell type number of a linear tetrahedron (vtkCellType.h: VTK_TETRA).
VTK_TETRA = 10


def _refuse_unsupported(points: Any, furthest_site: bool, qhull_options: Optional[str]) -> None:
    if furthest_site:
        raise ValueError(
            "cavity.Delaunay has no furthest-site triangulation (furthest_site=True): use "
            "scipy.spatial.Delaunay(points, furthest_site=True)")
    if qhull_options is not None:
        raise ValueError(
            f"cavity.Delaunay does not run Qhull, so qhull_options={qhull_options!r} has no "
            "meaning: its predicates are exact and degenerate input is resolved by symbolic "
            "perturbation, with no joggling ('QJ') or tolerances to set; drop the argument")
    try:
        shape = np.shape(points)
    except ValueError:  # ragged: the engine's conversion names the problem
        shape = ()
    if len(shape) == 2 and shape[1] != 3:
        advice = ("for 2-D points use scipy.spatial.Delaunay (or matplotlib.tri.Triangulation)"
                  if shape[1] == 2 else "scipy.spatial.Delaunay handles other dimensions")
        raise ValueError(f"points must have shape (n, 3), got {shape}: cavity.Delaunay "
                         f"triangulates points in 3-D; {advice}")


class Delaunay:
    """Exact Delaunay tetrahedralization of points in 3-D, or the regular (weighted Delaunay)
    triangulation of weighted points.

    A drop-in replacement for ``scipy.spatial.Delaunay`` on 3-D input, with the same attributes
    and methods. The predicates are exact for every finite double and degeneracies (grids,
    cospherical points) are resolved by a symbolic perturbation keyed on the row index, so the
    triangulation exists, is unique and has no flat tetrahedron: the same tetrahedra for every
    insertion order, point locator, storage and batch of ``add_points``.

    Parameters
    ----------
    points : array_like of floats, shape (npoints, 3)
        Coordinates of the points to triangulate (converted to float64; finite).
    furthest_site : bool, optional
        Must be False: there is no furthest-site triangulation (scipy has one).
    incremental : bool, optional
        Keep the triangulation live, so that ``add_points`` inserts into it.
    qhull_options : None, optional
        Must be None: cavity does not run Qhull and needs no precision options.
    weights : array_like of floats, shape (npoints,), optional
        Weights: the result is the regular triangulation (power diagram dual). Keyword only.
    order : {"brio", "hilbert", "zorder", "random", "input"}, optional
        Insertion order (Cheng, Dey & Shewchuk section 5.3). Default "brio".
    locate : {"walk", "straight-walk", "conflict-graph", "conflict-graph-all"}, optional
        Point location: a walk (section 5.5) or the conflict graph (section 5.4; "-all" keeps
        every conflict, so that ``count=True`` measures Theorem 5.4's conflicts created).
    seed : int, optional
        Seed of the order's and the walk's random choices. Results are reproducible.
    storage : {"array", "hash"}, optional
        Array storage, or the book's face hash table (not with ``incremental``).
    count : bool, optional
        Run the counting engine and put its counters in ``stats`` (within about 1% of the plain
        engine's instructions).
    threads : int, optional
        0 (default): the sequential engine. N >= 1: the parallel construction on N threads (walk
        and array storage only, no ``count``). The simplices are the same as the sequential
        engine's, in a canonical order that is the same for every N.
    progress : callable, optional
        ``progress(done, total)``, called now and then during construction.

    Attributes
    ----------
    points : ndarray of double, shape (npoints, 3)
        Coordinates of input points (read-only).
    simplices : ndarray of int32, shape (nsimplex, 4)
        Indices of the points forming the tetrahedra, each with positive volume by the
        right-hand rule (VTK's and TetGen's convention).
    neighbors : ndarray of int32, shape (nsimplex, 4)
        ``neighbors[j, i]`` is the simplex opposite vertex ``simplices[j, i]``; -1 on the hull.
    equations : ndarray of double, shape (nsimplex, 5)
        ``[normal, offset]`` of the hyperplane of each simplex lifted to the paraboloid (unit
        normal, pointing down).
    paraboloid_scale, paraboloid_shift : float
        The lifting: ``z = paraboloid_scale * |x|^2 + paraboloid_shift`` (Qhull's 'Qbb' rule:
        the lifted coordinate spans [0, max |coordinate|]).
    transform : ndarray of double, shape (nsimplex, 4, 3)
        Affine transforms from ``x`` to barycentric coordinates ``c``: ``c[:3] = T[:3] @ (x -
        T[3])``, ``c[3] = 1 - sum(c[:3])``, with ``T = transform[j]``.
    vertex_to_simplex : ndarray of int32, shape (npoints,)
        A simplex having each point as a vertex; -1 for points that are not vertices.
    convex_hull : ndarray of int32, shape (nfaces, 3)
        Hull triangles, counter-clockwise seen from outside.
    coplanar : ndarray of int32, shape (ncoplanar, 3)
        Points that are not vertices because they repeat another one exactly, as
        ``[point, a simplex of the vertex it repeats, that vertex]``. (In scipy, points Qhull left
        out for precision; exact arithmetic leaves out only exact repeats.)
    vertex_neighbor_vertices : tuple of two ndarrays of int32: (indptr, indices)
        The neighbours of vertex k are ``indices[indptr[k]:indptr[k+1]]``, increasing.
    furthest_site : bool
        False.
    good : ndarray of int32, shape (nsimplex,)
        Ones: scipy's marks of Qhull's option QG, which cavity does not have.
    min_bound, max_bound : ndarray of double, shape (3,)
        Bounds of the input points.
    npoints, nsimplex, ndim : int
        Number of points, of tetrahedra, and 3.
    weights : ndarray of double, shape (npoints,), or None
    duplicates : ndarray of int32, shape (k, 2)
        ``[point, first row with the same coordinates (and weight)]``.
    redundant : ndarray of int32, shape (r,)
        Weighted points that are not vertices (submerged), increasing.
    stats : dict
        Timings (wall and CPU seconds), the engine that ran, and with ``count=True`` its
        counters (tetrahedra created and deleted, walk steps, predicate stages, ...).

    Raises
    ------
    ValueError
        For a wrong shape (2-D points included), a NaN or infinity (naming the row), fewer than
        4 distinct points, all points coplanar, ``furthest_site=True`` or ``qhull_options``.

    Notes
    -----
    ``find_simplex`` is exact: a point is in a simplex when it is in its closure, decided by exact
    orientation tests, and a point on a face shared by several simplices gets the lowest-numbered
    one. scipy's ``tol`` and ``bruteforce`` are accepted and change nothing.

    The GIL is released during construction, point location and validation, so threads
    triangulating different point sets run in parallel.

    Examples
    --------
    >>> import numpy as np, cavity
    >>> points = np.random.default_rng(0).random((1000, 3))
    >>> tri = cavity.Delaunay(points)
    >>> simplex = tri.find_simplex([[0.5, 0.5, 0.5]])
    >>> T = tri.transform[simplex[0]]
    >>> c = T[:3] @ (np.array([0.5, 0.5, 0.5]) - T[3])
    >>> bool(np.all(np.append(c, 1 - c.sum()) >= -1e-12))
    True
    """

    def __init__(self, points: Any, furthest_site: bool = False, incremental: bool = False,
                 qhull_options: Optional[str] = None, *, weights: Any = None,
                 order: str = "brio", locate: str = "walk", seed: int = 0,
                 storage: str = "array", count: bool = False, threads: int = 0,
                 progress: Optional[Callable[[int, int], Any]] = None) -> None:
        _refuse_unsupported(points, furthest_site, qhull_options)
        self._options: dict[str, Any] = dict(order=order, locate=locate, seed=seed,
                                             storage=storage, count=count, threads=threads)
        self._engine = _cavity.Triangulation(points, weights, order, locate, seed, storage, count,
                                             threads, incremental, progress)
        self._batches = [len(self._engine.points)]
        self._derived: dict[str, Any] = {}

    # Arrays of the engine ----------------------------------------------------------------------

    @property
    def points(self) -> np.ndarray:
        return self._engine.points

    @property
    def weights(self) -> Optional[np.ndarray]:
        return self._engine.weights

    @property
    def simplices(self) -> np.ndarray:
        return self._engine.simplices

    @property
    def neighbors(self) -> np.ndarray:
        return self._engine.neighbors

    @property
    def convex_hull(self) -> np.ndarray:
        return self._engine.convex_hull

    @property
    def vertex_to_simplex(self) -> np.ndarray:
        return self._engine.vertex_to_simplex

    @property
    def duplicates(self) -> np.ndarray:
        return self._engine.duplicates

    @property
    def redundant(self) -> np.ndarray:
        return self._engine.redundant

    @property
    def stats(self) -> dict:
        return self._engine.stats

    @property
    def npoints(self) -> int:
        return int(self.points.shape[0])

    @property
    def nsimplex(self) -> int:
        return int(self.simplices.shape[0])

    @property
    def ndim(self) -> int:
        return 3

    @property
    def furthest_site(self) -> bool:
        return False

    @property
    def good(self) -> np.ndarray:
        """(nsimplex,) int32, scipy's: which simplices Qhull's option QG marks good; without the
        option, which cavity never runs, all of them (ones)."""
        return self._cached("good", lambda: np.ones(self.nsimplex, dtype=np.int32))

    @property
    def vertices(self) -> np.ndarray:
        """Deprecated alias of ``simplices``, as in scipy."""
        warnings.warn("Delaunay attribute 'vertices' is deprecated in favour of 'simplices'",
                      DeprecationWarning, stacklevel=2)
        return self.simplices

    @property
    def min_bound(self) -> np.ndarray:
        return self.points.min(axis=0)

    @property
    def max_bound(self) -> np.ndarray:
        return self.points.max(axis=0)

    # Derived arrays, computed once --------------------------------------------------------------

    def _cached(self, name: str, make: Callable[[], Any]) -> Any:
        if name not in self._derived:
            self._derived[name] = make()
        return self._derived[name]

    @property
    def coplanar(self) -> np.ndarray:
        def make() -> np.ndarray:
            d = self.duplicates
            out = np.empty((len(d), 3), dtype=np.int32)
            out[:, 0] = d[:, 0]
            out[:, 1] = self.vertex_to_simplex[d[:, 1]]
            out[:, 2] = d[:, 1]
            return out
        return self._cached("coplanar", make)

    @property
    def vertex_neighbor_vertices(self) -> tuple:
        return self._cached("vertex_neighbor_vertices", self._engine.vertex_neighbor_vertices)

    @property
    def transform(self) -> np.ndarray:
        return self._cached("transform", self._engine.transform)

    @property
    def paraboloid_scale(self) -> float:
        return self._lifting()[0]

    @property
    def paraboloid_shift(self) -> float:
        return self._lifting()[1]

    def _lifting(self) -> tuple:
        def make() -> tuple:
            squares = (self.points ** 2).sum(axis=1)
            low, high = float(squares.min()), float(squares.max())
            reach = float(np.abs(self.points).max())
            if high <= low or reach == 0.0:
                return 1.0, 0.0  # all points on one sphere about the origin: nothing to scale
            scale = reach / (high - low)
            return scale, -low * scale
        return self._cached("lifting", make)

    @property
    def equations(self) -> np.ndarray:
        return self._cached("equations", lambda: self._engine.equations(*self._lifting()))

    # Methods ----------------------------------------------------------------------------------

    def lift_points(self, x: Any) -> np.ndarray:
        """Lift points to the paraboloid: shape (..., 3) -> (..., 4)."""
        x = np.asarray(x, dtype=np.float64)
        z = np.empty(x.shape[:-1] + (4,))
        z[..., :3] = x
        z[..., 3] = (x ** 2).sum(axis=-1) * self.paraboloid_scale + self.paraboloid_shift
        return z

    def plane_distance(self, xi: Any) -> np.ndarray:
        """Distances of the lifted xi, shape (..., 3), to the lifted hyperplane of every simplex:
        shape (..., nsimplex); positive where xi is strictly inside the circumsphere."""
        xi = self._queries(xi)
        flat = self.lift_points(xi.reshape(-1, 3))
        out = flat @ self.equations[:, :4].T + self.equations[:, 4]
        return out.reshape(xi.shape[:-1] + (self.nsimplex,))

    def find_simplex(self, xi: Any, bruteforce: bool = False, tol: Optional[float] = None
                     ) -> np.ndarray:
        """The simplex holding each point of xi, shape (..., 3) -> int32 (...,); -1 outside.

        Exact: a point is in a simplex when it is in its closure, decided by exact orientation
        tests; on a face shared by several simplices the lowest-numbered one is returned.
        ``bruteforce`` and ``tol`` (scipy's, for its inexact test) change nothing. Points with a
        NaN coordinate get -1."""
        del bruteforce, tol  # the exact answer needs neither
        xi = self._queries(xi)
        found = self._engine.find_simplex(xi.reshape(-1, 3))
        return found.reshape(xi.shape[:-1])

    def add_points(self, points: Any, restart: bool = False, *, weights: Any = None) -> None:
        """Insert more points (shape (k, 3)) into the live triangulation (incremental=True).

        The result is the triangulation of all points so far, the same as one construction from
        the concatenated array. With ``restart=True`` everything is triangulated again from
        scratch instead."""
        if not self._engine.incremental:
            raise RuntimeError("incremental mode not enabled or already closed")
        if restart:
            if (weights is None) != (self.weights is None):
                raise ValueError("this triangulation is weighted: add_points needs weights"
                                 if self.weights is not None else
                                 "this triangulation is unweighted: add_points takes no weights")
            all_points = np.concatenate([self.points, np.asarray(points, dtype=np.float64)])
            all_weights = None
            if weights is not None:
                all_weights = np.concatenate([self.weights, np.asarray(weights, np.float64)])
            self._engine = _cavity.Triangulation(all_points, all_weights, progress=None,
                                                 incremental=True, **self._options)
            self._batches = [len(all_points)]
        else:
            before = self.npoints
            self._engine.add_points(points, weights)
            self._batches.append(self.npoints - before)
        self._derived = {}

    def close(self) -> None:
        """Finish incremental mode: the live triangulation is freed, the arrays stay."""
        self._engine.close()

    def check(self) -> bool:
        """Validate exactly (every tetrahedron positive, every facet locally Delaunay under the
        perturbation, every point accounted for): True, or raise cavity.ValidationError."""
        return self._engine.check()

    # Interoperability --------------------------------------------------------------------------

    def to_meshio(self) -> Any:
        """The tetrahedra as a ``meshio.Mesh`` (cells "tetra", positive volume)."""
        try:
            import meshio  # type: ignore[import]
        except ImportError as e:
            raise ImportError("to_meshio needs meshio (pip install meshio; Debian: "
                              "python3-meshio)") from e
        return meshio.Mesh(np.asarray(self.points), [("tetra", np.asarray(self.simplices))])

    def vtk_cells(self) -> tuple:
        """(cells, celltypes, points) as ``pyvista.UnstructuredGrid(cells, celltypes, points)``
        and VTK take them: cells = [4, a, b, c, d, 4, ...] (int64), celltypes all VTK_TETRA
        (uint8), each tetrahedron with positive volume."""
        cells = np.empty((self.nsimplex, 5), dtype=np.int64)
        cells[:, 0] = 4
        cells[:, 1:] = self.simplices
        celltypes = np.full(self.nsimplex, VTK_TETRA, dtype=np.uint8)
        return cells.ravel(), celltypes, np.asarray(self.points)

    def to_pyvista(self) -> Any:
        """The tetrahedra as a ``pyvista.UnstructuredGrid``."""
        try:
            import pyvista  # type: ignore[import]
        except ImportError as e:
            raise ImportError("to_pyvista needs pyvista (pip install pyvista); vtk_cells() "
                              "gives the arrays without it") from e
        return pyvista.UnstructuredGrid(*self.vtk_cells())

    # Pickling: the construction is replayed, batch by batch, which is deterministic -----------

    def __getstate__(self) -> dict:
        return dict(points=np.asarray(self.points), weights=self.weights,
                    options=self._options, batches=list(self._batches),
                    incremental=self._engine.incremental)

    def __setstate__(self, state: dict) -> None:
        points, weights, batches = state["points"], state["weights"], state["batches"]
        first = batches[0]
        self._options = state["options"]
        self._engine = _cavity.Triangulation(
            points[:first], None if weights is None else weights[:first], progress=None,
            incremental=state["incremental"] or len(batches) > 1, **self._options)
        self._batches = [first]
        self._derived = {}
        end = first
        for size in batches[1:]:
            self._engine.add_points(points[end:end + size],
                                    None if weights is None else weights[end:end + size])
            self._batches.append(size)
            end += size
        if not state["incremental"]:
            self._engine.close()

    def __repr__(self) -> str:
        return f"<cavity.Delaunay: {self.npoints} points, {self.nsimplex} tetrahedra>"

    def _queries(self, xi: Any) -> np.ndarray:
        xi = np.asarray(xi, dtype=np.float64)
        if xi.ndim == 0 or xi.shape[-1] != 3:
            raise ValueError(f"points must have shape (..., 3), got {xi.shape}")
        return xi
