#include "cavity/core/cdt/cdt_validate.h"

#include <algorithm>
#include <map>
#include <set>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/edge_protection.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/perturbation/sos.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

class Report {
public:
    explicit Report(CdtValidation& out) : out_(out) {}

    void add(std::string what) {
        if (out_.problems.size() < 20) {
            out_.problems.push_back(std::move(what));
        }
        ++out_.problem_count;
    }

private:
    CdtValidation& out_;
};

/// An axis-aligned box in doubles: min and max are exact, so a box test never drops a simplex
/// that meets a facet; it only spares exact tests of those that cannot.
struct Box {
    std::array<double, 3> lo{};
    std::array<double, 3> hi{};

    template <class Ids>
    static Box of(const std::vector<Point3>& pts, const Ids& ids) {
        Box b;
        const Point3& p0 = pts[ids[0]];
        b.lo = b.hi = {p0.x, p0.y, p0.z};
        for (auto id : ids) {
            const Point3& p = pts[id];
            const std::array<double, 3> c{p.x, p.y, p.z};
            for (std::size_t k = 0; k < 3; ++k) {
                b.lo[k] = std::min(b.lo[k], c[k]);
                b.hi[k] = std::max(b.hi[k], c[k]);
            }
        }
        return b;
    }

    bool meets(const Box& o) const {
        for (std::size_t k = 0; k < 3; ++k) {
            if (hi[k] < o.lo[k] || o.hi[k] < lo[k]) {
                return false;
            }
        }
        return true;
    }
};

Box facet_box(const Plc& plc, const PlcFacet& facet) {
    std::vector<std::uint32_t> corners;
    for (const auto& loop : facet.loops) {
        corners.insert(corners.end(), loop.begin(), loop.end());
    }
    return Box::of(plc.points.points, corners);
}

/// The mesh simplices with their boxes, computed once for every facet's tests.
struct BoxedMesh {
    std::span<const std::array<std::uint32_t, 4>> tets;
    std::vector<Box> tet_boxes;
    std::vector<Triangle> triangles;
    std::vector<Box> triangle_boxes;
};

std::string tet_name(const std::array<std::uint32_t, 4>& t, int base) {
    std::string s = "tetrahedron";
    for (std::uint32_t v : t) {
        s += " " + std::to_string(v + static_cast<std::uint32_t>(base));
    }
    return s;
}

/// The facet's triangles among the mesh triangles lying in its plane, after checking that no
/// tetrahedron crosses it and that they cover its area.
std::vector<Triangle> polygon_faces(const Plc& plc,
                                    std::size_t index,
                                    const BoxedMesh& mesh,
                                    Report& report) {
    const PlcFacet& facet = plc.facets[index];
    const std::string name = facet_name(plc, index);
    const auto plane = ExactPlane::of_facet(plc, facet);
    std::vector<Triangle> faces;
    if (!plane) {
        report.add(name + ": corners are collinear");
        return faces;
    }
    const auto& pts = plc.points.points;
    const Box box = facet_box(plc, facet);
    for (std::size_t k = 0; k < mesh.tets.size(); ++k) {
        if (!box.meets(mesh.tet_boxes[k])) {
            continue;
        }
        const auto& t = mesh.tets[k];
        std::array<int, 4> s{};
        for (std::size_t i = 0; i < 4; ++i) {
            s[i] = static_cast<int>(plane->side(pts[t[i]]));
        }
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = 0; j < 4; ++j) {
                if (s[i] < 0 && s[j] > 0) {
                    if (in_facet_region(
                            plc, facet, *plane, plane->crossing(pts[t[i]], pts[t[j]]))) {
                        report.add(tet_name(t, plc.points.index_base) + " crosses " + name);
                    }
                    i = j = 4;
                    break;
                }
            }
        }
    }
    Rational covered = 0;
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const Triangle& g = mesh.triangles[k];
        if (!box.meets(mesh.triangle_boxes[k])) {
            continue;
        }
        if (plane->side(pts[g[0]]) != Sign::kZero || plane->side(pts[g[1]]) != Sign::kZero ||
            plane->side(pts[g[2]]) != Sign::kZero) {
            continue;
        }
        const ExactPoint a = exact_point(pts[g[0]]);
        const ExactPoint b = exact_point(pts[g[1]]);
        const ExactPoint c = exact_point(pts[g[2]]);
        const ExactPoint centroid{
            (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
        if (in_facet_region(plc, facet, *plane, centroid)) {
            faces.push_back(g);
            covered += triangle_area2(*plane, pts[g[0]], pts[g[1]], pts[g[2]]);
        }
    }
    if (covered != facet_region_area2(plc, facet, *plane)) {
        report.add(name + " is not a union of mesh triangles (their area differs from its area)");
    }
    return faces;
}

}  // namespace

CdtValidation validate_cdt(const Plc& plc, std::span<const std::array<std::uint32_t, 4>> tets) {
    CdtValidation result;
    Report report(result);
    const int base = plc.points.index_base;
    for (const auto& t : tets) {
        for (std::uint32_t v : t) {
            if (v >= plc.points.size()) {
                report.add(tet_name(t, base) + " names a point that does not exist");
                return result;
            }
        }
    }
    // The complex checks name vertices by their ids: number them as the file does (ids shifted by
    // the base, keys unchanged so the perturbation is the same), so every message can be matched
    // against the input.
    std::vector<std::array<std::uint32_t, 4>> numbered(tets.begin(), tets.end());
    for (auto& t : numbered) {
        for (auto& v : t) {
            v += static_cast<std::uint32_t>(base);
        }
    }
    std::vector<Point3> points(static_cast<std::size_t>(base), Point3{0, 0, 0});
    points.insert(points.end(), plc.points.points.begin(), plc.points.points.end());
    std::vector<std::uint32_t> keys(points.size());
    for (std::size_t v = 0; v < keys.size(); ++v) {
        keys[v] = static_cast<std::uint32_t>(v < static_cast<std::size_t>(base) ? 0 : v - base);
    }
    const Geometry geometry(std::move(points), std::move(keys), {});
    ArrayStorage storage;
    try {
        storage = complex_from_tets(numbered);
    } catch (const Error& e) {
        report.add(e.what());
        return result;
    }
    for (const std::string& p : check_complex(storage, geometry)) {
        report.add(p);
    }
    std::vector<bool> used(plc.points.size(), false);
    for (const auto& t : tets) {
        for (std::uint32_t v : t) {
            used[v] = true;
        }
    }
    for (std::size_t v = 0; v < used.size(); ++v) {
        if (!used[v]) {
            report.add("point " + std::to_string(v + static_cast<std::size_t>(base)) +
                       " is not a vertex");
        }
    }
    for (const Edge& e : unprotected_edges(plc, tets)) {
        report.add("PLC edge " + std::to_string(e[0] + static_cast<std::uint32_t>(base)) + "-" +
                   std::to_string(e[1] + static_cast<std::uint32_t>(base)) +
                   " is not an edge of the mesh");
    }
    if (!result.ok()) {
        return result;
    }
    std::set<Triangle> triangles;
    for (const auto& t : tets) {
        for (int f = 0; f < 4; ++f) {
            const auto g = facet_vertices(t, f);
            Triangle s{g[0], g[1], g[2]};
            std::sort(s.begin(), s.end());
            triangles.insert(s);
        }
    }
    BoxedMesh mesh{tets, {}, {triangles.begin(), triangles.end()}, {}};
    for (const auto& t : tets) {
        mesh.tet_boxes.push_back(Box::of(plc.points.points, t));
    }
    for (const Triangle& g : mesh.triangles) {
        mesh.triangle_boxes.push_back(Box::of(plc.points.points, g));
    }
    std::set<Triangle> constrained;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        for (const Triangle& g : polygon_faces(plc, f, mesh, report)) {
            constrained.insert(g);
        }
    }
    result.polygon_triangles = constrained.size();
    for (TetId t = 0; t < storage.capacity(); ++t) {
        if (!storage.alive(t) || is_ghost(storage.vertices(t))) {
            continue;
        }
        const TetVertices& v = storage.vertices(t);
        for (int f = 0; f < 4; ++f) {
            const HalfFacet h = storage.adjacent(t, f);
            if (h == kNoHalfFacet || is_ghost(storage.vertices(tet_of(h)))) {
                continue;
            }
            const TetVertices& w = storage.vertices(tet_of(h));
            Triangle g = facet_vertices(v, f);  // numbered like the file
            std::sort(g.begin(), g.end());
            const auto b = static_cast<std::uint32_t>(base);
            if (constrained.contains({g[0] - b, g[1] - b, g[2] - b})) {
                continue;
            }
            const VertexId q = w[static_cast<std::size_t>(facet_of(h))];
            const auto& gm = geometry;
            if (perturbation::insphere_sos(
                    gm.point(v[0]),
                    gm.point(v[1]),
                    gm.point(v[2]),
                    gm.point(v[3]),
                    gm.point(q),
                    {gm.key(v[0]), gm.key(v[1]), gm.key(v[2]), gm.key(v[3]), gm.key(q)}) ==
                Sign::kPos) {
                report.add("triangle " + std::to_string(g[0]) + " " + std::to_string(g[1]) + " " +
                           std::to_string(g[2]) + " is in no polygon and not locally Delaunay");
            }
        }
    }
    return result;
}

}  // namespace cavity::core
