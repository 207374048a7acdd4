#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "cavity/predicates/stage.h"

namespace cavity::core {

/// The predicates the engine evaluates, for per-stage counts.
enum class PredicateKind : std::uint8_t { kOrient3d = 0, kInsphere = 1, kOrient4d = 2, kGhost = 3 };

inline constexpr int kPredicateKindCount = 4;

/// Names of PredicateKind, in its order (the --stats JSON's and Python's keys).
inline constexpr std::array<std::string_view, kPredicateKindCount> kPredicateKindNames{
    "orient3d", "insphere", "orient4d", "ghost"};

/// Work done by one run, summed over insertions. Everything the chapter's analysis counts:
/// tetrahedra created and deleted (Theorem 5.4), conflicts (Proposition 5.1-5.3 via Σ j), walk
/// steps (§5.5), predicate calls by deciding stage and perturbation invocations.
struct Counters {
    std::uint64_t insertions = 0;
    std::uint64_t tets_created = 0;
    std::uint64_t tets_deleted = 0;
    std::uint64_t ghosts_created = 0;
    std::uint64_t ghosts_deleted = 0;
    std::uint64_t max_cavity = 0;         ///< most tetrahedra deleted by one insertion
    std::uint64_t dig_tests = 0;          ///< conflict tests in DigCavity3D
    std::uint64_t walk_steps = 0;         ///< tetrahedra visited by walking point location
    std::uint64_t walk_orient_calls = 0;  ///< orient3d calls made by the walk
    std::uint64_t walk_fallbacks = 0;     ///< straight-line walks finished by the visibility walk
    std::uint64_t points_redistributed =
        0;  ///< conflict graph: uninserted points moved to a new cell
    std::uint64_t redistribution_steps = 0;  ///< conflict graph: cells visited while moving them
    std::uint64_t duplicates = 0;     ///< input points repeating an earlier one, not inserted
    std::uint64_t redundant = 0;      ///< weighted points that are not vertices (submerged)
    std::uint64_t perturbations = 0;  ///< perturbed predicates that needed the tie-break
    std::uint64_t perturbation_cofactors = 0;
    std::uint64_t hash_probes = 0;
    /// Conflicts (Theorem 5.4), counted only by ConflictCountingObserver (conflict_counter.h).
    /// conflicts_created is Σj over created solid tetrahedra, j = the input points in the open
    /// (perturbed) circumball; ghosts' conflicts, the points in front of their hull triangle, are
    /// counted apart. Deleted: the same sums over deleted tetrahedra, whose conflicts are all still
    /// uninserted when they die. Live: what a conflict graph keeping every conflict stores.
    std::uint64_t conflicts_created = 0;
    std::uint64_t ghost_conflicts_created = 0;
    std::uint64_t conflicts_deleted = 0;
    std::uint64_t ghost_conflicts_deleted = 0;
    std::uint64_t live_conflicts_max =
        0;  ///< most live conflicts (solid and ghost) after an insertion
    std::uint64_t conflict_tests =
        0;  ///< exact tests the counting made (its cost, not the engine's)
    /// [predicate kind][stage]: calls decided at that stage.
    std::array<std::array<std::uint64_t, predicates::kStageCount>, kPredicateKindCount>
        stage_calls{};

    void count_predicate(PredicateKind kind, predicates::Stage stage) {
        ++stage_calls[static_cast<std::size_t>(kind)][static_cast<std::size_t>(stage)];
    }
};

/// Which writers show a counter: conflicts only mean something in a run that counted them.
enum class CounterGroup { kEngine, kConflicts };

/// One scalar counter of Counters, by the name every output uses.
struct CounterField {
    std::string_view name;
    std::uint64_t Counters::*field;
    CounterGroup group;
};

/// Every scalar counter, in the order outputs list them: the CLI's --stats JSON and Python's
/// stats are written from this table (the per-stage counts follow it), so a new counter is its
/// field above and its row here.
inline constexpr std::array<CounterField, 23> kCounterFields{{
    {"insertions", &Counters::insertions, CounterGroup::kEngine},
    {"tets_created", &Counters::tets_created, CounterGroup::kEngine},
    {"tets_deleted", &Counters::tets_deleted, CounterGroup::kEngine},
    {"ghosts_created", &Counters::ghosts_created, CounterGroup::kEngine},
    {"ghosts_deleted", &Counters::ghosts_deleted, CounterGroup::kEngine},
    {"max_cavity", &Counters::max_cavity, CounterGroup::kEngine},
    {"dig_tests", &Counters::dig_tests, CounterGroup::kEngine},
    {"walk_steps", &Counters::walk_steps, CounterGroup::kEngine},
    {"walk_orient_calls", &Counters::walk_orient_calls, CounterGroup::kEngine},
    {"walk_fallbacks", &Counters::walk_fallbacks, CounterGroup::kEngine},
    {"points_redistributed", &Counters::points_redistributed, CounterGroup::kEngine},
    {"redistribution_steps", &Counters::redistribution_steps, CounterGroup::kEngine},
    {"duplicates", &Counters::duplicates, CounterGroup::kEngine},
    {"redundant", &Counters::redundant, CounterGroup::kEngine},
    {"perturbations", &Counters::perturbations, CounterGroup::kEngine},
    {"perturbation_cofactors", &Counters::perturbation_cofactors, CounterGroup::kEngine},
    {"hash_probes", &Counters::hash_probes, CounterGroup::kEngine},
    {"conflicts_created", &Counters::conflicts_created, CounterGroup::kConflicts},
    {"ghost_conflicts_created", &Counters::ghost_conflicts_created, CounterGroup::kConflicts},
    {"conflicts_deleted", &Counters::conflicts_deleted, CounterGroup::kConflicts},
    {"ghost_conflicts_deleted", &Counters::ghost_conflicts_deleted, CounterGroup::kConflicts},
    {"live_conflicts_max", &Counters::live_conflicts_max, CounterGroup::kConflicts},
    {"conflict_tests", &Counters::conflict_tests, CounterGroup::kConflicts},
}};

// A field added to Counters without its row would be missing from every output.
static_assert(sizeof(Counters) ==
                  kCounterFields.size() * sizeof(std::uint64_t) + sizeof(Counters::stage_calls),
              "every scalar counter of Counters has a row in kCounterFields");

/// What one insertion did, handed to observers after it completes.
struct InsertionRecord {
    std::uint32_t vertex;  ///< input index of the inserted point
    std::uint64_t step;    ///< 0-based position in the insertion sequence
    std::uint32_t created;
    std::uint32_t deleted;
    std::uint32_t walk_steps;
};

}  // namespace cavity::core
