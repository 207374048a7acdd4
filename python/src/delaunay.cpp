// cavity.Delaunay: scipy.spatial.Delaunay's shape over cavity's live triangulation.

#include <array>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <string>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "input_arrays.h"
#include "stats_dict.h"

namespace cavity::python {

namespace {

using Clock = std::chrono::steady_clock;

/// Wall-clock and this thread's CPU time: on a shared machine the CPU time is the steadier one.
struct Stopwatch {
    Clock::time_point wall = Clock::now();
    double cpu = thread_cpu_seconds();

    static double thread_cpu_seconds() {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }

    /// {wall seconds, CPU seconds} since construction.
    std::pair<double, double> elapsed() const {
        return {std::chrono::duration<double>(Clock::now() - wall).count(),
                thread_cpu_seconds() - cpu};
    }
};

/// A read-only int32 numpy array that takes ownership of `values` without copying them. T is
/// std::int32_t, std::uint32_t (ids < 2^31, so the bits are the same) or an array of them.
template <class T>
py::array_t<std::int32_t> adopt(std::vector<T>&& values, const std::vector<py::ssize_t>& shape) {
    static_assert(sizeof(T) % sizeof(std::int32_t) == 0);
    auto* heap = new std::vector<T>(std::move(values));
    py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    py::array_t<std::int32_t> array(
        shape, reinterpret_cast<const std::int32_t*>(heap->data()), owner);
    array.attr("setflags")(py::arg("write") = false);
    return array;
}

/// Everything one triangulation produces, computed without the GIL.
struct Built {
    core::Triangulation triangulation;
    core::Adjacency adjacency;
    std::pair<double, double> order_s;  ///< {wall, CPU}
    std::pair<double, double> triangulate_s;
    std::pair<double, double> adjacency_s;
};

Built build(const core::PointSet& input,
            const core::OrderOptions& order_options,
            const core::TriangulateOptions& options) {
    Built b;
    Stopwatch clock;
    const core::InsertionOrder order = core::make_insertion_order(input.points, order_options);
    b.order_s = clock.elapsed();
    clock = Stopwatch();
    if (options.storage == core::StorageKind::kArray) {
        // The live triangulation's own adjacency, read off in linear time: no facet matching.
        const core::DelaunayTriangulation dt(input, order.sequence, options);
        b.triangulate_s = clock.elapsed();
        clock = Stopwatch();
        b.adjacency = dt.adjacency();
        b.triangulation.duplicates = dt.duplicates();
        b.triangulation.redundant = dt.redundant();
        b.triangulation.counters = dt.counters();
        b.triangulation.hull_triangles = b.adjacency.hull.size();
        b.triangulation.storage_bytes = dt.storage().bytes();
        b.adjacency_s = clock.elapsed();
        return b;
    }
    // The face hash table is not kept live: its tetrahedra are matched facet by facet.
    b.triangulation = core::triangulate(input, order.sequence, options);
    b.triangulate_s = clock.elapsed();
    clock = Stopwatch();
    // Rank of each point along the insertion order (a space-filling curve, rounds aside).
    std::vector<std::uint32_t> rank(input.size());
    for (std::size_t r = 0; r < order.sequence.size(); ++r) {
        rank[order.sequence[r]] = static_cast<std::uint32_t>(r);
    }
    b.adjacency = core::build_adjacency(b.triangulation.tets, rank);
    b.triangulation.tets = {};  // adjacency.simplices holds them, renumbered
    b.adjacency_s = clock.elapsed();
    return b;
}

class Delaunay {
public:
    Delaunay(const py::handle& points,
             const py::handle& weights,
             const std::string& order,
             const std::string& locate,
             std::uint64_t seed,
             const std::string& storage,
             const py::object& progress)
        : input_(to_point_set(points, weights)) {
        core::OrderOptions order_options;
        order_options.kind = core::parse_order_kind(order);
        order_options.seed = seed;
        core::TriangulateOptions options;
        options.locate = core::parse_locate_kind(locate);
        options.storage = core::parse_storage_kind(storage);
        options.count = true;
        options.seed = seed;
        if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
            throw py::type_error("progress must be callable as progress(done, total), or None");
        }
        // Called from the engine without the GIL: take it, let Ctrl-C interrupt, report.
        options.progress = [&progress](std::size_t done, std::size_t total) {
            py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() != 0) {
                throw py::error_already_set();
            }
            if (!progress.is_none()) {
                progress(done, total);
            }
        };

        Built b;
        {
            py::gil_scoped_release nogil;
            b = build(input_, order_options, options);
        }
        publish(std::move(b), seed, order, locate, storage);
    }

    /// Runs the exact validator (core::validate) on this triangulation.
    bool check() const {
        const auto* data = reinterpret_cast<const core::Tet*>(simplices_.data());
        const std::span<const core::Tet> simplices(data,
                                                   static_cast<std::size_t>(simplices_.shape(0)));
        core::ValidationReport report;
        {
            py::gil_scoped_release nogil;
            report = core::validate(input_, simplices);
        }
        if (report.ok()) {
            return true;
        }
        std::string message = std::to_string(report.problem_count) + " problem(s):";
        for (const std::string& p : report.problems) {
            message += "\n  " + p;
        }
        throw ValidationFailure(message);
    }

    py::array points_;
    py::object weights_;
    py::array_t<std::int32_t> simplices_;
    py::array_t<std::int32_t> neighbors_;
    py::array_t<std::int32_t> convex_hull_;
    py::array_t<std::int32_t> vertex_to_simplex_;
    py::array_t<std::int32_t> duplicates_;
    py::array_t<std::int32_t> redundant_;
    py::dict stats_;

private:
    void publish(Built&& b,
                 std::uint64_t seed,
                 const std::string& order,
                 const std::string& locate,
                 const std::string& storage) {
        const auto n = static_cast<py::ssize_t>(input_.size());
        py::array_t<double> points({n, py::ssize_t{3}});
        auto* p = points.mutable_data();
        for (std::size_t i = 0; i < input_.size(); ++i) {
            p[3 * i] = input_.points[i].x;
            p[3 * i + 1] = input_.points[i].y;
            p[3 * i + 2] = input_.points[i].z;
        }
        points.attr("setflags")(py::arg("write") = false);
        points_ = points;
        if (input_.weighted()) {
            py::array_t<double> w(n, input_.weights.data());
            w.attr("setflags")(py::arg("write") = false);
            weights_ = w;
        } else {
            weights_ = py::none();
        }
        core::Triangulation& t = b.triangulation;
        const auto m = static_cast<py::ssize_t>(b.adjacency.simplices.size());
        const auto hull = static_cast<py::ssize_t>(b.adjacency.hull.size());
        const auto dup = static_cast<py::ssize_t>(t.duplicates.size());
        const auto red = static_cast<py::ssize_t>(t.redundant.size());

        py::dict stats = counters_dict(t.counters);
        stats["points"] = input_.size();
        stats["tets"] = b.adjacency.simplices.size();
        stats["hull_triangles"] = t.hull_triangles;
        stats["storage_bytes"] = t.storage_bytes;
        stats["order"] = order;
        stats["locate"] = locate;
        stats["storage"] = storage;
        stats["seed"] = seed;
        py::dict timings;
        timings["order_s"] = b.order_s.first;
        timings["triangulate_s"] = b.triangulate_s.first;
        timings["adjacency_s"] = b.adjacency_s.first;
        timings["order_cpu_s"] = b.order_s.second;
        timings["triangulate_cpu_s"] = b.triangulate_s.second;
        timings["adjacency_cpu_s"] = b.adjacency_s.second;
        stats["timings"] = timings;
        stats_ = stats;

        simplices_ = adopt(std::move(b.adjacency.simplices), {m, 4});
        neighbors_ = adopt(std::move(b.adjacency.neighbors), {m, 4});
        convex_hull_ = adopt(std::move(b.adjacency.hull), {hull, 3});
        vertex_to_simplex_ = adopt(std::move(b.adjacency.vertex_to_simplex), {n});
        duplicates_ = adopt(std::move(t.duplicates), {dup, 2});
        redundant_ = adopt(std::move(t.redundant), {red});
    }

    core::PointSet input_;
};

}  // namespace

void bind_delaunay(py::module_& m) {
    py::class_<Delaunay>(m, "Delaunay", R"doc(
Exact 3D Delaunay (or weighted Delaunay / regular) triangulation.

Delaunay(points, weights=None, order="brio", locate="walk", seed=0, storage="array", progress=None)

points   : (n, 3) array of finite numbers (converted to float64).
weights  : None, or (n,) finite weights: the regular triangulation of the weighted points.
order    : insertion order: "brio" (default), "hilbert", "zorder", "random", "input".
locate   : point location: "walk" (default), "conflict-graph" (one cell per point, the book's
           §5.4) or "conflict-graph-all" (every conflict kept; stats then hold Theorem 5.4's
           conflicts_created).
seed     : seed of the order's and the walk's random choices (results are reproducible).
storage  : "array" (default) or "hash" (the book's face hash table).
progress : None, or a callable progress(done, total) called now and then (with the GIL).

The result is the Delaunay triangulation under a symbolic perturbation keyed on the row index, so
it exists and is unique for every input with an affinely 3D set of distinct points: degenerate
inputs (grids, cospherical points) get a valid triangulation with no flat tetrahedron.
Exact repeats are not vertices (see `duplicates`); weighted points whose lifted point is above the
lower hull are not vertices (see `redundant`).

Raises ValueError (naming the row) for a wrong shape, NaN or infinity, fewer than 4 distinct points
or all points coplanar or collinear (naming the affine dimension). The GIL is released while
triangulating.
)doc")
        .def(py::init<const py::handle&,
                      const py::handle&,
                      const std::string&,
                      const std::string&,
                      std::uint64_t,
                      const std::string&,
                      const py::object&>(),
             py::arg("points"),
             py::arg("weights") = py::none(),
             py::arg("order") = "brio",
             py::arg("locate") = "walk",
             py::arg("seed") = 0,
             py::arg("storage") = "array",
             py::arg("progress") = py::none())
        .def_readonly("points", &Delaunay::points_, "(n, 3) float64: the input points")
        .def_readonly("weights", &Delaunay::weights_, "(n,) float64 weights, or None")
        .def_readonly("simplices",
                      &Delaunay::simplices_,
                      "(m, 4) int32: tetrahedra as row indices, each with positive volume by "
                      "the right-hand rule (TetGen's and VTK's convention; cavity.orient3d "
                      "of each row is -1)")
        .def_readonly("neighbors",
                      &Delaunay::neighbors_,
                      "(m, 4) int32: neighbors[t, i] is the tetrahedron opposite vertex i of t, "
                      "-1 on the convex hull")
        .def_readonly("convex_hull",
                      &Delaunay::convex_hull_,
                      "(h, 3) int32: hull triangles, counter-clockwise seen from outside")
        .def_readonly("vertex_to_simplex",
                      &Delaunay::vertex_to_simplex_,
                      "(n,) int32: a tetrahedron having the point as a vertex, -1 for points "
                      "that are not vertices (repeats, redundant)")
        .def_readonly(
            "duplicates",
            &Delaunay::duplicates_,
            "(k, 2) int32: rows [point, first row with the same coordinates (and weight)]")
        .def_readonly("redundant",
                      &Delaunay::redundant_,
                      "(r,) int32: weighted points that are not vertices, increasing")
        .def_readonly(
            "stats",
            &Delaunay::stats_,
            "dict: instrumentation counters, stage_calls and timings (wall and CPU seconds)")
        .def_property_readonly("nsimplex", [](const Delaunay& d) { return d.simplices_.shape(0); })
        .def_property_readonly("npoints", [](const Delaunay& d) { return d.points_.shape(0); })
        .def_property_readonly("ndim", [](const Delaunay&) { return 3; })
        .def(
            "check",
            &Delaunay::check,
            "Validates the triangulation exactly (cavity::core::validate): returns True, or raises "
            "cavity.ValidationError listing the problems.")
        .def("__repr__", [](const Delaunay& d) {
            return "<cavity.Delaunay: " + std::to_string(d.points_.shape(0)) + " points, " +
                   std::to_string(d.simplices_.shape(0)) + " tetrahedra>";
        });
}

}  // namespace cavity::python
