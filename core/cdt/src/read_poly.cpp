#include "cavity/core/cdt/read_poly.h"

#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/io/parse_poly.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

[[noreturn]] void fail_at(const Plc& plc, const PlcFacet& facet, const std::string& what) {
    throw Error(located_message(plc.source, facet.line, what));
}

/// A facet's geometry, decided exactly; fails with the file and the facet's header line.
void check_facet(const Plc& plc, const PlcFacet& facet) {
    const std::string name = "facet " + std::to_string(facet.number);
    const auto plane = ExactPlane::of_facet(plc, facet);
    if (!plane && !facet.loops.empty()) {
        fail_at(plc, facet, name + ": its corners are collinear");
    }
    for (const auto& loop : facet.loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            if (plane->side(plc.points.points[loop[i]]) != predicates::Sign::kZero) {
                fail_at(plc,
                        facet,
                        name + ": corner " + std::to_string(loop[i] + plc.points.index_base) +
                            " is not in the plane of the facet");
            }
            const auto& p = plc.points.points[loop[i]];
            const auto& q = plc.points.points[loop[(i + 1) % loop.size()]];
            if (p.x == q.x && p.y == q.y && p.z == q.z) {
                fail_at(plc, facet, name + ": a loop has two equal consecutive corners");
            }
        }
    }
    for (std::size_t h = 0; h < facet.holes.size(); ++h) {
        const std::string hole =
            name + ": hole point " +
            std::to_string(h + static_cast<std::size_t>(plc.points.index_base));
        if (!plane) {
            continue;
        }
        if (plane->side(facet.holes[h]) != predicates::Sign::kZero) {
            fail_at(plc, facet, hole + " is not in the plane of the facet");
        }
        for (const auto& loop : facet.loops) {
            if (loop_position(plc, loop, plane->dropped_axis(), exact_point(facet.holes[h])) ==
                LoopPosition::kOnBoundary) {
                fail_at(plc,
                        facet,
                        hole +
                            " lies on a polygon side, so the face it removes is "
                            "ambiguous");
            }
        }
    }
}

}  // namespace

Plc read_poly(const std::filesystem::path& file) {
    Plc plc = parse_poly(file);
    for (const PlcFacet& facet : plc.facets) {
        check_facet(plc, facet);
    }
    return plc;
}

}  // namespace cavity::core
