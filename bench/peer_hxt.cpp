// HXT (gmsh's contrib/hxt, Marot, Pellerin and Remacle, "One machine, one minute, three billion
// tetrahedra", 2019) as a peer: hxtDelaunay on an empty mesh, with its own Hilbert ordering,
// perfectDelaunay set (no constraints), sequentially and on the benchmark's thread count.

#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "hxt_mesh.h"
#include "hxt_tetDelaunay.h"
#include "hxt_tools.h"
#include "peer_engines.h"

namespace peers {

namespace {

struct MeshDeleter {
    void operator()(HXTMesh* mesh) const { hxtMeshDelete(&mesh); }
};

using MeshPointer = std::unique_ptr<HXTMesh, MeshDeleter>;

void check(HXTStatus status, const char* what) {
    if (status != HXT_STATUS_OK) {
        throw std::runtime_error(std::string("HXT: ") + what + " failed");
    }
}

/// HXT keeps 4 doubles per vertex (the fourth is its scratch space) in an aligned array it owns.
MeshPointer mesh_of(const cavity::core::PointSet& points) {
    HXTMesh* raw = nullptr;
    check(hxtMeshCreate(&raw), "hxtMeshCreate");
    MeshPointer mesh(raw);
    const auto n = static_cast<std::uint32_t>(points.size());
    check(hxtAlignedMalloc(&mesh->vertices.coord, sizeof(double) * 4 * n), "hxtAlignedMalloc");
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto& p = points.points[i];
        double* c = mesh->vertices.coord + 4 * static_cast<std::size_t>(i);
        c[0] = p.x;
        c[1] = p.y;
        c[2] = p.z;
        c[3] = 0.0;
    }
    mesh->vertices.num = n;
    mesh->vertices.size = n;
    return mesh;
}

PreparedRun prepared(const cavity::core::PointSet& points, unsigned threads) {
    auto mesh = std::make_shared<MeshPointer>(mesh_of(points));
    return [mesh, threads]() {
        HXTDelaunayOptions options;
        std::memset(&options, 0, sizeof options);
        options.perfectDelaunay = 1;
        options.verbosity = 0;
        options.delaunayThreads = static_cast<int>(threads);
        HXTMesh* m = mesh->get();
        check(hxtDelaunay(m, &options), "hxtDelaunay");
        // Ghost tetrahedra (HXT's infinite vertex) close the hull; count the finite ones.
        std::size_t finite = 0;
        for (std::uint64_t t = 0; t < m->tetrahedra.num; ++t) {
            finite += m->tetrahedra.node[4 * t + 3] != HXT_GHOST_VERTEX ? 1 : 0;
        }
        return finite;
    };
}

}  // namespace

std::vector<PeerEngine> optional_engines(unsigned threads) {
    std::vector<PeerEngine> engines;
    engines.push_back({"hxt", 1, [](const auto& points) { return prepared(points, 1); }});
    if (threads > 1) {
        engines.push_back({"hxt-threads", threads, [threads](const auto& points) {
                               return prepared(points, threads);
                           }});
    }
    return engines;
}

}  // namespace peers
