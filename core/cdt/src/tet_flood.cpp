#include "tet_flood.h"

#include <algorithm>

#include "cavity/core/io/tet_adjacency.h"
#include "cavity/predicates/generic_predicates.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

/// Which of p's four replacements of a vertex of t (positive right-hand volume: orient3d < 0)
/// are zero, or none when one is positive and p is outside the closed tetrahedron.
std::optional<std::array<bool, 4>> zero_faces(const PointSet& pts, const Tet& t, const Point3& p) {
    std::array<bool, 4> zero{};
    for (std::size_t i = 0; i < 4; ++i) {
        std::array<predicates::GenericPoint3, 4> q{generic_point(pts, t[0]),
                                                   generic_point(pts, t[1]),
                                                   generic_point(pts, t[2]),
                                                   generic_point(pts, t[3])};
        q[i] = p;
        const predicates::Sign s = predicates::orient3d(q[0], q[1], q[2], q[3]);
        if (s == predicates::Sign::kPos) {
            return std::nullopt;
        }
        zero[i] = s == predicates::Sign::kZero;
    }
    return zero;
}

}  // namespace

TetFlood::TetFlood(std::span<const Tet> tets, std::span<const CdtFace> faces)
    : tets_(tets), reached_(tets.size(), false) {
    std::size_t point_count = 0;
    for (const Tet& t : tets) {
        point_count = std::max(point_count, std::size_t{*std::max_element(t.begin(), t.end())} + 1);
    }
    across_ = match_facets(tets, point_count);
    // A wall is found among the tetrahedra at its corner with the fewest: a counting sort of the
    // tetrahedra by vertex, then a short scan per polygon triangle.
    std::vector<std::uint32_t> begin(point_count + 1, 0);
    for (const Tet& t : tets) {
        for (std::uint32_t v : t) {
            ++begin[v + 1];
        }
    }
    for (std::size_t v = 1; v < begin.size(); ++v) {
        begin[v] += begin[v - 1];
    }
    std::vector<std::uint32_t> incident(begin.back());
    {
        std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
        for (std::uint32_t t = 0; t < tets.size(); ++t) {
            for (std::uint32_t v : tets[t]) {
                incident[next[v]++] = t;
            }
        }
    }
    const auto degree = [&](std::uint32_t v) { return begin[v + 1] - begin[v]; };
    for (const CdtFace& face : faces) {
        const auto [a, b, c] = face.v;
        if (std::max({a, b, c}) >= point_count) {
            continue;  // a corner on no tetrahedron: no facet to block
        }
        const std::uint32_t scan = std::min(
            {a, b, c}, [&](std::uint32_t u, std::uint32_t w) { return degree(u) < degree(w); });
        for (std::uint32_t k = begin[scan]; k < begin[scan + 1]; ++k) {
            const std::uint32_t t = incident[k];
            const Tet& tet = tets[t];
            // The facet is opposite the one slot whose vertex is not a corner of the face.
            int corners = 0;
            std::size_t outside = 0;
            for (std::size_t s = 0; s < 4; ++s) {
                const bool corner = tet[s] == a || tet[s] == b || tet[s] == c;
                corners += corner ? 1 : 0;
                outside = corner ? outside : s;
            }
            if (corners == 3) {
                across_[4 * std::size_t{t} + outside] = kWall;
            }
        }
    }
}

std::vector<std::uint32_t> TetFlood::open_hull_tets() const {
    std::vector<std::uint32_t> seeds;
    for (std::uint32_t t = 0; t < tets_.size(); ++t) {
        for (std::size_t f = 0; f < 4; ++f) {
            if (across_[4 * std::size_t{t} + f] == kOpen) {
                seeds.push_back(t);
                break;
            }
        }
    }
    return seeds;
}

std::optional<std::uint32_t> TetFlood::locate(const PointSet& pts, const Point3& p) const {
    for (std::uint32_t t = 0; t < tets_.size(); ++t) {
        if (zero_faces(pts, tets_[t], p)) {
            return t;
        }
    }
    return std::nullopt;
}

bool TetFlood::on_wall(const PointSet& pts, const Point3& p) const {
    for (std::size_t t = 0; t < tets_.size(); ++t) {
        const auto zero = zero_faces(pts, tets_[t], p);
        if (!zero) {
            continue;
        }
        // p is in the closed tetrahedron, so it lies on facet f exactly when replacing the
        // vertex opposite f by p leaves the volume zero.
        for (std::size_t f = 0; f < 4; ++f) {
            if ((*zero)[f] && across_[4 * t + f] == kWall) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace cavity::core
