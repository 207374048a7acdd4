#include "cavity/core/cdt/cdt_vertex_insertion.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <unordered_set>

#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/mesh/dig_cavity.h"
#include "cavity/core/mesh/facet_gluer.h"

namespace cavity::core {

namespace {

using Triangle = std::array<VertexId, 3>;

Triangle sorted(Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
}

std::array<std::uint32_t, 2> sorted_edge(VertexId a, VertexId b) {
    return {std::min(a, b), std::max(a, b)};
}

bool has_ghost(const Triangle& t) {
    return t[0] == kGhostVertex || t[1] == kGhostVertex || t[2] == kGhostVertex;
}

}  // namespace

bool LiveCdt::Carrier::inside(const Triangle& t) const {
    // Outside the hull (0) or inside a tetrahedron (4), the point lies on no triangle.
    if (size == 0 || size == 4) {
        return false;
    }
    for (int i = 0; i < size; ++i) {
        if (std::find(t.begin(), t.end(), v[static_cast<std::size_t>(i)]) == t.end()) {
            return false;
        }
    }
    return true;
}

bool LiveCdt::Carrier::is_edge(VertexId a, VertexId b) const {
    return size == 2 && std::min(a, b) == v[0] && std::max(a, b) == v[1];
}

std::string LiveCdt::name(VertexId v) const {
    return v == kGhostVertex
               ? "g"
               : std::to_string(v + static_cast<std::uint32_t>(plc_.points.index_base));
}

std::string LiveCdt::triangle_name(const Triangle& t) const {
    return name(t[0]) + " " + name(t[1]) + " " + name(t[2]);
}

void LiveCdt::add_face(const Triangle& v, std::uint32_t facet) {
    face_index_[sorted(v)] = faces_.size();
    faces_.push_back({{v[0], v[1], v[2]}, plc_.facets[facet].marker});
    face_facet_.push_back(facet);
}

void LiveCdt::remove_face(const Triangle& key) {
    const auto it = face_index_.find(key);
    const std::size_t i = it->second;
    face_index_.erase(it);
    if (i + 1 != faces_.size()) {
        faces_[i] = faces_.back();
        face_facet_[i] = face_facet_.back();
        face_index_[sorted({faces_[i].v[0], faces_[i].v[1], faces_[i].v[2]})] = i;
    }
    faces_.pop_back();
    face_facet_.pop_back();
}

/// The remembering stochastic walk (Devillers, Pion & Teillaud) over the live complex with exact
/// orient3d: it terminates on any triangulation, constrained ones included, where the plain
/// visibility walk may cycle.
LiveCdt::Carrier LiveCdt::locate(const Point3& p) {
    if (hint_ == kNoTet || !storage_.alive(hint_) || is_ghost(storage_.vertices(hint_))) {
        hint_ = 0;
        while (!storage_.alive(hint_) || is_ghost(storage_.vertices(hint_))) {
            ++hint_;
        }
    }
    Carrier carrier;
    stochastic_walk(
        storage_,
        hint_,
        walk_random_,
        [&](TetId t, const TetVertices& v) {
            ++counters_.walk_steps;
            carrier = Carrier{};
            carrier.tet = t;
            return is_ghost(v);  // entered through the hull triangle with p strictly in front
        },
        [&](TetId, const TetVertices& v, int f, int entered) {
            const auto tri = facet_vertices(v, f);
            // By the vertices' definitions: a rounded implicit vertex could invert a tetrahedron.
            const Sign s = geometry_.orient3d(tri[0], tri[1], tri[2], predicates::GenericPoint3(p));
            if (s == Sign::kNeg && f != entered) {
                return true;
            }
            if (s == Sign::kPos) {
                // Facet f's sign is the barycentric sign of vertex f: nonzero puts it in the
                // carrier.
                carrier.v[static_cast<std::size_t>(carrier.size++)] =
                    v[static_cast<std::size_t>(f)];
            }
            return false;
        });
    // Unused slots hold kNoVertex: last. (A ghost's carrier is empty: nothing to sort.)
    std::sort(carrier.v.begin(), carrier.v.end());
    return carrier;
}

bool LiveCdt::conflicts(TetId t, VertexId u) {
    ++counters_.conflict_tests;
    const TetVertices& v = storage_.vertices(t);
    if (!is_ghost(v)) {
        return geometry_.conflicts_solid(v, u);
    }
    // The coplanar case needs a vertex strictly behind the hull triangle: the solid apex.
    const HalfFacet behind = storage_.adjacent(t, 3);
    const VertexId apex =
        storage_.vertices(tet_of(behind))[static_cast<std::size_t>(facet_of(behind))];
    return geometry_.conflicts_ghost(v, u, {apex, apex, apex, apex});
}

/// DigCavity with constraints (§5.7): the dig of Bowyer–Watson (dig_cavity.h) with the polygon
/// triangles blocked, except those the new vertex lies on. Nothing is deleted, only stamped: the
/// insertion may still be refused.
LiveCdt::Cavity LiveCdt::dig(const Carrier& carrier, VertexId u) {
    Cavity cavity;
    if (++epoch_ == 0) {
        std::fill(stamp_.begin(), stamp_.end(), 0u);
        epoch_ = 1;
    }
    stamp_.resize(storage_.capacity(), 0u);

    struct Rules {
        LiveCdt& cdt;
        const Carrier& carrier;
        VertexId u;
        Cavity& cavity;
        bool polygon = false;  // whether the face blocked() last looked at is a polygon triangle

        bool blocked(TetId t, int f) {
            const Triangle tri = facet_vertices(cdt.storage_.vertices(t), f);
            polygon = !has_ghost(tri) && cdt.face_index_.count(sorted(tri)) != 0;
            const bool through = polygon && carrier.inside(tri);
            if (through) {
                cavity.split.insert(sorted(tri));
            }
            return polygon && !through;
        }

        bool in_cavity(TetId t) const { return cdt.in_cavity(t); }

        // A solid tetrahedron holding the point has it in its closure and not as a vertex, so
        // strictly inside the circumball; a ghost has it strictly in front: t0 is taken untested.
        bool conflicts(TetId t) { return cdt.conflicts(t, u); }

        void take(TetId t) {
            cdt.stamp_[t] = cdt.epoch_;
            cavity.tets.push_back(t);
        }

        void blocked_inside(TetId t, int f) {
            // Reached around the polygon: its triangle has the cavity on both sides.
            cavity.doubled.insert(sorted(facet_vertices(cdt.storage_.vertices(t), f)));
        }

        void cavity_face(TetId t, int f, HalfFacet across) {
            cavity.faces.push_back({t, f, across, polygon});
        }
    };

    Rules rules{*this, carrier, u, cavity};
    dig_cavity(storage_, carrier.tet, dig_stack_, rules);
    // A polygon face found before the search reached its far side from elsewhere is no cavity face.
    std::erase_if(cavity.faces,
                  [&](const CavityFace& face) { return in_cavity(tet_of(face.across)); });
    return cavity;
}

LiveCdt::Star LiveCdt::make_star(const Cavity& cavity, VertexId u) const {
    Star star;
    star.tets.reserve(cavity.faces.size());
    for (const CavityFace& face : cavity.faces) {
        const auto [v, u_slot] = cone(facet_vertices(storage_.vertices(face.inner), face.facet), u);
        star.tets.push_back(v);
        star.outer.push_back(u_slot);
    }
    // Around u, the face rotated to (u, p, q) meets the one rotated to (u, q, p): the engine's
    // gluer pairs them (by the vertex ids: a star is built once per vertex, off any hot path).
    FacetGluer gluer;
    for (std::size_t n = 0; n < star.tets.size(); ++n) {
        const TetVertices& v = star.tets[n];
        const auto a = static_cast<std::size_t>(star.outer[n]);
        for (std::size_t s = 0; s < 4; ++s) {
            if (s == a) {
                continue;
            }
            const VertexId p = v[static_cast<std::size_t>(kApexFaceEdge[a][s][0])];
            const VertexId q = v[static_cast<std::size_t>(kApexFaceEdge[a][s][1])];
            const HalfFacet h = half_facet(static_cast<TetId>(n), static_cast<int>(s));
            const HalfFacet partner = gluer.match_hashed(p, q, h);
            if (partner != kNoHalfFacet) {
                star.around.push_back({partner, h});
            }
        }
    }
    gluer.end();
    return star;
}

/// The polygons v lies on, retriangulated in their planes: their triangles with both sides in the
/// cavity give way to v joined to the boundary edges of their union (an edge holding v is no
/// boundary: v splits it). A doubled triangle of another polygon is diagnosis 2, and so is a new
/// triangle whose edge lies on no cavity face (it would not be a face of the new tetrahedra).
std::string LiveCdt::retriangulate_polygons(Cavity& cavity,
                                            const Carrier& carrier,
                                            VertexId u,
                                            std::vector<PolygonTriangle>& added) const {
    std::set<std::uint32_t> facets;
    for (const Triangle& key : cavity.split) {
        facets.insert(face_facet_[face_index_.at(key)]);
    }
    for (const Triangle& key : cavity.doubled) {
        const std::size_t i = face_index_.at(key);
        if (facets.count(face_facet_[i]) == 0) {
            return "polygon triangle " + triangle_name(key) +
                   " runs through the cavity (the tetrahedra on both of its sides conflict with "
                   "the new vertex)";
        }
        cavity.split.insert(key);
    }
    std::map<std::pair<std::uint32_t, PlcEdge>, int> uses;  // (facet, edge) -> split triangles
    for (const Triangle& key : cavity.split) {
        const std::uint32_t facet = face_facet_[face_index_.at(key)];
        for (int i = 0; i < 3; ++i) {
            ++uses[{facet,
                    sorted_edge(key[static_cast<std::size_t>(i)],
                                key[static_cast<std::size_t>((i + 1) % 3)])}];
        }
    }
    std::set<PlcEdge> kept;
    for (const CavityFace& face : cavity.faces) {
        const Triangle tri = facet_vertices(storage_.vertices(face.inner), face.facet);
        for (int i = 0; i < 3; ++i) {
            kept.insert(sorted_edge(tri[static_cast<std::size_t>(i)],
                                    tri[static_cast<std::size_t>((i + 1) % 3)]));
        }
    }
    for (const Triangle& key : cavity.split) {
        const std::size_t i = face_index_.at(key);
        const CdtFace& old = faces_[i];
        for (std::size_t k = 0; k < 3; ++k) {
            const VertexId a = old.v[(k + 1) % 3];
            const VertexId b = old.v[(k + 2) % 3];
            if (uses.at({face_facet_[i], sorted_edge(a, b)}) > 1 || carrier.is_edge(a, b)) {
                continue;
            }
            if (kept.count(sorted_edge(a, b)) == 0) {
                return "the polygon of triangle " + triangle_name(key) +
                       " cannot be retriangulated around the new vertex: its edge " + name(a) +
                       "-" + name(b) + " lies inside the cavity";
            }
            Triangle replaced{old.v[0], old.v[1], old.v[2]};
            replaced[k] = u;
            added.push_back({replaced, face_facet_[i]});
        }
    }
    return {};
}

/// Diagnosis 2 for edges and vertices: a simplex survives only if it lies on a cavity face, i.e.
/// some tetrahedron around it stays. A PLC edge or a vertex with every tetrahedron in the cavity
/// would disappear.
std::string LiveCdt::through_cavity(const Cavity& cavity, const Carrier& carrier) const {
    std::unordered_set<VertexId> kept_vertices;
    std::set<PlcEdge> kept_edges;
    for (const CavityFace& face : cavity.faces) {
        const Triangle tri = facet_vertices(storage_.vertices(face.inner), face.facet);
        for (int i = 0; i < 3; ++i) {
            kept_vertices.insert(tri[static_cast<std::size_t>(i)]);
            kept_edges.insert(sorted_edge(tri[static_cast<std::size_t>(i)],
                                          tri[static_cast<std::size_t>((i + 1) % 3)]));
        }
    }
    for (TetId t : cavity.tets) {
        const TetVertices& v = storage_.vertices(t);
        for (std::size_t i = 0; i < 4; ++i) {
            if (v[i] != kGhostVertex && kept_vertices.count(v[i]) == 0) {
                return "vertex " + name(v[i]) +
                       " lies inside the cavity (all of its tetrahedra conflict with the new "
                       "vertex) and would vanish";
            }
            for (std::size_t j = i + 1; j < 4; ++j) {
                if (v[i] == kGhostVertex || v[j] == kGhostVertex || carrier.is_edge(v[i], v[j])) {
                    continue;
                }
                const PlcEdge e = sorted_edge(v[i], v[j]);
                if (plc_edges_.count(e) != 0 && kept_edges.count(e) == 0) {
                    return "PLC edge " + name(e[0]) + "-" + name(e[1]) +
                           " runs through the cavity (all of its tetrahedra conflict with the new "
                           "vertex)";
                }
            }
        }
    }
    return {};
}

/// Diagnosis 1: every new solid tetrahedron must be positively oriented, and the new hull convex:
/// across each edge of a new hull triangle, the third vertex of the neighbouring hull triangle
/// (old or new) must not be in front of it.
std::string LiveCdt::not_star_shaped(const Cavity& cavity, const Star& star) const {
    const auto in_front = [&](const TetVertices& ghost, VertexId w) {
        return w != kGhostVertex &&
               geometry_.orient3d(ghost[0], ghost[1], ghost[2], w) == Sign::kPos;
    };
    const auto hull_name = [&](const TetVertices& g) {
        return "the cavity is not star-shaped from the new vertex: the new hull triangle " +
               name(g[0]) + " " + name(g[1]) + " " + name(g[2]) + " has vertex ";
    };
    for (std::size_t n = 0; n < star.tets.size(); ++n) {
        const TetVertices& v = star.tets[n];
        if (is_ghost(v)) {
            const HalfFacet across = cavity.faces[n].across;
            const VertexId w =
                storage_.vertices(tet_of(across))[static_cast<std::size_t>(facet_of(across))];
            if (in_front(v, w)) {
                return hull_name(v) + name(w) + " in front of it";
            }
            continue;
        }
        const Sign s = geometry_.orient3d(v[0], v[1], v[2], v[3]);
        if (s != Sign::kPos) {
            const Triangle tri =
                facet_vertices(storage_.vertices(cavity.faces[n].inner), cavity.faces[n].facet);
            return "the cavity is not star-shaped from the new vertex: its face " +
                   triangle_name(tri) + " and the new vertex make a tetrahedron of " +
                   (s == Sign::kZero ? "zero volume" : "negative orientation");
        }
    }
    for (const auto& [h1, h2] : star.around) {
        const TetVertices& a = star.tets[tet_of(h1)];
        const TetVertices& b = star.tets[tet_of(h2)];
        if (is_ghost(a) && is_ghost(b)) {
            for (const auto& [g, other, s] :
                 {std::tuple{a, b, facet_of(h2)}, std::tuple{b, a, facet_of(h1)}}) {
                if (in_front(g, other[static_cast<std::size_t>(s)])) {
                    return hull_name(g) + name(other[static_cast<std::size_t>(s)]) +
                           " in front of it";
                }
            }
        }
    }
    return {};
}

/// The third check: every new face between two new solid tetrahedra, except the new polygon
/// triangles, must be locally Delaunay (the new faces against the old tetrahedra are, because the
/// old ones did not conflict). Bowyer–Watson guarantees it when the triangulation is Delaunay;
/// a CDT is not, and a new tetrahedron may take in a vertex that a polygon hid from the deleted
/// ones (or the perturbation fixed a polygon's triangulation from its other side). Then the PLC
/// with v has no CDT that keeps the rest, and v is refused like the chapter's two diagnoses.
std::string LiveCdt::not_delaunay(const Star& star, const std::vector<PolygonTriangle>& added) {
    std::set<Triangle> polygon;
    for (const PolygonTriangle& t : added) {
        polygon.insert(sorted(t.v));
    }
    for (const auto& [h1, h2] : star.around) {
        const TetVertices& a = star.tets[tet_of(h1)];
        const TetVertices& b = star.tets[tet_of(h2)];
        if (is_ghost(a) || is_ghost(b)) {
            continue;
        }
        const Triangle face = facet_vertices(a, facet_of(h1));
        if (polygon.count(sorted(face)) != 0) {
            continue;
        }
        ++counters_.face_tests;
        if (geometry_.conflicts_solid(a, b[static_cast<std::size_t>(facet_of(h2))])) {
            return "the new face " + triangle_name(face) +
                   " is not locally Delaunay (a vertex hidden from the cavity by a polygon lies "
                   "in a new tetrahedron's circumball): no CDT keeps the rest of the mesh";
        }
    }
    return {};
}

void LiveCdt::split_plc_edge(const PlcEdge& e, std::uint32_t m) {
    core::split_plc_edge(plc_, e, m);
    plc_edges_.erase(e);
    plc_edges_.insert(sorted_edge(e[0], m));
    plc_edges_.insert(sorted_edge(m, e[1]));
}

void LiveCdt::commit(const Cavity& cavity,
                     const Star& star,
                     const std::vector<PolygonTriangle>& added,
                     const Carrier& carrier,
                     VertexId u) {
    for (TetId t : cavity.tets) {
        ++(is_ghost(storage_.vertices(t)) ? counters_.ghosts_deleted : counters_.tets_deleted);
        storage_.delete_tetrahedron(t);
    }
    std::vector<TetId> ids;
    ids.reserve(star.tets.size());
    for (std::size_t n = 0; n < star.tets.size(); ++n) {
        const TetId t = storage_.add_tetrahedron(star.tets[n]);
        ids.push_back(t);
        storage_.glue(half_facet(t, star.outer[n]), cavity.faces[n].across);
        if (is_ghost(star.tets[n])) {
            ++counters_.ghosts_created;
        } else {
            ++counters_.tets_created;
            hint_ = t;
        }
    }
    for (const auto& [h1, h2] : star.around) {
        storage_.glue(half_facet(ids[tet_of(h1)], facet_of(h1)),
                      half_facet(ids[tet_of(h2)], facet_of(h2)));
    }
    storage_.end_operation();
    for (const Triangle& key : cavity.split) {
        remove_face(key);
    }
    for (const PolygonTriangle& t : added) {
        add_face(t.v, t.facet);
    }
    counters_.polygon_triangles_split += cavity.split.size();
    if (!cavity.split.empty()) {
        ++counters_.on_polygon;
    }
    plc_.points.points.push_back(geometry_.point(u));
    if (!plc_.points.exact.empty()) {
        plc_.points.exact.emplace_back(geometry_.point(u));
    }
    if (carrier.size == 2 && plc_edges_.count({carrier.v[0], carrier.v[1]}) != 0) {
        split_plc_edge({carrier.v[0], carrier.v[1]}, u);
        ++counters_.on_plc_edge;
    }
}

CdtInsertion LiveCdt::insert_vertex(const Point3& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw Error(located_message(
            plc_.source, std::nullopt, "cannot insert a point with a non-finite coordinate"));
    }
    ++counters_.attempts;
    const Carrier carrier = locate(p);
    if (carrier.size == 1) {
        ++counters_.duplicates;
        return {CdtInsertionStatus::kDuplicate,
                carrier.v[0],
                "the point coincides with vertex " + name(carrier.v[0])};
    }
    const VertexId u = geometry_.append_point(p);
    Cavity cavity = dig(carrier, u);
    const Star star = make_star(cavity, u);
    std::vector<PolygonTriangle> added;
    CdtInsertion result;
    // Diagnosis 2 first: a polygon through the cavity always breaks star-shapedness too, and
    // naming the polygon says more.
    result.message = retriangulate_polygons(cavity, carrier, u, added);
    if (result.message.empty()) {
        result.message = through_cavity(cavity, carrier);
    }
    if (!result.message.empty()) {
        result.status = CdtInsertionStatus::kThroughCavity;
        ++counters_.refused_through_cavity;
    } else if (result.message = not_star_shaped(cavity, star); !result.message.empty()) {
        result.status = CdtInsertionStatus::kNotStarShaped;
        ++counters_.refused_not_star_shaped;
    } else if (result.message = not_delaunay(star, added); !result.message.empty()) {
        result.status = CdtInsertionStatus::kNotDelaunay;
        ++counters_.refused_not_delaunay;
    }
    if (!result.message.empty()) {
        // Geometry only grows; drop the tentative point by rebuilding it (refusals are rare).
        geometry_ = geometry_by_index(plc_.points);
        result.message = "the vertex cannot be inserted: " + result.message;
        return result;
    }
    commit(cavity, star, added, carrier, u);
    inserted_.push_back(u);
    ++counters_.inserted;
    result.vertex = u;
    return result;
}

}  // namespace cavity::core
