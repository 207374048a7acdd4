#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "cavity/core/edit/retriangulation_counters.h"
#include "cavity/core/geometry/geometry.h"

namespace cavity::core::detail {

/// The dictionary of unfinished facets and the apex choice shared by both gift-wrapping entry
/// points. A facet is stored as seen from its finished side (the finished tetrahedron's apex on
/// its positive side); the tetrahedron built on it lies on its negative side.
class GiftWrapEngine {
public:
    using Triangle = std::array<VertexId, 3>;

    GiftWrapEngine(const Geometry& geometry,
                   std::span<const VertexId> candidates,
                   bool ghost_allowed,
                   RetriangulationCounters& counters)
        : geometry_(geometry)
        , candidates_(candidates)
        , ghost_allowed_(ghost_allowed)
        , counters_(counters) {}

    /// Enters a facet as unfinished, or finishes it when its other side is already unfinished.
    /// `apex` is the fourth vertex of the finished tetrahedron (kNoVertex if unknown).
    /// \throws Error when the same side is entered twice (the tetrahedra would overlap).
    void offer(const Triangle& seen_from_finished_side, VertexId apex);

    /// Builds tetrahedra until no facet is unfinished. A finite facet with no candidate in front
    /// is a hull triangle: closed by a ghost tetrahedron when ghosts are allowed, else counted.
    /// \throws Error when a ghost facet has no candidate.
    void run();

    const std::vector<TetVertices>& tets() const { return tets_; }

    std::size_t hull_triangles() const { return hull_triangles_; }

private:
    struct TriangleHash {
        std::size_t operator()(const Triangle& t) const {
            return (std::size_t{t[0]} * 0x9E3779B97F4A7C15ull) ^
                   (std::size_t{t[1]} * 0xC2B2AE3D27D4EB4Full) ^ std::size_t{t[2]};
        }
    };

    VertexId solid_apex(const Triangle& f);
    VertexId ghost_apex(const TetVertices& partial, VertexId behind_apex);
    bool in_outer_halfspace(const TetVertices& ghost, VertexId u);

    const Geometry& geometry_;
    std::span<const VertexId> candidates_;
    bool ghost_allowed_;
    RetriangulationCounters& counters_;

    struct Unfinished {
        Triangle seen;  // oriented, from the finished side
        VertexId apex;  // of the finished tetrahedron
    };

    std::unordered_map<Triangle, Unfinished, TriangleHash> unfinished_;  // sorted key -> facet
    std::vector<Triangle> stack_;
    std::vector<TetVertices> tets_;
    std::size_t hull_triangles_ = 0;
};

}  // namespace cavity::core::detail
