#include "stats_dict.h"

#include <array>
#include <string>

namespace cavity::python {

py::dict counters_dict(const core::Counters& c) {
    py::dict d;
    d["insertions"] = c.insertions;
    d["tets_created"] = c.tets_created;
    d["tets_deleted"] = c.tets_deleted;
    d["ghosts_created"] = c.ghosts_created;
    d["ghosts_deleted"] = c.ghosts_deleted;
    d["max_cavity"] = c.max_cavity;
    d["dig_tests"] = c.dig_tests;
    d["walk_steps"] = c.walk_steps;
    d["walk_orient_calls"] = c.walk_orient_calls;
    d["walk_fallbacks"] = c.walk_fallbacks;
    d["points_redistributed"] = c.points_redistributed;
    d["redistribution_steps"] = c.redistribution_steps;
    d["duplicates"] = c.duplicates;
    d["redundant"] = c.redundant;
    d["perturbations"] = c.perturbations;
    d["perturbation_cofactors"] = c.perturbation_cofactors;
    d["hash_probes"] = c.hash_probes;
    // Theorem 5.4's conflicts: counted by the full conflict graph (locate="conflict-graph-all"),
    // zero otherwise.
    d["conflicts_created"] = c.conflicts_created;
    d["ghost_conflicts_created"] = c.ghost_conflicts_created;
    d["conflicts_deleted"] = c.conflicts_deleted;
    d["ghost_conflicts_deleted"] = c.ghost_conflicts_deleted;
    d["live_conflicts_max"] = c.live_conflicts_max;
    // Same order as core::PredicateKind.
    constexpr std::array<const char*, core::kPredicateKindCount> kKinds{
        "orient3d", "insphere", "orient4d", "ghost"};
    py::dict stages;
    for (std::size_t k = 0; k < kKinds.size(); ++k) {
        py::dict per_stage;
        for (int s = 0; s < predicates::kStageCount; ++s) {
            per_stage[py::str(
                std::string(predicates::stage_name(static_cast<predicates::Stage>(s))))] =
                c.stage_calls[k][static_cast<std::size_t>(s)];
        }
        stages[kKinds[k]] = per_stage;
    }
    d["stage_calls"] = stages;
    return d;
}

}  // namespace cavity::python
