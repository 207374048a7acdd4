#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "cavity/core/input/plc.h"

/// Families of piecewise linear complexes of growing size, for the polygon-insertion experiments
/// (Cheng, Dey & Shewchuk §5.8, Propositions 5.5-5.6). Every coordinate is a dyadic rational with
/// few bits, so the midpoints that edge protection inserts stay exact, and no free point lies in
/// the plane of a polygon it could touch (the PLCs are valid by construction). The result depends
/// only on (family, n, seed).
namespace cavity::experiments {

struct PlcFamily {
    std::string_view name;
    std::string_view description;
};

/// Every family make_plc_family() knows, in a fixed order.
std::span<const PlcFamily> plc_families();

/// A PLC of the named family with about n points (before edge protection).
/// \throws core::Error for an unknown family or n < 8.
core::Plc make_plc_family(std::string_view family, std::size_t n, std::uint64_t seed);

}  // namespace cavity::experiments
