#pragma once

#include <concepts>

#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// What the insertion loop (insertion_driver.h) asks of a point locator, for an engine type
/// `Engine` (a BowyerWatson): `start` once after the bootstrap; `locate` a tetrahedron from which
/// the conflict search for vertex u starts (one in conflict with u, or one whose region holds u);
/// then `after_insertion` when u was inserted, or `skip` when it was not (a redundant weighted
/// point). The walks (WalkingLocator), the book's conflict graph (ConflictGraph) and the full
/// conflict graph (FullConflictGraph) are the locators; a locator may also offer `tally()`, its
/// own count of conflicts, which the loop checks against the conflict counter's.
template <class L, class Engine>
concept Locator = requires(L locator, Engine& engine, VertexId u) {
    locator.start(engine);
    { locator.locate(engine, u) } -> std::same_as<TetId>;
    locator.after_insertion(engine, u);
    locator.skip(engine, u);
};

}  // namespace cavity::core
