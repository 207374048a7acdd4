#include "cavity/core/live/triangulate.h"

namespace cavity::core {

Triangulation triangulate(const PointSet& points,
                          std::span<const std::uint32_t> sequence,
                          const TriangulateOptions& options) {
    Triangulation out;
    detail::with_observer(options, [&](auto& observer) {
        out = triangulate_observed(points, sequence, options, observer);
    });
    return out;
}

}  // namespace cavity::core
