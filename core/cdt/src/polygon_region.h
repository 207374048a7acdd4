#pragma once

// Steps 1-2 of FlipInsertPolygon (Cheng, Dey & Shewchuk §5.8): where one polygon sits in the live
// complex. The exact tests that decide whether a tetrahedron crosses the polygon, touches it, or
// has a face in it, and the rotary and depth-first searches that find the region R without
// looking at the rest of the complex.

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "cavity/core/base/id_hash_map.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/input/plc.h"
#include "cavity/core/mesh/array_storage.h"
#include "exact_plane.h"

namespace cavity::core {

/// One facet of a PLC against the vertices of the complex, exactly. Left vertices lie on the
/// negative side of the facet's plane h, right vertices on the positive side.
///
/// Every test below asks the facet's FacetRegion about a single point that cannot lie on a loop
/// side: the loop sides are edges of the complex (edge protection), and simplices of a complex do
/// not cross, so the relative interior of a simplex lying in h is inside or outside the region as a
/// whole, unless the simplex is a loop side or corner itself (then it is on the boundary).
class FacetGeometry {
public:
    FacetGeometry(const Geometry& geometry, const Plc& plc, const PlcFacet& facet);

    const Geometry& geometry() const { return geometry_; }

    const Plc& plc() const { return plc_; }

    const PlcFacet& facet() const { return facet_; }

    /// -1 left, +1 right, 0 on h.
    int side(VertexId v);

    /// n . (v - a) for a right vertex (the speed at which its height rises), 0 otherwise.
    Rational speed(VertexId v);

    /// The vertex's point in rationals, converted once per facet.
    const ExactPoint& point(VertexId v) { return placed(v).point; }

    bool has_left_and_right(std::span<const VertexId> vs);

    /// How a tetrahedron meets the polygon.
    enum class Contact : std::uint8_t {
        kNone,
        kTouches,  ///< its closure meets the polygon's relative interior, its interior does not
        kCrosses,  ///< its interior meets the polygon: a tetrahedron of R
    };

    /// A solid tetrahedron crosses the polygon when it has a left and a right vertex and its
    /// section by h (a convex polygon whose interior avoids every edge of the complex, hence the
    /// polygon's boundary) is inside the region: the crossing point of any left-right edge
    /// decides. Otherwise it touches the polygon when the face spanned by its vertices on h (a
    /// vertex, edge or triangle) has its relative interior in the region. Ghost tetrahedra never
    /// touch.
    Contact contact(const TetVertices& t);

    bool crosses(const TetVertices& t) { return contact(t) == Contact::kCrosses; }

    /// True when triangle g lies in h and inside the region (its centroid decides).
    bool holds_triangle(const std::array<VertexId, 3>& g);

    /// The loop sides, each as a sorted pair, in loop order.
    const std::vector<std::array<VertexId, 2>>& loop_sides() const { return sides_; }

private:
    /// Whether the simplex spanned by `on` (1 to 3 vertices, all on h) has its relative interior
    /// in the region.
    bool face_in_region(std::span<const VertexId> on);

    /// Whether left-right edge ab (side(a) < 0 < side(b)) crosses h inside the region.
    bool edge_crosses_region(VertexId a, VertexId b);

    /// face_in_region for a facet whose region is a triangle of input points (triangle_corners_),
    /// by orientations of the face's vertices against the triangle's sides; nullopt when they
    /// leave it open (every vertex on the line of one side) and the centroid must decide.
    std::optional<bool> face_in_triangle(std::span<const VertexId> on);

    /// Where a vertex on h lies against triangle_corners_: bit i set when it is on the line of
    /// side i (corners i and i + 1), bit 3 when it is strictly beyond some side.
    std::uint8_t triangle_position(VertexId v);

    const Geometry& geometry_;
    const Plc& plc_;
    const PlcFacet& facet_;
    ExactPlane plane_;
    FacetRegion region_;

    /// A vertex's point and offset n . (p - a) in rationals, made on the first question that
    /// needs them (a centroid, a speed or a lifted point for polygon insertion's flips, a
    /// crossing point that ExactPlane::projected_crossing cannot make) and kept: converting an
    /// implicit point costs dozens of GMP operations, and most vertices are only asked for their
    /// side.
    struct Placed {
        Rational offset;
        ExactPoint point;
    };

    const Placed& placed(VertexId v);

    /// side(v) by the exact orient3d predicate, whose filters decide most signs in doubles.
    IdHashMap<std::int8_t> vertex_sides_;
    std::map<VertexId, Placed> placed_;

    /// What is known of the region at the relative interior of a piece of h, keyed by the sorted
    /// vertices of the simplex it belongs to (unused slots kGhostVertex): a vertex, edge or
    /// triangle of the complex lying in h, or the crossing point of a left-right edge. No piece
    /// but a loop side or corner meets the region's boundary (the loop sides are edges of the
    /// complex, and simplices of a complex do not cross), so a piece is inside or outside as a
    /// whole, and as every piece of the same simplex's section by h in whose closure it lies:
    /// one answer serves every tetrahedron with that vertex, edge or triangle. Most tetrahedra
    /// of R share a left-right edge or a vertex on h with one already asked, where each used to
    /// need its own crossing point and region test, most of polygon insertion on merged
    /// polygons.
    struct TripleHash {
        std::size_t operator()(const std::array<VertexId, 3>& k) const {
            std::uint64_t h = k[0];
            h = h * 0x9E3779B97F4A7C15ull + k[1];
            h = h * 0x9E3779B97F4A7C15ull + k[2];
            return static_cast<std::size_t>(h ^ (h >> 29));
        }
    };

    using PieceKey = std::array<VertexId, 3>;

    /// The pieces of a tetrahedron's section by h (or of a face in h) that are off the loops:
    /// left-right edges, vertices on h that are not corners, edges in h that are not loop
    /// sides, and the face itself when it is a triangle or an edge in h. At most seven.
    struct Pieces {
        std::array<PieceKey, 7> keys{};
        std::size_t count = 0;
    };

    /// Adds the vertices and edges of the simplex `on` (on h) that are off the loops.
    void add_pieces_on_h(std::span<const VertexId> on, Pieces& pieces) const;

    /// The answer known for any of the pieces, or nullopt.
    std::optional<bool> known(const Pieces& pieces) const;

    /// Records the answer for every piece.
    void learn(const Pieces& pieces, bool inside);

    /// face_in_region without the table: the face's own region test.
    bool face_in_region_tested(std::span<const VertexId> on);

    std::unordered_map<PieceKey, bool, TripleHash> pieces_in_region_;
    /// Whether an answer is recorded for every piece or only for the one asked (the first
    /// left-right edge, or the face): a triangle's region questions are a few orientations,
    /// cheaper than recording the pieces (homer: +4.6 M instructions when recorded).
    bool share_pieces_ = true;
    /// A triangle without hole points: a left-right edge crosses it when it turns the same way
    /// around its three sides (three orientations, crosses_facet_region), no crossing point needed.
    bool triangle_;
    /// The same for a triangle whose sides edge protection split (split_triangle.h): its three
    /// corners, or nullopt.
    std::optional<std::array<predicates::GenericPoint3, 3>> split_triangle_;
    /// The region's triangle when it is one with input corners (a triangle, or a split one whose
    /// corners are input points), with a point off h: orient3d of two corners, a vertex on h and
    /// that point tells the vertex's side of the line through the two, in h, without the
    /// vertex's rational coordinates. `triangle_turn_` is the sign of orient3d of the corners
    /// and that point: the sign of the strict inside of every side.
    std::optional<std::array<Point3, 3>> triangle_corners_;
    Point3 off_h_{};
    int triangle_turn_ = 0;
    std::unordered_map<VertexId, std::uint8_t> triangle_positions_;
    std::vector<std::array<VertexId, 2>> sides_;
    std::set<std::array<VertexId, 2>> side_set_;
    std::set<VertexId> corners_;
};

/// The region R of one polygon and the work of finding it.
struct PolygonRegion {
    std::vector<TetId> tets;              ///< R: the solid tetrahedra crossing the polygon
    std::vector<TetId> touching_outside;  ///< tetrahedra touching the polygon without crossing it
    std::uint64_t vertices = 0;           ///< m: distinct vertices of R
    std::uint64_t rotary_steps = 0;
    std::uint64_t search_visited = 0;
};

/// Steps 1-2. For every loop side (an edge of the complex), a walk through the star of one end
/// toward the other finds a tetrahedron holding the side, and the rotary search around the side
/// tests its ring for tetrahedra touching the polygon; a depth-first search across facets from each
/// one found then tests the neighbours of every touching tetrahedron. The touching tetrahedra of
/// each connected piece of the polygon are facet-connected (around any point of the piece they form
/// the star of a face), and every piece is bounded by loop sides, so the searches meet every
/// tetrahedron of R. Every side is searched, not one per loop: loops may share corners, so a piece
/// need not have a whole loop on its boundary. Doesn't change the complex.
PolygonRegion find_polygon_region(const ArrayStorage& storage, FacetGeometry& facet);

/// True when triangle abc is a face of the complex (ghosts present): a tetrahedron with edge ab
/// is found by the walk of step 1, and c is on the ring around ab. Steps are counted as the
/// rotary search's.
bool is_face(const ArrayStorage& storage,
             const Geometry& geometry,
             const std::array<VertexId, 3>& abc,
             std::uint64_t& steps);

}  // namespace cavity::core
