// cavity.cdt and cavity.CDT: the constrained Delaunay tetrahedralization of a PLC given as arrays,
// with the checks `cavity cdt` makes of a .poly file.

#include "cavity/core/cdt/cdt.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "adopt.h"
#include "bindings.h"
#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt_carve.h"
#include "cavity/core/cdt/cdt_regions.h"
#include "cavity/core/cdt/cdt_vertex_insertion.h"
#include "cavity/core/cdt/read_plc.h"
#include "cavity/core/input/plc.h"
#include "cavity/predicates/orient3d.h"
#include "input_arrays.h"

namespace cavity::python {

namespace {

using core::Point3;
using predicates::Sign;

std::string repr_text(const py::handle& h) {
    return py::repr(h).cast<std::string>();
}

/// Python's operator.index: Python and numpy integers are accepted, floats are not (a corner
/// 2.0 is most likely a bug upstream, and 2.5 is no vertex at all).
long long index_value(const py::handle& item, const std::string& where) {
    PyObject* number = PyNumber_Index(item.ptr());
    if (number == nullptr) {
        PyErr_Clear();
        throw py::value_error(where + ": corner " + repr_text(item) + " is not an integer");
    }
    int overflow = 0;
    const long long value = PyLong_AsLongLongAndOverflow(number, &overflow);
    Py_DECREF(number);
    // Beyond long long is out of range for any point count: clamp, keeping the sign for the
    // message.
    if (overflow != 0) {
        return overflow > 0 ? std::numeric_limits<long long>::max()
                            : std::numeric_limits<long long>::min();
    }
    return value;
}

/// An integer numpy array of int64 (checked to be integers: casting floats would truncate them).
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

IndexArray integer_array(const py::handle& h, const std::string& name) {
    const py::array raw = py::module_::import("numpy").attr("asarray")(h);
    const char kind = raw.dtype().kind();
    if (kind != 'i' && kind != 'u' && raw.size() != 0) {
        throw py::value_error(name + " must be integers, got dtype " +
                              py::str(raw.dtype()).cast<std::string>());
    }
    return IndexArray(raw);
}

/// Checks the corners of one loop, named by `name` in messages: at least 3, each a point index,
/// none repeated (a repeated corner makes the sides cross or overlap).
std::vector<std::uint32_t> checked_loop(const std::vector<long long>& corners,
                                        const std::string& name,
                                        std::size_t point_count) {
    if (corners.size() < 3) {
        throw py::value_error(name + " has " + std::to_string(corners.size()) +
                              " corner(s); a polygon needs at least 3 (give edges as segments)");
    }
    std::vector<std::uint32_t> loop;
    loop.reserve(corners.size());
    for (const long long c : corners) {
        if (c < 0) {
            throw py::value_error(name + ": corner " + std::to_string(c) + " is negative");
        }
        if (static_cast<unsigned long long>(c) >= point_count) {
            throw py::value_error(name + ": corner " + std::to_string(c) + " is out of range for " +
                                  std::to_string(point_count) + " points");
        }
        loop.push_back(static_cast<std::uint32_t>(c));
    }
    std::vector<std::uint32_t> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end()) {
        throw py::value_error(name + " lists corner " + std::to_string(*twice) + " twice");
    }
    return loop;
}

std::string polygon_name(std::size_t p) {
    return "polygon " + std::to_string(p);
}

/// A sequence in Python's sense (numpy arrays are), but not a string (a str is a sequence of str).
bool is_sequence(const py::handle& h) {
    return py::isinstance<py::sequence>(h) && !py::isinstance<py::str>(h) &&
           !py::isinstance<py::bytes>(h);
}

std::vector<std::uint32_t> loop_of(const py::handle& item,
                                   const std::string& name,
                                   std::size_t point_count) {
    if (!is_sequence(item)) {
        throw py::value_error(name + " must be a sequence of point indices, got " +
                              repr_text(item));
    }
    std::vector<long long> corners;
    for (const py::handle corner : item) {
        corners.push_back(index_value(corner, name));
    }
    return checked_loop(corners, name, point_count);
}

/// Points of an (h, 3) array (an empty sequence: none), e.g. a facet's hole points.
std::vector<Point3> point_rows(const py::handle& h, const std::string& name) {
    if (py::len(h) == 0) {
        return {};
    }
    const DoubleArray a = require_rows(h, name.c_str(), 3);
    std::vector<Point3> points(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t i = 0; i < points.size(); ++i) {
        points[i] = {a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]};
    }
    return points;
}

/// One item of a polygon sequence: a loop [i, j, k, ...], a facet [[loop], [loop], ...] or a facet
/// with hole points {"loops": [[loop], ...], "holes": [[x, y, z], ...]}.
core::PlcFacet facet_of(const py::handle& item, std::size_t p, std::size_t point_count) {
    const std::string name = polygon_name(p);
    core::PlcFacet facet;
    py::object loops = py::reinterpret_borrow<py::object>(item);
    if (py::isinstance<py::dict>(item)) {
        const auto d = py::reinterpret_borrow<py::dict>(item);
        for (const auto& [key, value] : d) {
            const std::string k = py::str(key).cast<std::string>();
            if (k != "loops" && k != "holes") {
                throw py::value_error(name + ": unknown key " + repr_text(key) +
                                      " (a polygon given as a dict has \"loops\" and \"holes\")");
            }
        }
        if (!d.contains("loops")) {
            throw py::value_error(name + " is a dict without \"loops\"");
        }
        loops = d["loops"];
        if (d.contains("holes")) {
            facet.holes = point_rows(d["holes"], name + " holes");
        }
        if (!is_sequence(loops) || py::len(loops) == 0 || !is_sequence(loops[py::int_(0)])) {
            throw py::value_error(name +
                                  ": \"loops\" must be a sequence of loops, each a "
                                  "sequence of point indices");
        }
    } else if (!is_sequence(item)) {
        throw py::value_error(name +
                              " must be a sequence of point indices, a sequence of loops or "
                              "a dict with \"loops\" and \"holes\"; got " +
                              repr_text(item));
    } else if (py::len(item) == 0) {
        throw py::value_error(name + " is empty");
    } else if (!is_sequence(loops[py::int_(0)])) {
        // The first element is a corner, not a loop: the polygon is one loop.
        facet.loops.push_back(loop_of(item, name, point_count));
        return facet;
    }
    const std::size_t count = py::len(loops);
    for (std::size_t l = 0; l < count; ++l) {
        const std::string loop_name = count == 1 ? name : name + ", loop " + std::to_string(l);
        facet.loops.push_back(loop_of(loops[py::int_(l)], loop_name, point_count));
    }
    return facet;
}

/// The fast path: an (f, k) integer array, one loop of k corners per row.
std::vector<core::PlcFacet> facets_of_array(const py::handle& polygons, std::size_t point_count) {
    const IndexArray a = integer_array(polygons, "polygons");
    if (a.ndim() != 2 || a.shape(1) < 3) {
        std::string shape = "(";
        for (py::ssize_t i = 0; i < a.ndim(); ++i) {
            shape += (i ? ", " : "") + std::to_string(a.shape(i));
        }
        throw py::value_error("polygons as an array must have shape (f, k) with k >= 3, got " +
                              shape + (a.ndim() == 1 ? ",)" : ")"));
    }
    const auto f = static_cast<std::size_t>(a.shape(0));
    const auto k = static_cast<std::size_t>(a.shape(1));
    std::vector<core::PlcFacet> facets(f);
    std::vector<long long> corners(k);
    for (std::size_t p = 0; p < f; ++p) {
        std::copy_n(a.data() + p * k, k, corners.begin());
        facets[p].loops.push_back(checked_loop(corners, polygon_name(p), point_count));
    }
    return facets;
}

std::vector<core::PlcFacet> facets_of(const py::handle& polygons, std::size_t point_count) {
    // An object array holds polygons of different sizes (numpy's ragged array): the slow path.
    if (py::isinstance<py::array>(polygons) &&
        py::reinterpret_borrow<py::array>(polygons).dtype().kind() != 'O') {
        return facets_of_array(polygons, point_count);
    }
    if (!is_sequence(polygons)) {
        throw py::value_error(
            "polygons must be an (f, k) integer array or a sequence of polygons, got " +
            repr_text(polygons));
    }
    std::vector<core::PlcFacet> facets;
    const std::size_t count = py::len(polygons);
    facets.reserve(count);
    for (std::size_t p = 0; p < count; ++p) {
        facets.push_back(facet_of(polygons[py::int_(p)], p, point_count));
    }
    return facets;
}

std::vector<std::array<std::uint32_t, 2>> segments_of(const py::handle& segments,
                                                      std::size_t point_count) {
    if (segments.is_none() || py::len(segments) == 0) {
        return {};
    }
    const IndexArray a = integer_array(segments, "segments");
    if (a.ndim() != 2 || a.shape(1) != 2) {
        throw py::value_error("segments must have shape (s, 2)");
    }
    std::vector<std::array<std::uint32_t, 2>> result(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t s = 0; s < result.size(); ++s) {
        const std::string name = "segment " + std::to_string(s);
        for (std::size_t e = 0; e < 2; ++e) {
            const std::int64_t v = a.data()[2 * s + e];
            if (v < 0 || static_cast<std::uint64_t>(v) >= point_count) {
                throw py::value_error(
                    name + ": point " + std::to_string(v) +
                    (v < 0 ? " is negative"
                           : " is out of range for " + std::to_string(point_count) + " points"));
            }
            result[s][e] = static_cast<std::uint32_t>(v);
        }
        if (result[s][0] == result[s][1]) {
            throw py::value_error(name + " joins point " + std::to_string(result[s][0]) +
                                  " to itself");
        }
    }
    return result;
}

void set_markers(const py::handle& markers, std::vector<core::PlcFacet>& facets) {
    if (markers.is_none()) {
        return;
    }
    const IndexArray a = integer_array(markers, "markers");
    if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != facets.size()) {
        throw py::value_error("markers must have one integer per polygon, shape (" +
                              std::to_string(facets.size()) + ",)");
    }
    for (std::size_t p = 0; p < facets.size(); ++p) {
        const std::int64_t m = a.data()[p];
        if (m < std::numeric_limits<std::int32_t>::min() ||
            m > std::numeric_limits<std::int32_t>::max()) {
            throw py::value_error("markers[" + std::to_string(p) + "] = " + std::to_string(m) +
                                  " does not fit in int32");
        }
        facets[p].marker = static_cast<int>(m);
    }
}

/// TetGen's region list: rows [x, y, z, marker], the marker an integer that fits int32.
std::vector<core::PlcRegion> regions_of(const py::handle& regions) {
    if (py::len(regions) == 0) {
        return {};
    }
    const DoubleArray a = require_rows(regions, "regions", 4);
    std::vector<core::PlcRegion> result(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t r = 0; r < result.size(); ++r) {
        const double* row = a.data() + 4 * r;
        const double m = row[3];
        if (!(m >= std::numeric_limits<std::int32_t>::min() &&
              m <= std::numeric_limits<std::int32_t>::max()) ||
            m != static_cast<double>(static_cast<std::int32_t>(m))) {
            throw py::value_error("regions row " + std::to_string(r) + ": marker " +
                                  py::repr(py::float_(m)).cast<std::string>() +
                                  " is not an integer that fits int32");
        }
        result[r] = {{row[0], row[1], row[2]}, static_cast<std::int32_t>(m), 0};
    }
    return result;
}

/// TetGen's volume hole list: rows [x, y, z].
std::vector<core::PlcVolumeHole> holes_of(const py::handle& holes) {
    if (py::len(holes) == 0) {
        return {};
    }
    const DoubleArray a = require_rows(holes, "holes", 3);
    std::vector<core::PlcVolumeHole> result(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t h = 0; h < result.size(); ++h) {
        const double* row = a.data() + 3 * h;
        result[h] = {{row[0], row[1], row[2]}, 0};
    }
    return result;
}

/// Collinearity, exactly: a, b, c are collinear when their projections on the three coordinate
/// planes are. Each 2D orientation is orient3d of the projections (z = 0) and the apex (0, 0, 1):
/// the determinant is minus orient2d's, so the zero test is exact as orient3d is.
bool collinear(const Point3& a, const Point3& b, const Point3& c) {
    const Point3 apex{0, 0, 1};
    const auto flat = [&](double (*u)(const Point3&), double (*v)(const Point3&)) {
        return predicates::orient3d(
                   Point3{u(a), v(a), 0}, Point3{u(b), v(b), 0}, Point3{u(c), v(c), 0}, apex) ==
               Sign::kZero;
    };
    const auto x = [](const Point3& p) { return p.x; };
    const auto y = [](const Point3& p) { return p.y; };
    const auto z = [](const Point3& p) { return p.z; };
    return flat(x, y) && flat(y, z) && flat(z, x);
}

/// The checks read_poly makes of each facet of a .poly file: corners not all collinear, every
/// corner and hole point in the plane (exact). build_cdt and plc_violations take them as given
/// (plc_validity.h), so a PLC made in memory is checked here.
/// \throws core::Error naming the polygon.
void check_facet_geometry(const core::Plc& plc, std::size_t f) {
    const std::string name = polygon_name(f);
    const auto& points = plc.points.points;
    std::vector<std::uint32_t> corners;
    for (const auto& loop : plc.facets[f].loops) {
        corners.insert(corners.end(), loop.begin(), loop.end());
    }
    const Point3& a = points[corners[0]];
    // b: the first corner other than a (distinct indices may still coincide; plc_delaunay names
    // such points later); c: the first corner off the line ab.
    const auto b = std::find_if(corners.begin(), corners.end(), [&](std::uint32_t v) {
        const Point3& p = points[v];
        return p.x != a.x || p.y != a.y || p.z != a.z;
    });
    const auto c = b == corners.end() ? b : std::find_if(b, corners.end(), [&](std::uint32_t v) {
        return !collinear(a, points[*b], points[v]);
    });
    if (c == corners.end()) {
        throw core::Error(name + ": its corners are collinear");
    }
    const auto in_plane = [&](const Point3& p) {
        return predicates::orient3d(a, points[*b], points[*c], p) == Sign::kZero;
    };
    for (const std::uint32_t v : corners) {
        if (!in_plane(points[v])) {
            throw core::Error(name + ": corner " + std::to_string(v) +
                              " is not in the plane of the polygon");
        }
    }
    const auto& holes = plc.facets[f].holes;
    for (std::size_t h = 0; h < holes.size(); ++h) {
        if (!in_plane(holes[h])) {
            throw core::Error(name + ": hole point " + std::to_string(h) +
                              " is not in the plane of the polygon");
        }
    }
}

/// The row of the first region point outside the mesh, for a message naming it (core names the
/// .poly line, and these rows have none); regions.size() when every point is inside.
std::size_t region_outside(const core::Cdt& cdt) {
    core::Plc probe;
    probe.points = cdt.plc.points;
    for (std::size_t r = 0; r < cdt.plc.regions.size(); ++r) {
        probe.regions = {cdt.plc.regions[r]};
        try {
            core::region_markers(probe, cdt.tets, cdt.faces);
        } catch (const core::Error&) {
            return r;
        }
    }
    return cdt.plc.regions.size();
}

/// The row of the first hole point core refuses, and core's message for it (which has no line to
/// name); holes.size() when each is accepted on its own.
std::pair<std::size_t, std::string> hole_refused(const core::Cdt& cdt) {
    core::Cdt probe;
    probe.plc.points = cdt.plc.points;
    probe.tets = cdt.tets;
    probe.faces = cdt.faces;
    for (std::size_t h = 0; h < cdt.plc.volume_holes.size(); ++h) {
        probe.plc.volume_holes = {cdt.plc.volume_holes[h]};
        try {
            core::carve_cdt(probe, true);
        } catch (const core::Error& e) {
            return {h, e.what()};
        }
    }
    return {cdt.plc.volume_holes.size(), {}};
}

/// How the polygons are read: as a .poly file's facets, or as a surface mesh file's faces.
struct Reading {
    bool surface = false;
    bool merge_coplanar_faces = true;  ///< with `surface`
};

/// The points to insert after the polygons (§5.7), as `cavity cdt --insert` does.
struct Insertion {
    bool given = false;  ///< `insert` was not None (it may still have no rows)
    std::vector<Point3> points;
    bool all_or_nothing = false;
};

/// Everything one CDT produces, computed without the GIL.
struct Built {
    core::SurfaceReading surface;
    core::Cdt cdt;
    core::CarvedCdt domain;
    /// Per row of the inserted points: its vertex index, or -1 when it was left out.
    std::vector<std::int32_t> inserted;
    /// The rows left out, each with core's reason.
    std::vector<std::pair<std::size_t, std::string>> left_out;
};

/// The CDT of `plc`, then the insertion's points in row order. A point that cannot be inserted
/// (or repeats a vertex) is left out and recorded, or with all_or_nothing refuses the whole call.
core::Cdt construct(core::Plc plc,
                    const core::CdtOptions& options,
                    const Insertion& insertion,
                    Built& b) {
    if (!insertion.given) {
        // build_cdt validates its result exactly (validate_cdt) before returning it.
        return core::build_cdt(std::move(plc), options);
    }
    core::LiveCdt live(std::move(plc), options);
    b.inserted.assign(insertion.points.size(), -1);
    for (std::size_t row = 0; row < insertion.points.size(); ++row) {
        const core::CdtInsertion r = live.insert_vertex(insertion.points[row]);
        if (r.inserted()) {
            b.inserted[row] = static_cast<std::int32_t>(r.vertex);
            continue;
        }
        if (insertion.all_or_nothing) {
            throw core::Error("insert row " + std::to_string(row) + ": " + r.message +
                              " (all_or_nothing=True: nothing returned)");
        }
        b.left_out.emplace_back(row, r.message);
    }
    // The constructor checked the CDT of the PLC; check again what the insertions made of it.
    live.validate();
    return live.snapshot();
}

Built build(core::Plc plc,
            const core::CdtOptions& options,
            bool convex_hull,
            Reading reading,
            const Insertion& insertion) {
    Built b;
    if (reading.surface) {
        // The surface check names degenerate faces (collinear corners, not flat) itself.
        b.surface = core::prepare_surface_mesh(plc, reading.merge_coplanar_faces);
    } else {
        for (std::size_t f = 0; f < plc.facets.size(); ++f) {
            check_facet_geometry(plc, f);
        }
    }
    try {
        b.cdt = construct(std::move(plc), options, insertion, b);
    } catch (const core::Error& e) {
        // Core words its advice for the command line; here the switch is the keyword argument.
        std::string message = e.what();
        const std::string flag = "--protect";
        if (const auto at = message.find(flag); at != std::string::npos) {
            message.replace(at, flag.size(), "protect=True");
        }
        throw core::Error(message, e.kind());
    }
    try {
        b.domain = core::carve_cdt(b.cdt, convex_hull);
    } catch (const core::Error&) {
        // Core names .poly lines, and these rows have none: find the row it refused.
        const auto [hole, why] = hole_refused(b.cdt);
        if (hole < b.cdt.plc.volume_holes.size()) {
            throw core::Error("holes row " + std::to_string(hole) + ": " + why);
        }
        const std::size_t row = region_outside(b.cdt);
        if (row == b.cdt.plc.regions.size()) {
            throw;  // neither: core's message as it is
        }
        throw core::Error("regions row " + std::to_string(row) +
                          ": the point lies outside the tetrahedralization (the convex hull "
                          "of the points)");
    }
    return b;
}

class Cdt {
public:
    Cdt(core::Plc plc,
        const core::CdtOptions& options,
        bool with_regions,
        bool convex_hull,
        Reading reading,
        const Insertion& insertion) {
        const std::size_t polygons = plc.facets.size();
        const std::size_t input_points = plc.points.size();
        Built b;
        {
            py::gil_scoped_release nogil;
            b = build(std::move(plc), options, convex_hull, reading, insertion);
        }
        core::Cdt& cdt = b.cdt;
        const auto n = static_cast<py::ssize_t>(cdt.plc.points.size());
        py::array_t<double> points({n, py::ssize_t{3}});
        auto* p = points.mutable_data();
        for (std::size_t i = 0; i < cdt.plc.points.size(); ++i) {
            p[3 * i] = cdt.plc.points.points[i].x;
            p[3 * i + 1] = cdt.plc.points.points[i].y;
            p[3 * i + 2] = cdt.plc.points.points[i].z;
        }
        points.attr("setflags")(py::arg("write") = false);
        points_ = points;

        const auto& c = cdt.counters;
        py::dict stats;
        stats["points"] = cdt.plc.points.size();
        stats["input_points"] = input_points;
        stats["protection_points"] = cdt.protection.inserted.size();
        stats["protection_rounds"] = cdt.protection.rounds;
        stats["polygons"] = polygons;
        stats["warped_faces"] = b.surface.warped_faces;
        stats["merged_faces"] = b.surface.merged_faces;
        stats["merged_polygons"] = b.surface.merged_polygons;
        stats["tets"] = b.domain.tets.size();
        stats["removed_tets"] = b.domain.removed;
        stats["faces"] = cdt.faces.size();
        stats["flips_23"] = c.flips.flip_count(core::FlipKind::k23);
        stats["flips_32"] = c.flips.flip_count(core::FlipKind::k32);
        stats["flips_44"] = c.flips.flip_count(core::FlipKind::k44);
        stats["events_queued"] = c.events_queued;
        stats["events_stale"] = c.events_stale;
        stats["events_held"] = c.events_held;
        stats["region_tets"] = c.region_tets;
        stats["region_vertices"] = c.region_vertices;
        stats["max_region_vertices"] = c.max_region_vertices;
        stats["rotary_steps"] = c.rotary_steps;
        stats["search_visited"] = c.search_visited;
        stats["certify_calls"] = c.certify_calls;
        const auto& in = cdt.insertion;
        stats["insert_attempts"] = in.attempts;
        stats["inserted"] = in.inserted;
        stats["insert_duplicates"] = in.duplicates;
        stats["insert_not_star_shaped"] = in.refused_not_star_shaped;
        stats["insert_through_cavity"] = in.refused_through_cavity;
        stats["insert_not_delaunay"] = in.refused_not_delaunay;
        stats["insert_on_polygon"] = in.on_polygon;
        stats["insert_on_plc_edge"] = in.on_plc_edge;
        stats_ = stats;

        const auto m = static_cast<py::ssize_t>(b.domain.tets.size());
        const auto f = static_cast<py::ssize_t>(cdt.faces.size());
        std::vector<std::array<std::uint32_t, 3>> faces(cdt.faces.size());
        std::vector<std::int32_t> markers(cdt.faces.size());
        for (std::size_t i = 0; i < cdt.faces.size(); ++i) {
            faces[i] = cdt.faces[i].v;
            markers[i] = cdt.faces[i].marker;
        }
        const auto s = static_cast<py::ssize_t>(cdt.protection.inserted.size());
        simplices_ = adopt(std::move(b.domain.tets), {m, 4});
        faces_ = adopt(std::move(faces), {f, 3});
        face_markers_ = adopt(std::move(markers), {f});
        steiner_ = adopt(std::move(cdt.protection.inserted), {s});
        region_markers_ =
            with_regions ? py::object(adopt(std::move(b.domain.regions), {m})) : py::none();
        if (!insertion.given) {
            inserted_ = py::none();
            left_out_ = py::none();
            return;
        }
        const auto k = static_cast<py::ssize_t>(b.inserted.size());
        inserted_ = adopt(std::move(b.inserted), {k});
        py::list left_out;
        for (const auto& [row, why] : b.left_out) {
            left_out.append(py::make_tuple(row, why));
        }
        left_out_ = left_out;
        if (!b.left_out.empty()) {
            // Left out silently, a point would only show as a missing vertex much later.
            const std::string warning =
                std::to_string(b.left_out.size()) + " of " + std::to_string(k) +
                " insert points left out, the first: row " +
                std::to_string(b.left_out.front().first) + ": " + b.left_out.front().second +
                " (CDT.left_out lists them all)";
            if (PyErr_WarnEx(PyExc_RuntimeWarning, warning.c_str(), 1) != 0) {
                throw py::error_already_set();  // the warnings filter made it an error
            }
        }
    }

    py::object to_meshio() const {
        py::module_ meshio;
        try {
            meshio = py::module_::import("meshio");
        } catch (py::error_already_set& e) {
            if (!e.matches(PyExc_ImportError)) {
                throw;
            }
            py::raise_from(e,
                           PyExc_ImportError,
                           "CDT.to_meshio() needs the meshio package (pip install meshio; "
                           "Debian: apt install python3-meshio)");
            throw py::error_already_set();
        }
        py::list cells;
        cells.append(py::make_tuple("tetra", simplices_));
        py::dict cell_data;
        // The name the CLI's .vtu gives TetGen's region attribute.
        if (!region_markers_.is_none()) {
            py::list per_block;
            per_block.append(region_markers_);
            cell_data["region"] = per_block;
        }
        return meshio.attr("Mesh")(points_, cells, py::arg("cell_data") = cell_data);
    }

    py::array points_;
    py::array_t<std::int32_t> simplices_;
    py::array_t<std::int32_t> faces_;
    py::array_t<std::int32_t> face_markers_;
    py::array_t<std::int32_t> steiner_;
    py::object region_markers_;
    py::object inserted_;
    py::object left_out_;
    py::dict stats_;
};

Cdt make_cdt(const py::handle& points,
             const py::handle& polygons,
             const py::handle& segments,
             const py::handle& markers,
             const py::handle& regions,
             const py::handle& holes,
             bool convex_hull,
             bool protect,
             std::size_t max_protection_points,
             bool surface,
             bool keep_faces,
             const py::handle& insert,
             bool all_or_nothing) {
    if (keep_faces && !surface) {
        throw py::value_error("keep_faces=True applies to surface=True only");
    }
    if (all_or_nothing && insert.is_none()) {
        throw py::value_error("all_or_nothing=True applies to insert only");
    }
    Insertion insertion;
    insertion.all_or_nothing = all_or_nothing;
    if (!insert.is_none()) {
        insertion.given = true;
        const DoubleArray rows = require_rows(insert, "insert", 3);
        const double* data = rows.data();
        for (py::ssize_t r = 0; r < rows.shape(0); ++r) {
            insertion.points.push_back({data[3 * r], data[3 * r + 1], data[3 * r + 2]});
        }
    }
    core::Plc plc;
    plc.points = to_point_set(points, py::none());
    // Core prefixes messages with a non-empty source, as it does with a file name.
    plc.points.source.clear();
    const std::size_t n = plc.points.size();
    const auto int32_max = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
    if (max_protection_points > int32_max - n ||
        insertion.points.size() > int32_max - n - max_protection_points) {
        throw py::value_error(
            "max_protection_points: the points, the protecting points and the insert points "
            "together must be numbered by int32 indices");
    }
    plc.facets = facets_of(polygons, n);
    set_markers(markers, plc.facets);
    plc.segments = segments_of(segments, n);
    if (surface) {
        if (!plc.segments.empty()) {
            throw py::value_error("surface=True takes no segments: a surface mesh is its faces");
        }
        for (std::size_t f = 0; f < plc.facets.size(); ++f) {
            if (plc.facets[f].loops.size() != 1 || !plc.facets[f].holes.empty()) {
                throw py::value_error(polygon_name(f) +
                                      ": with surface=True each polygon is one loop, a face of "
                                      "the surface mesh");
            }
            plc.facets[f].number = f;  // the surface check names faces by their row
        }
    }
    if (!regions.is_none()) {
        plc.regions = regions_of(regions);
    }
    if (!holes.is_none()) {
        plc.volume_holes = holes_of(holes);
    }
    return Cdt(std::move(plc),
               core::CdtOptions{protect, max_protection_points},
               !regions.is_none(),
               convex_hull,
               Reading{surface, !keep_faces},
               insertion);
}

}  // namespace

void bind_cdt(py::module_& m) {
    py::class_<Cdt>(m, "CDT", R"doc(
Constrained Delaunay tetrahedralization of a piecewise linear complex, made by cavity.cdt().

Every attribute is a read-only numpy array (or a dict). The mesh was checked exactly before it was
returned (the same validator as ``cavity cdt``): every tetrahedron has positive volume, the
polygons are unions of ``faces``, and every face is constrained Delaunay.

Attributes
----------
points : (n', 3) float64
    The input points, then the protecting (Steiner) points added with ``protect=True``, then
    the ``insert`` points that were inserted, in row order.
simplices : (m, 4) int32
    Tetrahedra of the domain the polygons bound (of the whole convex hull with
    ``convex_hull=True``), minus the ``holes``, as row indices into ``points``, each with
    positive volume by the right-hand rule (cavity.orient3d of each row is -1).
faces : (f, 3) int32
    The triangles the polygons are divided into (in no particular orientation).
face_markers : (f,) int32
    The marker of the polygon each face belongs to (0 without ``markers``).
steiner : (s,) int32
    Indices into ``points`` of the protecting points, in insertion order (n to n + s - 1).
region_markers : (m,) int32 or None
    With ``regions``: the marker of the region holding each tetrahedron, 0 for none.
inserted : (k,) int32 or None
    With ``insert``: per row of it, the index into ``points`` of the vertex it became, or -1
    when it was left out.
left_out : list of (int, str) or None
    With ``insert``: the rows left out, each with the reason (a vertex there already, or no CDT
    of the PLC with the point added: the cavity is not star-shaped, a polygon, PLC edge or
    vertex lies inside it, or a new face is not locally Delaunay).
stats : dict
    Counts of the construction: points, input_points, protection_points, protection_rounds,
    polygons, warped_faces, merged_faces, merged_polygons (surface=True), tets (kept), removed_tets (carved away), faces, flips_23, flips_32, flips_44, events_queued, events_stale,
    events_held, region_tets, region_vertices, max_region_vertices, rotary_steps,
    search_visited, certify_calls; of ``insert``: insert_attempts, inserted, insert_duplicates,
    insert_not_star_shaped, insert_through_cavity, insert_not_delaunay, insert_on_polygon,
    insert_on_plc_edge.
npoints, nsimplex : int
    len(points), len(simplices).
)doc")
        .def_readonly("points", &Cdt::points_, "(n', 3) float64: input points, then Steiner points")
        .def_readonly("simplices",
                      &Cdt::simplices_,
                      "(m, 4) int32: tetrahedra with positive right-hand volume (cavity.orient3d "
                      "of each row is -1)")
        .def_readonly("faces", &Cdt::faces_, "(f, 3) int32: the polygons' triangles")
        .def_readonly("face_markers", &Cdt::face_markers_, "(f,) int32: each face's polygon marker")
        .def_readonly("steiner", &Cdt::steiner_, "(s,) int32: indices of the protecting points")
        .def_readonly("region_markers",
                      &Cdt::region_markers_,
                      "(m,) int32 region marker per tetrahedron (0: no region), or None without "
                      "regions")
        .def_readonly("inserted",
                      &Cdt::inserted_,
                      "(k,) int32 vertex index per insert row (-1: left out), or None without "
                      "insert")
        .def_readonly("left_out",
                      &Cdt::left_out_,
                      "list of (row, reason) of the insert rows left out, or None without insert")
        .def_readonly("stats", &Cdt::stats_, "dict: counts of protection and polygon insertion")
        .def_property_readonly("npoints", [](const Cdt& c) { return c.points_.shape(0); })
        .def_property_readonly("nsimplex", [](const Cdt& c) { return c.simplices_.shape(0); })
        .def("to_meshio",
             &Cdt::to_meshio,
             R"doc(The mesh as a meshio.Mesh: ``points`` and one "tetra" cell block, with the cell
data "region" when regions were given. Raises ImportError when meshio is not installed.)doc")
        .def("__repr__", [](const Cdt& c) {
            return "<cavity.CDT: " + std::to_string(c.points_.shape(0)) + " points (" +
                   std::to_string(c.steiner_.shape(0)) + " protecting), " +
                   std::to_string(c.simplices_.shape(0)) + " tetrahedra, " +
                   std::to_string(c.faces_.shape(0)) + " polygon triangles>";
        });

    m.def("cdt",
          &make_cdt,
          py::arg("points"),
          py::arg("polygons"),
          py::kw_only(),
          py::arg("segments") = py::none(),
          py::arg("markers") = py::none(),
          py::arg("regions") = py::none(),
          py::arg("holes") = py::none(),
          py::arg("convex_hull") = false,
          py::arg("protect") = false,
          py::arg("max_protection_points") = 100000,
          py::arg("surface") = false,
          py::arg("keep_faces") = false,
          py::arg("insert") = py::none(),
          py::arg("all_or_nothing") = false,
          R"doc(
Constrained Delaunay tetrahedralization (CDT) of a piecewise linear complex (PLC).

The Delaunay triangulation of the points, then each polygon inserted by flips (Cheng, Dey &
Shewchuk §5.8), every polygon a union of its triangles; then, as TetGen does with -p, the domain
the polygons bound is carved out of the convex hull: the tetrahedra reachable from the hull
without crossing a polygon are removed, and so are those reachable from each hole point. Exact;
the GIL is released while it runs. This is ``cavity cdt`` without the files.

Parameters
----------
points : (n, 3) array_like of float
    The vertices (finite; converted to float64).
polygons : (f, k) array_like of int, or sequence
    As an integer array: one polygon of k >= 3 corners per row, e.g. the (f, 3) triangles of a
    closed surface mesh (the fast path). As a sequence, each item is one of
      - a loop: a sequence of >= 3 point indices, e.g. [0, 1, 2, 3];
      - a polygon with holes, as coplanar loops whose sides do not cross: [[outer], [inner], ...];
      - a dict {"loops": [[outer], [inner], ...], "holes": [[x, y, z], ...]}.
    The region of a polygon follows TetGen's .poly facets: the union of the loops' interiors,
    minus every face of their arrangement that holds a hole point. A loop nested in another
    therefore cuts a hole only when a hole point lies inside it; without one it only subdivides
    the polygon. Every polygon's corners must be coplanar and not all collinear.
segments : (s, 2) array_like of int, optional
    Edges the mesh must contain, besides the polygons' sides.
markers : (f,) array_like of int, optional
    One marker per polygon (int32), copied to the polygon's faces (``face_markers``).
regions : (r, 4) array_like of float, optional
    TetGen's region list, rows [x, y, z, marker]: the tetrahedra reachable from the one holding
    (x, y, z) without crossing a polygon get the (integer) marker, the first region to reach a
    tetrahedron keeping it (``region_markers``).
holes : (h, 3) array_like of float, optional
    TetGen's volume hole list: the tetrahedra reachable from the one holding each point, without
    crossing a polygon, are removed. A point on a face, edge or vertex in no polygon removes the
    same tetrahedra whichever tetrahedron holds it; a point on a polygon or outside the convex
    hull is refused by its row.
convex_hull : bool
    Keep the whole convex hull: neither the exterior nor the holes are removed (hole points are
    still checked).
protect : bool
    Split PLC edges that are not Delaunay edges at points lying exactly on them (double
    coordinates), until the PLC is edge-protected. Off: such a PLC is refused, naming the edges.
max_protection_points : int
    The most protecting points protect=True may add before giving up.
surface : bool
    The polygons are the faces of a closed surface mesh, one loop each (no segments), read as
    ``cavity cdt`` reads an .off/.stl/.obj/.ply file: a face whose corners are not exactly
    coplanar is cut into the triangles with the shortest diagonals; the surface must bound a
    solid (every side in exactly two faces, no degenerate or intersecting faces), else the
    ValueError names the faces ("facet i" is polygon i) and points; then each group of exactly
    coplanar faces joined by their sides, with one marker, is merged into one polygon (with
    holes), as TetGen does without -M: their shared sides are no constraints and need no
    protecting points. ``stats`` counts warped_faces, merged_faces and merged_polygons.
keep_faces : bool
    With surface=True: merge no faces (TetGen's -M), each face stays a polygon of its own.
insert : (k, 3) array_like of float, optional
    Points inserted after the polygons, in row order, each by vertex insertion into the CDT
    (Cheng, Dey & Shewchuk §5.7), as ``cavity cdt --insert`` does: a point on a polygon or a PLC
    edge splits it. A point that repeats a vertex, or whose insertion would leave no CDT, is
    left out, listed in ``CDT.left_out`` with the reason, and a RuntimeWarning names the first.
all_or_nothing : bool
    With ``insert``: a point left out is a ValueError naming its row, and nothing is returned.

Returns
-------
CDT

Raises
------
ValueError
    Naming the polygon, segment or row and the bad value: wrong shapes or dtypes, NaN or
    infinity, indices negative or out of range, a corner repeated in a loop, fewer than 3
    corners, a polygon not flat or collinear. With the core's message, which calls polygon i
    "facet i" as TetGen does: coinciding points, a PLC that is not edge-protected (without
    protect), an edge through a polygon, overlapping polygons, crossing loops, a hole point on a
    loop side. A region point outside the convex hull, or a hole point outside it or on a
    polygon, names its row.
)doc");
}

}  // namespace cavity::python
