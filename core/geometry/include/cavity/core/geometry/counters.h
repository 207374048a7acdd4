#pragma once

#include <array>
#include <concepts>
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

/// Which writers show a counter: conflicts only mean something in a run that counted them.
enum class CounterGroup { kEngine, kConflicts };

/// Every scalar counter, one line each: its name (the field of Counters and the key of every
/// output: the CLI's --stats JSON, Python's stats), its group, and what it counts. Adding a
/// counter is adding its line here; the field and its row in kCounterFields follow.
// A macro because C++20 cannot enumerate a struct's fields: the struct and the table are both
// generated from this one list.
#define CAVITY_COUNTERS(X)                                                                         \
    X(insertions, kEngine)             /* points inserted (not the bootstrap four) */              \
    X(tets_created, kEngine)           /* solid tetrahedra created (Theorem 5.4) */                \
    X(tets_deleted, kEngine)           /* solid tetrahedra deleted */                              \
    X(ghosts_created, kEngine)         /* ghost tetrahedra created */                              \
    X(ghosts_deleted, kEngine)         /* ghost tetrahedra deleted */                              \
    X(max_cavity, kEngine)             /* most tetrahedra deleted by one insertion */              \
    X(dig_tests, kEngine)              /* conflict tests in DigCavity3D */                         \
    X(walk_steps, kEngine)             /* tetrahedra visited by walking point location */          \
    X(walk_orient_calls, kEngine)      /* orient3d calls made by the walk */                       \
    X(walk_fallbacks, kEngine)         /* straight-line walks finished by the visibility walk */   \
    X(points_redistributed, kEngine)   /* conflict graph: uninserted points moved to a new cell */ \
    X(redistribution_steps, kEngine)   /* conflict graph: cells visited while moving them */       \
    X(duplicates, kEngine)             /* input points repeating an earlier one, not inserted */   \
    X(redundant, kEngine)              /* weighted points that are not vertices (submerged) */     \
    X(perturbations, kEngine)          /* perturbed predicates that needed the tie-break */        \
    X(perturbation_cofactors, kEngine) /* cofactors the tie-breaks evaluated */                    \
    X(hash_probes, kEngine)            /* face hash table probes (hash storage only) */            \
    X(conflicts_created, kConflicts)   /* Σj over created solid tetrahedra (Theorem 5.4) */       \
    X(ghost_conflicts_created, kConflicts) /* the same over created ghosts */                      \
    X(conflicts_deleted, kConflicts)       /* Σj over deleted solid tetrahedra */                 \
    X(ghost_conflicts_deleted, kConflicts) /* the same over deleted ghosts */                      \
    X(live_conflicts_max, kConflicts)      /* most live conflicts, solid and ghost, at once */     \
    X(conflict_tests, kConflicts) /* exact tests the counting made (its cost, not the engine's) */

/// Work done by one run, summed over insertions. Everything the chapter's analysis counts:
/// tetrahedra created and deleted (Theorem 5.4), conflicts (Proposition 5.1-5.3 via Σ j), walk
/// steps (§5.5), predicate calls by deciding stage and perturbation invocations. The conflicts
/// are counted only by ConflictCountingObserver (conflict_counter.h): j of a solid tetrahedron
/// is the number of input points in its open (perturbed) circumball, a ghost's the points in
/// front of its hull triangle; deleted tetrahedra's conflicts are all still uninserted when they
/// die; live conflicts are what a conflict graph keeping every conflict stores.
///
/// Counters is also the tally the geometric tests record their deciding stage in (see Tally).
struct Counters {
    static constexpr bool kCounting = true;

#define CAVITY_COUNTER_FIELD(name, group) std::uint64_t name = 0;
    CAVITY_COUNTERS(CAVITY_COUNTER_FIELD)
#undef CAVITY_COUNTER_FIELD

    /// [predicate kind][stage]: calls decided at that stage.
    std::array<std::array<std::uint64_t, predicates::kStageCount>, kPredicateKindCount>
        stage_calls{};

    void count_predicate(PredicateKind kind, predicates::Stage stage, std::uint64_t calls = 1) {
        stage_calls[static_cast<std::size_t>(kind)][static_cast<std::size_t>(stage)] += calls;
    }
};

/// The tally of code that does not count: the engine without a counting observer, flips,
/// gift-wrapping, the CDT and the validators. Tests given it compile to the plain predicates.
struct Uncounted {
    static constexpr bool kCounting = false;
};

/// Where a geometric test records the stage that decided it, chosen at compile time: Counters in
/// the counting engine, Uncounted everywhere else. The one counting mechanism of the engine, its
/// walks and its tests: no pointer is checked at run time.
template <class T>
concept Tally = std::same_as<T, Counters> || std::same_as<T, Uncounted>;

/// One scalar counter of Counters, by the name every output uses.
struct CounterField {
    std::string_view name;
    std::uint64_t Counters::*field;
    CounterGroup group;
};

/// Every scalar counter, in CAVITY_COUNTERS's order: the CLI's --stats JSON and Python's stats
/// are written from this table (the per-stage counts follow it).
inline constexpr std::array kCounterFields{
#define CAVITY_COUNTER_ROW(name, group) CounterField{#name, &Counters::name, CounterGroup::group},
    CAVITY_COUNTERS(CAVITY_COUNTER_ROW)
#undef CAVITY_COUNTER_ROW
};

// The table and the struct come from the same list; a field declared outside it would be
// missing from every output.
static_assert(sizeof(Counters) ==
                  kCounterFields.size() * sizeof(std::uint64_t) + sizeof(Counters::stage_calls),
              "every scalar counter of Counters comes from CAVITY_COUNTERS");

/// What one insertion did, handed to observers after it completes.
struct InsertionRecord {
    std::uint32_t vertex;  ///< input index of the inserted point
    std::uint64_t step;    ///< 0-based position in the insertion sequence
    std::uint32_t created;
    std::uint32_t deleted;
    std::uint32_t walk_steps;
};

}  // namespace cavity::core
