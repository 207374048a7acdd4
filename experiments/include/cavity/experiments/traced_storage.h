#pragma once

#include "cavity/core/mesh/array_storage.h"
#include "cavity/experiments/memory_model.h"

namespace cavity::experiments {

/// The engine's array storage, reporting every record it reads or writes to a MemoryTrace: the
/// tetrahedron record on each access, and the four point records of a tetrahedron whose vertices
/// are read (the engine reads them to evaluate a predicate). The engine is a template on its
/// storage and calls these members by name, so they replace ArrayStorage's without virtual calls.
/// The one-bit-per-slot liveness array is not traced: at n/8 bytes it stays cached.
class TracedArrayStorage : public core::ArrayStorage {
public:
    explicit TracedArrayStorage(MemoryTrace& trace) : trace_(&trace) {}

    const core::TetVertices& vertices(core::TetId t) const {
        trace_->touch_tet(t);
        const core::TetVertices& v = ArrayStorage::vertices(t);
        for (core::VertexId u : v) {
            if (u != core::kGhostVertex) {
                trace_->touch_point(u);
            }
        }
        return v;
    }

    core::HalfFacet adjacent(core::TetId t, int f) const {
        trace_->touch_tet(t);
        return ArrayStorage::adjacent(t, f);
    }

    void glue(core::HalfFacet a, core::HalfFacet b) {
        trace_->touch_tet(core::tet_of(a));
        trace_->touch_tet(core::tet_of(b));
        ArrayStorage::glue(a, b);
    }

    core::TetId add_tetrahedron(const core::TetVertices& v) {
        const core::TetId t = ArrayStorage::add_tetrahedron(v);
        trace_->touch_tet(t);
        return t;
    }

    void delete_tetrahedron(core::TetId t) {
        trace_->touch_tet(t);
        ArrayStorage::delete_tetrahedron(t);
    }

private:
    MemoryTrace* trace_;
};

}  // namespace cavity::experiments
