// cavity._cavity.Triangulation: the engine behind cavity.Delaunay (python/cavity/_delaunay.py),
// over cavity's live triangulation. Everything scipy's interface needs that is not plain numpy
// arithmetic on the arrays is here: construction, exact point location, vertex neighbours,
// incremental insertion and the exact validator, each without the GIL.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <limits>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "adopt.h"
#include "bindings.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/live/simplex_location.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "input_arrays.h"
#include "simplex_geometry.h"
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

/// Everything one construction produces, computed without the GIL.
struct Built {
    std::optional<core::DelaunayTriangulation> live;  ///< kept for incremental insertion
    core::Triangulation triangulation;                ///< duplicates, redundant, counters
    core::Adjacency adjacency;
    std::pair<double, double> order_s;  ///< {wall, CPU}
    std::pair<double, double> triangulate_s;
    std::pair<double, double> adjacency_s;
};

/// The scalar results of the live triangulation, as triangulate() returns them, beside its
/// adjacency (which holds the hull).
void read_live(const core::DelaunayTriangulation& dt,
               const core::Adjacency& adjacency,
               core::Triangulation& t) {
    t.duplicates = dt.duplicates();
    t.redundant = dt.redundant();
    t.counters = dt.counters();
    t.hull_triangles = adjacency.hull.size();
    t.storage_bytes = dt.storage().bytes();
}

Built build(const core::PointSet& input,
            const core::OrderOptions& order_options,
            const core::TriangulateOptions& options,
            bool incremental) {
    Built b;
    Stopwatch clock;
    const core::InsertionOrder order = core::make_insertion_order(input.points, order_options);
    b.order_s = clock.elapsed();
    clock = Stopwatch();
    if (options.storage == core::StorageKind::kArray) {
        // The live triangulation's own adjacency, read off in linear time: no facet matching.
        core::DelaunayTriangulation dt(input, order.sequence, options);
        b.triangulate_s = clock.elapsed();
        clock = Stopwatch();
        b.adjacency = dt.adjacency();
        read_live(dt, b.adjacency, b.triangulation);
        if (incremental) {
            b.live.emplace(std::move(dt));
        }
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

class Triangulation {
public:
    Triangulation(const py::handle& points,
                  const py::handle& weights,
                  const std::string& order,
                  const std::string& locate,
                  std::uint64_t seed,
                  const std::string& storage,
                  bool count,
                  unsigned threads,
                  bool incremental,
                  const py::object& progress)
        : input_(to_point_set(points, weights)) {
        order_options_.kind = core::parse_order_kind(order);
        order_options_.seed = seed;
        order_options_.threads = std::max(1u, threads);
        core::TriangulateOptions options;
        options.locate = core::parse_locate_kind(locate);
        options.storage = core::parse_storage_kind(storage);
        options.count = count;
        options.seed = seed;
        options.threads = threads;
        if (threads > 127) {
            throw py::value_error("threads must be between 0 and 127, not " +
                                  std::to_string(threads));
        }
        if (incremental && options.storage != core::StorageKind::kArray) {
            throw py::value_error(
                "incremental=True needs storage=\"array\": the face hash table is not kept live");
        }
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
            b = build(input_, order_options_, options, incremental);
        }
        live_ = std::move(b.live);
        // The plain engine counts nothing: no zeros that would read as measurements.
        stats_ = count ? counters_dict(b.triangulation.counters) : py::dict();
        stats_["engine"] = count ? "counting" : threads > 0 ? "parallel" : "plain";
        stats_["threads"] = threads;
        stats_["order"] = order;
        stats_["locate"] = locate;
        stats_["storage"] = storage;
        stats_["seed"] = seed;
        py::dict timings;
        timings["order_s"] = b.order_s.first;
        timings["triangulate_s"] = b.triangulate_s.first;
        timings["adjacency_s"] = b.adjacency_s.first;
        timings["order_cpu_s"] = b.order_s.second;
        timings["triangulate_cpu_s"] = b.triangulate_s.second;
        timings["adjacency_cpu_s"] = b.adjacency_s.second;
        stats_["timings"] = timings;
        publish(std::move(b.adjacency), std::move(b.triangulation), 0);
    }

    /// Inserts the rows of `points` (and `weights`) into the live triangulation along the
    /// construction's insertion order; their perturbation keys are their rows in the concatenated
    /// input, so the result is the triangulation of all points so far, whatever the batches.
    void add_points(const py::handle& points, const py::handle& weights) {
        const core::PointSet batch = to_point_set(points, weights);
        core::Adjacency adjacency;
        core::Triangulation t;
        const char* refusal = nullptr;
        std::uint64_t edit = 0;
        {
            py::gil_scoped_release nogil;
            const std::lock_guard<std::mutex> lock(mutex_);
            if (!live_) {
                refusal =
                    "add_points needs a triangulation made with incremental=True and not closed";
            } else if (batch.weighted() != input_.weighted()) {
                refusal = input_.weighted()
                              ? "this triangulation is weighted: add_points needs weights"
                              : "this triangulation is unweighted: add_points takes no weights";
            } else if (input_.size() + batch.size() >
                       static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
                refusal = "more than 2^31-1 points cannot be numbered by int32 indices";
            } else {
                const core::InsertionOrder order =
                    core::make_insertion_order(batch.points, order_options_);
                live_->insert(batch, order.sequence);
                adjacency = live_->adjacency();
                read_live(*live_, adjacency, t);
                input_.points.insert(input_.points.end(), batch.points.begin(), batch.points.end());
                input_.weights.insert(
                    input_.weights.end(), batch.weights.begin(), batch.weights.end());
                edit = ++edits_;
            }
        }
        if (refusal != nullptr) {
            throw py::value_error(refusal);
        }
        stats_["points_added"] = stats_["points_added"].cast<std::size_t>() + batch.size();
        publish(std::move(adjacency), std::move(t), edit);
    }

    /// Ends incremental mode: the live triangulation is freed; the arrays stay.
    void close() {
        const std::lock_guard<std::mutex> lock(mutex_);
        live_.reset();
    }

    bool incremental() const {
        const std::lock_guard<std::mutex> lock(mutex_);
        return live_.has_value();
    }

    /// For each row of the (k, 3) `xi`, the lowest-numbered simplex whose closure holds it, or
    /// -1 (outside the hull, or a NaN coordinate). The queries are walked to along a Hilbert
    /// curve, each walk starting where the last one ended, so that the walks stay short whatever
    /// the order the queries come in (the answers do not depend on it).
    py::array_t<std::int32_t> find_simplex(const py::handle& xi) const {
        const DoubleArray q(py::module_::import("numpy").attr("asarray")(xi, "float64"));
        if (q.ndim() != 2 || q.shape(1) != 3) {
            throw py::value_error("find_simplex needs points of shape (k, 3)");
        }
        const auto k = static_cast<std::size_t>(q.shape(0));
        std::vector<std::int32_t> found(k, -1);
        const Arrays a = arrays();
        {
            py::gil_scoped_release nogil;
            const std::lock_guard<std::mutex> lock(mutex_);
            std::vector<core::Point3> finite;
            std::vector<std::size_t> row;
            const double* x = q.data();
            for (std::size_t i = 0; i < k; ++i) {
                const core::Point3 p{x[3 * i], x[3 * i + 1], x[3 * i + 2]};
                if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
                    finite.push_back(p);
                    row.push_back(i);
                }
            }
            core::OrderOptions curve;
            curve.kind = core::OrderKind::kHilbert;
            const core::InsertionOrder order = core::make_insertion_order(finite, curve);
            const core::SimplexLocator locator(input_.points, a.simplices(), a.neighbors());
            std::int32_t start = 0;
            for (std::uint32_t j : order.sequence) {
                const std::int32_t t = locator.find(finite[j], start);
                found[row[j]] = t;
                start = t >= 0 ? t : start;
            }
        }
        return adopt(std::move(found), {static_cast<py::ssize_t>(k)});
    }

    /// scipy's transform, (m, 4, 3) float64.
    py::array_t<double> transform() const {
        std::vector<double> values;
        const Arrays a = arrays();
        {
            py::gil_scoped_release nogil;
            const std::lock_guard<std::mutex> lock(mutex_);
            values = barycentric_transforms(input_.points, a.simplices());
        }
        return adopt<double>(std::move(values), {a.simplex.shape(0), 4, 3});
    }

    /// scipy's equations for the lifting z = scale |x|^2 + shift, (m, 5) float64.
    py::array_t<double> equations(double scale, double shift) const {
        std::vector<double> values;
        const Arrays a = arrays();
        {
            py::gil_scoped_release nogil;
            const std::lock_guard<std::mutex> lock(mutex_);
            values = lifted_hyperplanes(input_.points, a.simplices(), scale, shift);
        }
        return adopt<double>(std::move(values), {a.simplex.shape(0), 5});
    }

    /// scipy's (indptr, indices).
    py::tuple vertex_neighbor_vertices() const {
        core::VertexNeighbors vn;
        const Arrays a = arrays();
        {
            py::gil_scoped_release nogil;
            const std::lock_guard<std::mutex> lock(mutex_);
            vn = core::vertex_neighbors(a.simplices(), input_.size());
        }
        const auto n = static_cast<py::ssize_t>(vn.indptr.size());
        const auto e = static_cast<py::ssize_t>(vn.indices.size());
        return py::make_tuple(adopt(std::move(vn.indptr), {n}), adopt(std::move(vn.indices), {e}));
    }

    /// Runs the exact validator (core::validate) on this triangulation.
    bool check() const {
        core::ValidationReport report;
        const Arrays a = arrays();
        {
            py::gil_scoped_release nogil;
            const std::lock_guard<std::mutex> lock(mutex_);
            report = core::validate(input_, a.simplices());
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
    /// References to the published arrays, taken with the GIL: work without the GIL reads these,
    /// which stay alive while another thread's add_points publishes new ones.
    struct Arrays {
        py::array_t<std::int32_t> simplex;
        py::array_t<std::int32_t> neighbor;

        std::span<const core::Tet> simplices() const {
            return {reinterpret_cast<const core::Tet*>(simplex.data()),
                    static_cast<std::size_t>(simplex.shape(0))};
        }

        std::span<const std::int32_t> neighbors() const {
            return {neighbor.data(), static_cast<std::size_t>(neighbor.size())};
        }
    };

    Arrays arrays() const { return {simplices_, neighbors_}; }

    /// Called with the GIL, after construction (edit 0) or the insertion that made edit `edit`.
    /// Threads take the GIL back in any order: arrays older than the ones shown are dropped.
    void publish(core::Adjacency&& adjacency, core::Triangulation&& t, std::uint64_t edit) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (edit < shown_) {
            return;
        }
        shown_ = edit;
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
        const auto m = static_cast<py::ssize_t>(adjacency.simplices.size());
        const auto hull = static_cast<py::ssize_t>(adjacency.hull.size());
        const auto dup = static_cast<py::ssize_t>(t.duplicates.size());
        const auto red = static_cast<py::ssize_t>(t.redundant.size());
        stats_["points"] = input_.size();
        stats_["tets"] = adjacency.simplices.size();
        stats_["hull_triangles"] = t.hull_triangles;
        stats_["storage_bytes"] = t.storage_bytes;
        if (!stats_.contains("points_added")) {
            stats_["points_added"] = 0;
        }
        simplices_ = adopt(std::move(adjacency.simplices), {m, 4});
        neighbors_ = adopt(std::move(adjacency.neighbors), {m, 4});
        convex_hull_ = adopt(std::move(adjacency.hull), {hull, 3});
        vertex_to_simplex_ = adopt(std::move(adjacency.vertex_to_simplex), {n});
        duplicates_ = adopt(std::move(t.duplicates), {dup, 2});
        redundant_ = adopt(std::move(t.redundant), {red});
    }

    /// Guards input_ and live_ against two Python threads using one object, taken only without
    /// the GIL or by a holder of the GIL that waits for nothing else (no deadlock).
    mutable std::mutex mutex_;
    std::uint64_t edits_ = 0;  ///< insertions made
    std::uint64_t shown_ = 0;  ///< the insertion the published arrays show
    core::PointSet input_;
    core::OrderOptions order_options_;  ///< also orders the batches of add_points
    std::optional<core::DelaunayTriangulation> live_;
};

}  // namespace

void bind_delaunay(py::module_& m) {
    py::class_<Triangulation>(m, "Triangulation", R"doc(
The engine behind cavity.Delaunay (use that class): one exact Delaunay or regular triangulation,
its arrays, and the operations that need the engine.
)doc")
        .def(py::init<const py::handle&,
                      const py::handle&,
                      const std::string&,
                      const std::string&,
                      std::uint64_t,
                      const std::string&,
                      bool,
                      unsigned,
                      bool,
                      const py::object&>(),
             py::arg("points"),
             py::arg("weights"),
             py::arg("order"),
             py::arg("locate"),
             py::arg("seed"),
             py::arg("storage"),
             py::arg("count"),
             py::arg("threads"),
             py::arg("incremental"),
             py::arg("progress"))
        .def_readonly("points", &Triangulation::points_)
        .def_readonly("weights", &Triangulation::weights_)
        .def_readonly("simplices", &Triangulation::simplices_)
        .def_readonly("neighbors", &Triangulation::neighbors_)
        .def_readonly("convex_hull", &Triangulation::convex_hull_)
        .def_readonly("vertex_to_simplex", &Triangulation::vertex_to_simplex_)
        .def_readonly("duplicates", &Triangulation::duplicates_)
        .def_readonly("redundant", &Triangulation::redundant_)
        .def_readonly("stats", &Triangulation::stats_)
        .def_property_readonly("incremental", &Triangulation::incremental)
        .def("add_points", &Triangulation::add_points, py::arg("points"), py::arg("weights"))
        .def("close", &Triangulation::close)
        .def("find_simplex", &Triangulation::find_simplex, py::arg("xi"))
        .def("vertex_neighbor_vertices", &Triangulation::vertex_neighbor_vertices)
        .def("transform", &Triangulation::transform)
        .def("equations", &Triangulation::equations, py::arg("scale"), py::arg("shift"))
        .def("check", &Triangulation::check);
}

}  // namespace cavity::python
