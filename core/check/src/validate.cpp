#include "cavity/core/check/validate.h"

#include <algorithm>
#include <string>

#include "cavity/core/base/handedness.h"
#include "cavity/core/geometry/duplicates.h"
#include "cavity/core/mesh/tetrahedron.h"
#include "cavity/perturbation/outer_halfspace.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {

using predicates::Sign;

namespace {

constexpr std::size_t kProblemsKept = 20;

/// One side of a triangle: its vertex ids sorted (the key), the tetrahedron and facet it belongs
/// to, and whether the facet's orientation is an even permutation of the sorted key.
struct FaceRecord {
    std::array<std::uint32_t, 3> key;
    std::uint32_t half_facet;
    bool even;
};

bool sorted_is_even(std::array<std::uint32_t, 3>& v) {
    bool even = true;
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2 - i; ++j) {
            if (v[static_cast<std::size_t>(j)] > v[static_cast<std::size_t>(j) + 1]) {
                std::swap(v[static_cast<std::size_t>(j)], v[static_cast<std::size_t>(j) + 1]);
                even = !even;
            }
        }
    }
    return even;
}

class Validator {
public:
    Validator(const PointSet& points,
              std::span<const std::array<std::uint32_t, 4>> tets,
              std::span<const std::uint32_t> absent)
        : points_(points), absent_(points.size(), 0) {
        // The checks below reason in the engine's orientation (orient3d > 0); the API's lists have
        // positive right-hand volume, the mirror image.
        tets_.reserve(tets.size());
        for (const auto& t : tets) {
            tets_.push_back(swap_handedness(t));
        }
        for (std::uint32_t a : absent) {
            if (a < absent_.size()) {
                absent_[a] = 1;
            }
        }
    }

    ValidationReport run() {
        report_.tets = tets_.size();
        if (!check_tets()) {
            return report_;  // later checks assume valid indices
        }
        build_faces();
        check_delaunay_and_hull();
        check_points();
        report_.triangles = triangles_;
        const long long euler =
            static_cast<long long>(report_.vertices) - static_cast<long long>(report_.edges) +
            static_cast<long long>(report_.triangles) - static_cast<long long>(report_.tets);
        if (euler != 1) {
            problem("Euler characteristic V - E + F - T = " + std::to_string(euler) +
                    ", not 1: the tetrahedra do not form a triangulated ball");
        }
        return report_;
    }

private:
    const predicates::Point3& p(std::uint32_t i) const { return points_.points[i]; }

    predicates::WeightedPoint3 wp(std::uint32_t i) const {
        return {p(i).x, p(i).y, p(i).z, points_.weights[i]};
    }

    void problem(const std::string& what) {
        ++report_.problem_count;
        if (report_.problems.size() < kProblemsKept) {
            report_.problems.push_back(what);
        }
    }

    std::string tet_name(std::size_t t) const {
        const Tet v = swap_handedness(tets_[t]);  // as the caller listed it
        return "tetrahedron " + std::to_string(t) + " (" + std::to_string(v[0]) + " " +
               std::to_string(v[1]) + " " + std::to_string(v[2]) + " " + std::to_string(v[3]) + ")";
    }

    bool check_tets() {
        const std::size_t n = points_.size();
        used_.assign(n, 0);
        bool indices_ok = true;
        for (std::size_t t = 0; t < tets_.size(); ++t) {
            const auto& v = tets_[t];
            bool ok = true;
            for (int i = 0; i < 4; ++i) {
                if (v[static_cast<std::size_t>(i)] >= n) {
                    problem(tet_name(t) + ": vertex index out of range");
                    ok = false;
                }
                for (int j = 0; j < i; ++j) {
                    if (v[static_cast<std::size_t>(i)] == v[static_cast<std::size_t>(j)]) {
                        problem(tet_name(t) + ": repeated vertex");
                        ok = false;
                    }
                }
            }
            if (!ok) {
                indices_ok = false;
                continue;
            }
            for (std::uint32_t w : v) {
                used_[w] = 1;
            }
            if (predicates::orient3d(p(v[0]), p(v[1]), p(v[2]), p(v[3])) != Sign::kPos) {
                problem(tet_name(t) + ": volume not positive (right-hand rule)");
            }
        }
        report_.vertices = static_cast<std::size_t>(std::count(used_.begin(), used_.end(), 1));
        return indices_ok;
    }

    void build_faces() {
        faces_.reserve(4 * tets_.size());
        for (std::size_t t = 0; t < tets_.size(); ++t) {
            for (int f = 0; f < 4; ++f) {
                auto key = facet_vertices(tets_[t], f);
                const bool even = sorted_is_even(key);
                faces_.push_back(
                    {key, static_cast<std::uint32_t>(half_facet(static_cast<TetId>(t), f)), even});
            }
        }
        std::sort(faces_.begin(), faces_.end(), [](const FaceRecord& a, const FaceRecord& b) {
            return a.key < b.key;
        });
    }

    /// Sign of u against tetrahedron t: kPos when u conflicts with it (perturbed).
    Sign conflict(std::size_t t, std::uint32_t u) const {
        const auto& v = tets_[t];
        const perturbation::Keys5 keys{v[0], v[1], v[2], v[3], u};
        if (points_.weighted()) {
            return perturbation::orient4d_sos(wp(v[0]), wp(v[1]), wp(v[2]), wp(v[3]), wp(u), keys);
        }
        return perturbation::insphere_sos(p(v[0]), p(v[1]), p(v[2]), p(v[3]), p(u), keys);
    }

    void check_delaunay_and_hull() {
        struct HullEdge {
            std::uint32_t from, to;
            std::uint32_t half_facet;  // of the tetrahedron behind the hull triangle
        };

        std::vector<HullEdge> hull_edges;
        std::size_t i = 0;
        while (i < faces_.size()) {
            std::size_t j = i + 1;
            while (j < faces_.size() && faces_[j].key == faces_[i].key) {
                ++j;
            }
            ++triangles_;
            const FaceRecord& a = faces_[i];
            if (j - i > 2) {
                problem("triangle (" + std::to_string(a.key[0]) + " " + std::to_string(a.key[1]) +
                        " " + std::to_string(a.key[2]) + ") belongs to " + std::to_string(j - i) +
                        " tetrahedra");
            } else if (j - i == 2) {
                const FaceRecord& b = faces_[i + 1];
                if (a.even == b.even) {
                    problem("tetrahedra " + std::to_string(tet_of(a.half_facet)) + " and " +
                            std::to_string(tet_of(b.half_facet)) +
                            " lie on the same side of their common triangle");
                } else {
                    const std::uint32_t apex_b =
                        tets_[tet_of(b.half_facet)]
                             [static_cast<std::size_t>(facet_of(b.half_facet))];
                    if (conflict(tet_of(a.half_facet), apex_b) != Sign::kNeg) {
                        problem(tet_name(tet_of(a.half_facet)) + " and " +
                                tet_name(tet_of(b.half_facet)) +
                                ": their common triangle is not locally Delaunay");
                    }
                }
            } else {
                ++report_.hull_triangles;
                // The hull triangle seen from outside is the reverse of the facet.
                const auto tri =
                    facet_vertices(tets_[tet_of(a.half_facet)], facet_of(a.half_facet));
                const std::array<std::uint32_t, 3> out{tri[0], tri[2], tri[1]};
                for (int e = 0; e < 3; ++e) {
                    hull_edges.push_back({out[static_cast<std::size_t>(e)],
                                          out[static_cast<std::size_t>((e + 1) % 3)],
                                          a.half_facet});
                }
            }
            i = j;
        }
        check_hull(hull_edges);
        count_edges();
    }

    template <class HullEdges>
    void check_hull(HullEdges& edges) {
        const auto less = [](const auto& a, const auto& b) {
            return std::pair(a.from, a.to) < std::pair(b.from, b.to);
        };
        std::sort(edges.begin(), edges.end(), less);
        for (const auto& e : edges) {
            // The same directed edge twice, or no partner running the other way: not a closed,
            // consistently oriented surface.
            const auto twin =
                std::equal_range(edges.begin(), edges.end(), decltype(e){e.to, e.from, 0}, less);
            const auto same = std::equal_range(edges.begin(), edges.end(), e, less);
            if (twin.second - twin.first != 1 || same.second - same.first != 1) {
                problem("hull edge (" + std::to_string(e.from) + " " + std::to_string(e.to) +
                        ") is not shared by exactly two hull triangles");
                continue;
            }
            if (e.from > e.to) {
                continue;  // check each edge once
            }
            check_hull_edge(e.half_facet, twin.first->half_facet, e.from, e.to);
        }
    }

    /// Local convexity at a hull edge, and in-plane Delaunay when the two hull triangles are
    /// coplanar.
    void check_hull_edge(std::uint32_t h1, std::uint32_t h2, std::uint32_t from, std::uint32_t to) {
        const auto inner1 = facet_vertices(tets_[tet_of(h1)], facet_of(h1));
        const auto inner2 = facet_vertices(tets_[tet_of(h2)], facet_of(h2));
        std::uint32_t far = 0;  // the vertex of triangle 2 off the shared edge
        for (std::uint32_t w : inner2) {
            if (w != from && w != to) {
                far = w;
            }
        }
        const Sign side = predicates::orient3d(p(inner1[0]), p(inner1[1]), p(inner1[2]), p(far));
        if (side == Sign::kNeg) {
            // far is in front of triangle 1: the hull folds inwards at this edge.
            problem("hull edge (" + std::to_string(from) + " " + std::to_string(to) +
                    ") is reflex: the boundary is not convex");
            return;
        }
        if (side == Sign::kPos) {
            return;
        }
        const std::uint32_t behind = tets_[tet_of(h1)][static_cast<std::size_t>(facet_of(h1))];
        const std::array<std::uint32_t, 3> v{inner1[0], inner1[2], inner1[1]};  // outward
        const perturbation::Keys4 keys{v[0], v[1], v[2], far};
        const Sign in_disk = points_.weighted()
                                 ? perturbation::outer_halfspace_weighted_sos(
                                       wp(v[0]), wp(v[1]), wp(v[2]), wp(behind), wp(far), keys)
                                 : perturbation::outer_halfspace_sos(
                                       p(v[0]), p(v[1]), p(v[2]), p(behind), p(far), keys);
        if (in_disk != Sign::kNeg) {
            problem("coplanar hull triangles at edge (" + std::to_string(from) + " " +
                    std::to_string(to) + ") are not Delaunay in their plane");
        }
    }

    void count_edges() {
        std::vector<std::uint64_t> edges;
        edges.reserve(6 * tets_.size());
        for (const auto& v : tets_) {
            for (int i = 0; i < 4; ++i) {
                for (int j = i + 1; j < 4; ++j) {
                    const auto a =
                        std::min(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(j)]);
                    const auto b =
                        std::max(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(j)]);
                    edges.push_back((static_cast<std::uint64_t>(a) << 32) | b);
                }
            }
        }
        std::sort(edges.begin(), edges.end());
        report_.edges =
            static_cast<std::size_t>(std::unique(edges.begin(), edges.end()) - edges.begin());
    }

    void check_points() {
        const auto first = first_occurrences(points_.points, points_.weights);
        std::vector<std::uint32_t> missing;
        for (std::uint32_t i = 0; i < points_.size(); ++i) {
            if (absent_[i] != 0) {
                if (used_[i] != 0) {
                    problem("point " + std::to_string(i) + " was deleted but is a vertex");
                }
                continue;
            }
            if (used_[i] != 0) {
                if (first[i] != i && used_[first[i]] != 0) {
                    problem("points " + std::to_string(first[i]) + " and " + std::to_string(i) +
                            " are the same point, and both are vertices");
                }
                continue;
            }
            if (first[i] != i) {
                ++report_.duplicates;
                continue;
            }
            if (!points_.weighted()) {
                problem("point " + std::to_string(i) + " is not a vertex of the triangulation");
                continue;
            }
            missing.push_back(i);
        }
        if (!missing.empty()) {
            check_redundant(missing);
        }
    }

    /// A weighted point that is not a vertex must be redundant: in conflict with no tetrahedron.
    /// Tested against every tetrahedron whose closure holds it (brute force over tetrahedra,
    /// fine at the sizes a check is run on).
    void check_redundant(const std::vector<std::uint32_t>& missing) {
        for (std::uint32_t u : missing) {
            bool contained = false;
            bool conflicting = false;
            for (std::size_t t = 0; t < tets_.size() && !conflicting; ++t) {
                const auto& v = tets_[t];
                bool inside = true;
                for (int f = 0; f < 4 && inside; ++f) {
                    const auto tri = facet_vertices(v, f);
                    inside =
                        predicates::orient3d(p(tri[0]), p(tri[1]), p(tri[2]), p(u)) != Sign::kNeg;
                }
                if (inside) {
                    contained = true;
                    conflicting = conflict(t, u) == Sign::kPos;
                }
            }
            if (!contained) {
                problem("point " + std::to_string(u) + " lies outside the triangulation");
            } else if (conflicting) {
                problem("point " + std::to_string(u) +
                        " is not a vertex but is not redundant (it conflicts with a tetrahedron)");
            } else {
                ++report_.redundant;
            }
        }
    }

    const PointSet& points_;
    std::vector<Tet> tets_;
    std::vector<unsigned char> absent_;
    std::vector<unsigned char> used_;
    std::vector<FaceRecord> faces_;
    std::size_t triangles_ = 0;
    ValidationReport report_;
};

}  // namespace

ValidationReport validate(const PointSet& points,
                          std::span<const std::array<std::uint32_t, 4>> tets,
                          std::span<const std::uint32_t> absent) {
    return Validator(points, tets, absent).run();
}

}  // namespace cavity::core
