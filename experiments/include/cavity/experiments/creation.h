#pragma once

#include <cstdint>
#include <map>
#include <span>

#include "cavity/core/input/point_set.h"

/// The exact creation rule of §5.4, checked tetrahedron by tetrahedron on one run.
namespace cavity::experiments {

struct CreationAudit {
    /// j (perturbed circumball count over all points) -> solid tetrahedra created with that j.
    std::map<std::uint64_t, std::uint64_t> created_by_j;
    /// Created solid tetrahedra breaking the rule: its four vertices must all precede all its
    /// stoppers, it must be created at the insertion of its last vertex (step 0 for the first
    /// tetrahedron) and deleted at the insertion of its first stopper (never, without stoppers).
    std::uint64_t violations = 0;
};

/// Triangulates `points` in `sequence` order with the life-cycle observer (walking, array
/// storage) and audits every created solid tetrahedron against all points: O(created · n)
/// squared distances to a certified circumcentre, the exact perturbed insphere test for the points
/// the certificate leaves undecided (near the sphere), for small n. Generic input (no repeats) is
/// assumed by the rule.
CreationAudit audit_creation(const core::PointSet& points, std::span<const std::uint32_t> sequence);

}  // namespace cavity::experiments
