#include "cavity/core/check/orientation.h"

#include "cavity/core/base/error.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {

OrientationCount count_orientations(const PointSet& points, std::span<const Tet> tets) {
    OrientationCount count;
    for (const Tet& t : tets) {
        if (t[0] >= points.size() || t[1] >= points.size() || t[2] >= points.size() ||
            t[3] >= points.size()) {
            continue;
        }
        // orient3d(a, b, c, d) > 0 exactly when the right-hand volume det[b−a, c−a, d−a] < 0.
        // Implicit points (a CDT's Steiner points) by their exact definitions.
        const predicates::Sign sign = points.exact.empty()
                                          ? predicates::orient3d(points.points[t[0]],
                                                                 points.points[t[1]],
                                                                 points.points[t[2]],
                                                                 points.points[t[3]])
                                          : predicates::orient3d(points.exact[t[0]],
                                                                 points.exact[t[1]],
                                                                 points.exact[t[2]],
                                                                 points.exact[t[3]]);
        switch (sign) {
            case predicates::Sign::kPos:
                ++count.negative;
                break;
            case predicates::Sign::kNeg:
                ++count.positive;
                break;
            case predicates::Sign::kZero:
                ++count.flat;
                break;
        }
    }
    return count;
}

void refuse_inverted_mesh(const std::string& file,
                          const PointSet& points,
                          std::span<const Tet> tets) {
    const OrientationCount count = count_orientations(points, tets);
    if (count.negative > 0 && count.positive == 0) {
        throw Error(located_message(
            file,
            std::nullopt,
            "all " + std::to_string(count.negative) +
                " non-flat tetrahedra have negative volume by the right-hand rule (orient3d > 0, "
                "the orientation cavity wrote before version 0.2); TetGen, VTK and cavity now "
                "write positive volume: swap two vertices of each tetrahedron"));
    }
}

}  // namespace cavity::core
