// Using cavity from C++: triangulate a degenerate point set (a 4x4x4 grid, where every cube's
// eight corners are cospherical), check the result exactly, and print a summary. Exits non-zero
// if anything is wrong, so CI can run it.

#include <cstddef>
#include <cstdio>
#include <exception>

#include "cavity/core/base/error.h"
#include "cavity/core/check/orientation.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/geometry/counters.h"
#include "cavity/core/input/point_set.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/predicates/stage.h"

int main() {
    namespace core = cavity::core;
    core::PointSet grid;
    grid.source = "4x4x4 grid";
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) {
            for (int z = 0; z < 4; ++z) {
                grid.points.push_back({double(x), double(y), double(z)});
            }
        }
    }
    try {
        // The insertion order (BRIO along a Hilbert curve) and the triangulation; the result does
        // not depend on the order: ties are broken by the input index.
        const core::InsertionOrder order = core::make_insertion_order(grid.points, {});
        core::TriangulateOptions options;
        options.count = true;
        const core::Triangulation mesh = core::triangulate(grid, order.sequence, options);

        // Every tetrahedron has positive volume by the right-hand rule, as TetGen and VTK list
        // them: never a flat or inverted one, even on a grid.
        const core::OrientationCount signs = core::count_orientations(grid, mesh.tets);
        const std::size_t not_positive = signs.negative + signs.flat;
        const core::ValidationReport report = core::validate(grid, mesh.tets);
        std::printf("%zu points, %zu tetrahedra, %zu hull triangles, %zu not positive, %s\n",
                    grid.size(),
                    mesh.tets.size(),
                    mesh.hull_triangles,
                    not_positive,
                    report.ok() ? "valid" : "INVALID");
        // Calls decided by the floating-point filters: the static one, then the semi-static one.
        const auto& insphere =
            mesh.counters.stage_calls[static_cast<std::size_t>(core::PredicateKind::kInsphere)];
        const auto decided = [&](cavity::predicates::Stage s) {
            return static_cast<unsigned long long>(insphere[static_cast<std::size_t>(s)]);
        };
        std::printf(
            "work: %llu tetrahedra created, %llu insphere calls decided by the filters "
            "(%llu static, %llu semi-static)\n",
            static_cast<unsigned long long>(mesh.counters.tets_created),
            decided(cavity::predicates::Stage::kStatic) +
                decided(cavity::predicates::Stage::kFilter),
            decided(cavity::predicates::Stage::kStatic),
            decided(cavity::predicates::Stage::kFilter));
        return report.ok() && not_positive == 0 ? 0 : 1;
    } catch (const core::Error& e) {
        std::fprintf(stderr, "tetrahedralize: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tetrahedralize: unexpected: %s\n", e.what());
        return 2;
    }
}
