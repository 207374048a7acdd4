#include "cavity/core/cdt/cdt_regions.h"

#include <optional>

#include "cavity/core/base/error.h"
#include "tet_flood.h"

namespace cavity::core {

std::vector<std::int32_t> region_markers(const Plc& plc, TetFlood& flood, std::size_t tets) {
    std::vector<std::int32_t> marker(tets, 0);
    for (const PlcRegion& region : plc.regions) {
        const std::optional<std::uint32_t> seed = flood.locate(plc.points, region.point);
        if (!seed) {
            const auto line =
                region.line > 0 ? std::optional<std::size_t>(region.line) : std::nullopt;
            throw Error(located_message(
                plc.source, line, "region point lies outside the tetrahedralization"));
        }
        // An earlier region holding the seed keeps its tetrahedra: the first to reach one wins.
        flood.fill(*seed, [&](std::uint32_t t) { marker[t] = region.marker; });
    }
    return marker;
}

std::vector<std::int32_t> region_markers(const Plc& plc,
                                         std::span<const Tet> tets,
                                         std::span<const CdtFace> faces) {
    if (plc.regions.empty()) {
        return std::vector<std::int32_t>(tets.size(), 0);
    }
    TetFlood flood(tets, faces);
    return region_markers(plc, flood, tets.size());
}

}  // namespace cavity::core
