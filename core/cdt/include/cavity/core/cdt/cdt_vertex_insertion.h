#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cavity/core/base/pod_stack.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/delaunay/stochastic_walk.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/array_storage.h"

/// Vertex insertion into a constrained Delaunay tetrahedralization (Cheng, Dey & Shewchuk §5.7):
/// Bowyer–Watson adapted to CDTs as §3.9 does in the plane. The cavity is the set of tetrahedra
/// in conflict with the new vertex v (perturbed circumball, or outer halfspace for a ghost) that a
/// breadth-first search reaches without crossing a polygon, except a polygon v lies on. Even when
/// the PLC has a CDT, the PLC with v added may have none, and the chapter's two symptoms are then
/// checked before anything changes (the second first: a polygon through the cavity breaks
/// star-shapedness too, and naming it says more, so a point failing both is kThroughCavity):
///  1. the cavity is not star-shaped from v: some new tetrahedron (v and a cavity face) is not
///     positively oriented, or a new hull triangle has a neighbour in front of it;
///  2. a polygon, a PLC edge or a vertex lies inside the cavity: a triangle of a polygon that v
///     is not on with both its tetrahedra in the cavity, a PLC edge (segment or polygon side) or a
///     vertex all of whose tetrahedra are.
/// A vertex on a polygon or a PLC edge splits them: the polygon's triangles with both sides in
/// the cavity (those holding v, and those whose circumcircle holds it: the 2D Bowyer–Watson
/// cavity in the polygon) are replaced by v joined to the boundary edges of their union (same
/// marker), and the PLC edge becomes two in the Plc.
namespace cavity::core {

enum class CdtInsertionStatus : std::uint8_t {
    kInserted,
    kDuplicate,      ///< the point is a vertex already: nothing inserted
    kNotStarShaped,  ///< diagnosis 1: "this vertex cannot be inserted"
    kThroughCavity,  ///< diagnosis 2: "this vertex cannot be inserted"
    /// The cavity is star-shaped and nothing runs through it, yet a new face between two new
    /// tetrahedra is not locally Delaunay: a vertex that a polygon hid from the deleted tetrahedra
    /// lies in a new one's circumball (or the perturbation fixed a polygon's triangulation from
    /// its other side). No CDT keeps the rest of the mesh; also "cannot be inserted".
    kNotDelaunay,
};

struct CdtInsertion {
    CdtInsertionStatus status = CdtInsertionStatus::kInserted;
    /// Inserted: the new vertex's 0-based index. Duplicate: the vertex it equals. Else kNoVertex.
    std::uint32_t vertex = kNoVertex;
    /// Empty when inserted; else the reason, naming the offending simplex with ids numbered from
    /// plc.points.index_base.
    std::string message;

    bool inserted() const { return status == CdtInsertionStatus::kInserted; }
};

/// A CDT kept live for vertex insertion: the PLC, the complex with its ghosts (vertex id = 0-based
/// point index), the perturbed geometry, the polygon triangles with their markers and the PLC
/// edges.
class LiveCdt {
public:
    /// Builds the CDT of `plc` exactly as build_cdt does (construction is in cdt.cpp) and checks
    /// it. \throws Error as build_cdt.
    LiveCdt(Plc plc, const CdtOptions& options);

    /// Inserts p as vertex plc().points.size() (its perturbation key), or reports why not; on a
    /// refusal or a duplicate the triangulation is unchanged.
    /// \throws Error when p has a non-finite coordinate.
    CdtInsertion insert_vertex(const Point3& p);

    const Plc& plc() const { return plc_; }

    const ArrayStorage& storage() const { return storage_; }

    const Geometry& geometry() const { return geometry_; }

    const std::vector<CdtFace>& faces() const { return faces_; }

    const CdtInsertionCounters& counters() const { return counters_; }

    /// Indices of the vertices inserted so far, in order.
    const std::vector<std::uint32_t>& inserted() const { return inserted_; }

    /// The solid tetrahedra, 0-based, with positive right-hand volume (handedness.h).
    std::vector<std::array<std::uint32_t, 4>> tets() const;

    /// Checks the whole mesh from outside (validate_cdt on plc(), which rebuilds the complex from
    /// the tetrahedra and checks it); the storage's own complex only in the expensive-check build.
    /// \throws Error ("internal error: ... not a CDT") listing the problems.
    void validate() const;

    /// A copy of the current state as a Cdt.
    Cdt snapshot() const;

private:
    using Triangle = std::array<VertexId, 3>;
    using PlcEdge = std::array<std::uint32_t, 2>;

    /// The smallest simplex of the complex whose closure holds the point being inserted: its
    /// vertices, sorted (1: a duplicate; 2: on an edge; 3: on a triangle; 4: inside a tetrahedron;
    /// 0: outside the hull).
    struct Carrier {
        TetId tet = kNoTet;  ///< a tetrahedron holding it (a ghost when outside the hull)
        std::array<VertexId, 4> v{kNoVertex, kNoVertex, kNoVertex, kNoVertex};
        int size = 0;
        bool inside(const Triangle& t) const;
        bool is_edge(VertexId a, VertexId b) const;
    };

    /// A cavity face: facet `facet` of the cavity tetrahedron `inner`, with `across` outside.
    struct CavityFace {
        TetId inner;
        int facet;
        HalfFacet across;
        bool polygon;  ///< a polygon triangle (the search stopped there)
    };

    struct Cavity {
        std::vector<TetId> tets;
        std::vector<CavityFace> faces;
        std::set<Triangle> split;    ///< polygon triangles holding the point (sorted)
        std::set<Triangle> doubled;  ///< other polygon triangles with both sides in the cavity
    };

    /// The new tetrahedra, one per cavity face (slot `outer[n]` faces out), and the pairs of their
    /// half-facets (4 n + s) that meet around the new vertex.
    struct Star {
        std::vector<TetVertices> tets;
        std::vector<int> outer;
        std::vector<std::array<HalfFacet, 2>> around;
    };

    /// What construction starts from: the PLC after protection, with the Delaunay triangulation of
    /// its points.
    struct Start {
        Protection protection;
        Plc plc;
        DelaunayTriangulation delaunay;
    };

    static Start start(Plc plc, const CdtOptions& options);
    explicit LiveCdt(Start start);

    struct PolygonTriangle {
        Triangle v;
        std::uint32_t facet;
    };

    Carrier locate(const Point3& p);
    Cavity dig(const Carrier& carrier, VertexId u);
    bool conflicts(TetId t, VertexId u);
    Star make_star(const Cavity& cavity, VertexId u) const;
    std::string retriangulate_polygons(Cavity& cavity,
                                       const Carrier& carrier,
                                       VertexId u,
                                       std::vector<PolygonTriangle>& added) const;
    std::string through_cavity(const Cavity& cavity, const Carrier& carrier) const;
    std::string not_star_shaped(const Cavity& cavity, const Star& star) const;
    std::string not_delaunay(const Star& star, const std::vector<PolygonTriangle>& added);
    void commit(const Cavity& cavity,
                const Star& star,
                const std::vector<PolygonTriangle>& added,
                const Carrier& carrier,
                VertexId u);
    void split_plc_edge(const PlcEdge& e, std::uint32_t m);
    void add_face(const Triangle& v, std::uint32_t facet);
    void remove_face(const Triangle& key);

    bool in_cavity(TetId t) const { return t < stamp_.size() && stamp_[t] == epoch_; }

    std::string name(VertexId v) const;
    std::string triangle_name(const Triangle& t) const;

    // Initialised in this order by the constructor: protection splits the input first.
    Protection protection_;
    Plc plc_;
    Geometry geometry_;
    ArrayStorage storage_;
    PolygonInsertionCounters polygon_counters_;
    std::vector<CdtFace> faces_;
    std::vector<std::uint32_t> face_facet_;       ///< the facet (index in plc_.facets) of each face
    std::map<Triangle, std::size_t> face_index_;  ///< sorted triangle -> position in faces_
    std::set<PlcEdge> plc_edges_;                 ///< {min, max}
    std::vector<std::uint32_t> inserted_;
    CdtInsertionCounters counters_;
    TetId hint_ = kNoTet;  ///< where the next walk starts
    WalkRandom walk_random_{0x9E37'79B9'7F4A'7C15u};
    std::vector<std::uint32_t> stamp_;  ///< stamp_[t] == epoch_: t is in the current cavity
    PodStack<HalfFacet> dig_stack_;
    std::uint32_t epoch_ = 0;
};

}  // namespace cavity::core
