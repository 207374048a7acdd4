#include "cavity/core/cdt/cdt_carve.h"

#include <optional>
#include <string>

#include "cavity/core/base/error.h"
#include "tet_flood.h"

namespace cavity::core {

namespace {

[[noreturn]] void refuse_hole(const Plc& plc, const PlcVolumeHole& hole, const std::string& why) {
    const auto line = hole.line > 0 ? std::optional<std::size_t>(hole.line) : std::nullopt;
    throw Error(located_message(plc.source, line, "volume hole point " + why));
}

/// Which tetrahedra the holes and (unless convex_hull) the exterior remove; the hole points are
/// checked either way. Leaves the tetrahedra it removed reached in `flood`.
std::vector<bool> removed_tets(const Cdt& cdt, bool convex_hull, TetFlood& flood) {
    const auto& pts = cdt.plc.points;
    std::vector<bool> removed(cdt.tets.size(), false);
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
    // The whole hull without hole points to check, and without regions, needs no flood (nor its
    // facet matching); carving and the regions share one.
    const bool carves = !convex_hull || !cdt.plc.volume_holes.empty();
    std::optional<TetFlood> flood;
    if (carves || !cdt.plc.regions.empty()) {
        flood.emplace(cdt.tets, cdt.faces);
    }
    const std::vector<bool> removed =
        carves ? removed_tets(cdt, convex_hull, *flood) : std::vector<bool>(cdt.tets.size(), false);
    std::vector<std::int32_t> markers(cdt.tets.size(), 0);
    if (!cdt.plc.regions.empty()) {
        flood->forget_reached();
        markers = region_markers(cdt.plc, *flood, cdt.tets.size());
    }
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
