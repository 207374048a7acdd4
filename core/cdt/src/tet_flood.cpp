#include "tet_flood.h"

#include <algorithm>

#include "cavity/core/mesh/tetrahedron.h"
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

std::size_t TetFlood::KeyHash::operator()(const Key& k) const {
    std::uint64_t h = k[0];
    h = h * 0x9E37'79B9'7F4A'7C15ull ^ k[1];
    h = h * 0x9E37'79B9'7F4A'7C15ull ^ k[2];
    return static_cast<std::size_t>(h ^ (h >> 29));
}

TetFlood::Key TetFlood::facet_key(const Tet& t, int f) {
    const auto& s = kFacetVertices[static_cast<std::size_t>(f)];
    Key k{t[static_cast<std::size_t>(s[0])],
          t[static_cast<std::size_t>(s[1])],
          t[static_cast<std::size_t>(s[2])]};
    std::sort(k.begin(), k.end());
    return k;
}

TetFlood::TetFlood(std::span<const Tet> tets, std::span<const CdtFace> faces)
    : tets_(tets), reached_(tets.size(), false) {
    for (const CdtFace& f : faces) {
        Key k = f.v;
        std::sort(k.begin(), k.end());
        walls_.insert(k);
    }
    sides_.reserve(2 * tets.size());
    for (std::uint32_t t = 0; t < tets.size(); ++t) {
        for (int f = 0; f < 4; ++f) {
            auto [it, fresh] = sides_.try_emplace(facet_key(tets[t], f), std::array{t, t});
            if (!fresh) {
                it->second[1] = t;
            }
        }
    }
}

std::optional<std::uint32_t> TetFlood::across(std::uint32_t t, int f) const {
    const Key k = facet_key(tets_[t], f);
    if (walls_.contains(k)) {
        return std::nullopt;
    }
    const auto& two = sides_.at(k);
    const std::uint32_t other = two[0] == t ? two[1] : two[0];
    if (other == t) {
        return std::nullopt;
    }
    return other;
}

std::vector<std::uint32_t> TetFlood::open_hull_tets() const {
    std::vector<std::uint32_t> seeds;
    for (std::uint32_t t = 0; t < tets_.size(); ++t) {
        for (int f = 0; f < 4; ++f) {
            const Key k = facet_key(tets_[t], f);
            const auto& two = sides_.at(k);
            if (two[0] == two[1] && !walls_.contains(k)) {
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
    for (const Tet& t : tets_) {
        const auto zero = zero_faces(pts, t, p);
        if (!zero) {
            continue;
        }
        // p is in the closed tetrahedron, so it lies on facet f exactly when replacing the
        // vertex opposite f by p leaves the volume zero.
        for (int f = 0; f < 4; ++f) {
            if ((*zero)[static_cast<std::size_t>(f)] && walls_.contains(facet_key(t, f))) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace cavity::core
