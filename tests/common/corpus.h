#pragma once

#include <string>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::test {

/// A named input of the degenerate regression corpus, with what is known of its triangulation.
struct CorpusCase {
    std::string name;
    core::PointSet points;
    long long expected_tets = -1;  ///< -1: no closed form
};

/// The degenerate corpus: grids (integer and decimal), exactly cospherical integer points, a
/// paraboloid, cube corners, coplanar layers, duplicates, 1-ulp perturbations, coordinates scaled
/// to 1e+-300 and subnormals, large offsets, the moment curve and two skew lines.
std::vector<CorpusCase> degenerate_corpus();

}  // namespace cavity::test
