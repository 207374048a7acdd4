#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"

/// Pieces shared by the cofactor cascades of the perturbed predicates.
namespace cavity::perturbation {

/// The argument positions sorted by increasing key: the order in which the perturbation terms
/// dominate (the lowest key has the lowest power of eps). Depends only on the keys, never on where
/// the points are stored or when they were inserted.
template <std::size_t N>
std::array<std::uint8_t, N> key_order(const std::array<std::uint32_t, N>& keys) {
    // Insertion sort: for five elements it beats std::sort's dispatch, and the cascade runs on
    // every exact tie (a large share of the calls on grids).
    std::array<std::uint8_t, N> order{};
    for (std::size_t i = 0; i < N; ++i) {
        std::size_t j = i;
        for (; j > 0 && keys[order[j - 1]] > keys[i]; --j) {
            order[j] = order[j - 1];
        }
        order[j] = static_cast<std::uint8_t>(i);
    }
    return order;
}

/// The sign a cofactor cascade settled on and how many orient3d cofactors it evaluated.
struct Resolution {
    predicates::Sign sign;
    std::uint8_t cofactors;
};

/// The rows other than row `skipped`, in row order.
template <class P, std::size_t N>
std::array<P, N - 1> other_rows(const std::array<P, N>& rows, std::size_t skipped) {
    std::array<P, N - 1> others{};
    std::size_t n = 0;
    for (std::size_t j = 0; j < N; ++j) {
        if (j != skipped) {
            others[n++] = rows[j];
        }
    }
    return others;
}

/// The position of a point, weighted or not: the cofactors never see the weights.
inline predicates::Point3 position(const predicates::Point3& p) {
    return p;
}

inline predicates::Point3 position(const predicates::WeightedPoint3& p) {
    return {p.x, p.y, p.z};
}

inline const predicates::GenericPoint3& position(const predicates::GenericPoint3& p) {
    return p;
}

}  // namespace cavity::perturbation
