// The build without CGAL: the peers suite reports CGAL as unavailable.
#include "cavity/core/base/error.h"
#include "peer_engines.h"

namespace cavity::experiments::detail {

bool cgal_available() {
    return false;
}

EngineReport cgal_delaunay(core::PointSet) {
    throw core::Error("this build has no CGAL (libcgal-dev was not found at configure time)");
}

}  // namespace cavity::experiments::detail
