#include "cavity/core/cdt/read_poly.h"

#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/exact_points_file.h"
#include "cavity/core/io/parse_poly.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

[[noreturn]] void fail_at(const Plc& plc, const PlcFacet& facet, const std::string& what) {
    throw Error(located_message(plc.source, facet.line, what));
}

/// A facet's geometry, decided exactly; fails with the file and the facet's header line.
void check_facet(const Plc& plc, const PlcFacet& facet) {
    const std::string name = "facet " + std::to_string(*facet.number);
    const auto plane = ExactPlane::of_facet(plc, facet);
    if (!plane && !facet.loops.empty()) {
        fail_at(plc, facet, name + ": its corners are collinear");
    }
    for (const auto& loop : facet.loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            if (plane->side(generic_point(plc.points, loop[i])) != predicates::Sign::kZero) {
                fail_at(plc,
                        facet,
                        name + ": corner " + std::to_string(loop[i] + plc.points.index_base) +
                            " is not in the plane of the facet");
            }
            if (exact_point(plc.points, loop[i]) ==
                exact_point(plc.points, loop[(i + 1) % loop.size()])) {
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

Plc read_poly(const std::filesystem::path& file, const std::filesystem::path& exact) {
    Plc plc = parse_poly(file);
    if (!exact.empty()) {
        read_exact_points(exact.string(), plc.points);
    }
    for (const PlcFacet& facet : plc.facets) {
        check_facet(plc, facet);
    }
    return plc;
}

}  // namespace cavity::core
