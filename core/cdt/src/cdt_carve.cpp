#include "cavity/core/cdt/cdt_carve.h"

#include <optional>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt_regions.h"
#include "tet_flood.h"

namespace cavity::core {

namespace {

[[noreturn]] void refuse_hole(const Plc& plc, const PlcVolumeHole& hole, const std::string& why) {
    const auto line = hole.line > 0 ? std::optional<std::size_t>(hole.line) : std::nullopt;
    throw Error(located_message(plc.source, line, "volume hole point " + why));
}

/// Which tetrahedra the holes and (unless convex_hull) the exterior remove; the hole points are
/// checked either way.
std::vector<bool> removed_tets(const Cdt& cdt, bool convex_hull) {
    const auto& pts = cdt.plc.points;
    std::vector<bool> removed(cdt.tets.size(), false);
    TetFlood flood(cdt.tets, cdt.faces);
    const auto remove = [&](std::uint32_t t) { removed[t] = true; };
    for (const PlcVolumeHole& hole : cdt.plc.volume_holes) {
        const std::optional<std::uint32_t> seed = flood.locate(pts, hole.point);
        if (!seed) {
            refuse_hole(cdt.plc, hole, "lies outside the tetrahedralization (the convex hull)");
        }
        if (flood.on_wall(pts, hole.point)) {
            refuse_hole(cdt.plc, hole, "lies on a polygon: it does not say which side is a hole");
        }
        if (!convex_hull) {
            flood.fill(*seed, remove);
        }
    }
    if (!convex_hull) {
        for (std::uint32_t seed : flood.open_hull_tets()) {
            flood.fill(seed, remove);
        }
    }
    return removed;
}

}  // namespace

CarvedCdt carve_cdt(const Cdt& cdt, bool convex_hull) {
    // The whole hull without hole points to check needs no flood (nor its O(T) hash table).
    const std::vector<bool> removed = convex_hull && cdt.plc.volume_holes.empty()
                                          ? std::vector<bool>(cdt.tets.size(), false)
                                          : removed_tets(cdt, convex_hull);
    const std::vector<std::int32_t> markers = region_markers(cdt.plc, cdt.tets, cdt.faces);
    CarvedCdt out;
    for (std::size_t t = 0; t < cdt.tets.size(); ++t) {
        if (removed[t]) {
            ++out.removed;
            continue;
        }
        out.tets.push_back(cdt.tets[t]);
        out.regions.push_back(markers[t]);
    }
    return out;
}

}  // namespace cavity::core
