#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cavity/predicates/point.h"

namespace cavity::core {

using predicates::Point3;
using predicates::WeightedPoint3;

/// Points as read from a file or made by a generator. The position of a point in `points` is its
/// input index: the key of the symbolic perturbation and the id used in every output. Files number
/// their points from `index_base` (0 or 1, as the input file did); outputs keep that numbering.
struct PointSet {
    std::vector<Point3> points;
    std::vector<double> weights;  ///< empty for an unweighted set, else one weight per point
    int index_base = 0;
    std::string source;  ///< file name or generator description, for messages

    bool weighted() const { return !weights.empty(); }
    std::size_t size() const { return points.size(); }
};

}  // namespace cavity::core
