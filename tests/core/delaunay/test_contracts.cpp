// The engine's declared contracts (mesh/tet_storage.h, delaunay/observer.h, delaunay/locator.h):
// every storage, observer and locator of the library models its concept, and types that lack a
// member do not, so the engine's static_asserts reject them with the concept's name.

#include <gtest/gtest.h>

#include "cavity/core/delaunay/bowyer_watson.h"
#include "cavity/core/delaunay/conflict_counter.h"
#include "cavity/core/delaunay/locator.h"
#include "cavity/core/delaunay/observer.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/mesh/array_storage.h"
#include "cavity/core/mesh/face_hash_storage.h"
#include "cavity/core/mesh/tet_storage.h"

namespace cavity::test {
namespace {

using core::ArrayStorage;
using core::BowyerWatson;
using core::FaceHashStorage;

static_assert(core::TetStorage<ArrayStorage>);
static_assert(core::TetStorage<FaceHashStorage>);

// A store without gluing or ids of its own is not a TetStorage.
struct NoAdjacency {
    void reserve(std::size_t, std::size_t) {}

    core::TetId add_tetrahedron(const core::TetVertices&) { return 0; }
};

static_assert(!core::TetStorage<NoAdjacency>);

static_assert(core::EngineObserver<core::NullObserver>);
static_assert(core::EngineObserver<core::CountingObserver>);
static_assert(core::EngineObserver<core::ConflictCountingObserver>);

// Hooks without the counting flags: not an observer the engine can compile out.
struct HooksOnly {
    void on_start(const core::Geometry&) {}

    void on_finish() {}
};

static_assert(!core::EngineObserver<HooksOnly>);

template <class Storage, class Observer>
constexpr bool all_locators() {
    using Engine = BowyerWatson<Storage, Observer>;
    return core::Locator<core::detail::WalkLocator, Engine> &&
           core::Locator<core::detail::StraightWalkLocator, Engine> &&
           core::Locator<core::ConflictGraph, Engine> &&
           core::Locator<core::FullConflictGraph, Engine>;
}

static_assert(all_locators<ArrayStorage, core::NullObserver>());
static_assert(all_locators<FaceHashStorage, core::CountingObserver>());

// A locator that cannot be told about insertions would lose track of the mesh.
struct LocateOnly {
    template <class Engine>
    core::TetId locate(Engine&, core::VertexId) {
        return 0;
    }
};

static_assert(!core::Locator<LocateOnly, BowyerWatson<ArrayStorage, core::NullObserver>>);

// The checks above are compile-time; this records that the file was built and run.
TEST(Contracts, LibraryTypesModelTheirConcepts) {
    SUCCEED();
}

}  // namespace
}  // namespace cavity::test
