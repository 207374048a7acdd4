#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cavity/predicates/generic_point.h"
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
    /// Empty when every point is its coordinates; else one exact definition per point, an input
    /// point as its Point3 and an implicit (Steiner) point as its construction from input doubles
    /// (generic_point.h), whose entry in `points` is then only its rounding to doubles.
    std::vector<predicates::GenericPoint3> exact;
    int index_base = 0;
    std::string source;  ///< file name or generator description, for messages
    /// A .node file's attributes, kept for the output .node: `attribute_count` per point, row by
    /// row (with --weighted the weight is attribute 0 and is also in `weights`). Empty otherwise.
    std::size_t attribute_count = 0;
    std::vector<double> attributes;
    /// A .node file's boundary markers, one per point, kept for the output .node; else empty.
    std::vector<std::int64_t> markers;

    bool weighted() const { return !weights.empty(); }

    std::size_t size() const { return points.size(); }
};

}  // namespace cavity::core
