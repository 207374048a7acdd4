#include "gift_wrap_engine.h"

#include <algorithm>
#include <string>

#include "cavity/core/base/error.h"

namespace cavity::core::detail {

namespace {

GiftWrapEngine::Triangle sorted(GiftWrapEngine::Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
}

bool holds(const GiftWrapEngine::Triangle& t, VertexId v) {
    return t[0] == v || t[1] == v || t[2] == v;
}

std::string name(VertexId v) {
    return v == kGhostVertex ? "ghost" : std::to_string(v);
}

/// True when a, b, c lie on one line: every coordinate-plane projection is degenerate. The 2D
/// orientations are exact orient3d calls on points dropped into the plane z = 0 against (0,0,1).
bool collinear(const Point3& a, const Point3& b, const Point3& c) {
    const Point3 up{0, 0, 1};
    const auto flat = [&](auto project) {
        return predicates::orient3d(project(a), project(b), project(c), up) == Sign::kZero;
    };
    return flat([](const Point3& p) {
               return Point3{p.x, p.y, 0};
           }) &&
           flat([](const Point3& p) {
               return Point3{p.y, p.z, 0};
           }) &&
           flat([](const Point3& p) {
               return Point3{p.z, p.x, 0};
           });
}

/// For c and z coplanar with a and b: true when they lie on the same side of line ab (some
/// coordinate-plane projection of the plane is non-degenerate and sees them on the same side).
bool same_side_of_line(const Point3& a, const Point3& b, const Point3& c, const Point3& z) {
    const Point3 up{0, 0, 1};
    const auto side = [&](auto project, const Point3& p) {
        return predicates::orient3d(project(a), project(b), project(p), up);
    };
    const auto test = [&](auto project) -> int {
        const Sign sc = side(project, c);
        const Sign sz = side(project, z);
        if (sc == Sign::kZero && sz == Sign::kZero) {
            return -1;  // this projection cannot tell
        }
        return sc == sz ? 1 : 0;
    };
    for (int r : {test([](const Point3& p) {
                      return Point3{p.x, p.y, 0};
                  }),
                  test([](const Point3& p) {
                      return Point3{p.y, p.z, 0};
                  }),
                  test([](const Point3& p) {
                      return Point3{p.z, p.x, 0};
                  })}) {
        if (r >= 0) {
            return r == 1;
        }
    }
    return false;
}

}  // namespace

void GiftWrapEngine::offer(const Triangle& seen_from_finished_side, VertexId apex) {
    const Triangle key = sorted(seen_from_finished_side);
    const auto it = unfinished_.find(key);
    if (it == unfinished_.end()) {
        unfinished_.emplace(key, Unfinished{seen_from_finished_side, apex});
        stack_.push_back(key);
        return;
    }
    const Triangle& other = it->second.seen;
    const Triangle& mine = seen_from_finished_side;
    const bool opposite = other == Triangle{mine[1], mine[0], mine[2]} ||
                          other == Triangle{mine[0], mine[2], mine[1]} ||
                          other == Triangle{mine[2], mine[1], mine[0]};
    if (!opposite) {
        throw Error("gift-wrapping failed: triangle " + name(key[0]) + " " + name(key[1]) + " " +
                    name(key[2]) + " was built twice on the same side");
    }
    unfinished_.erase(it);
}

VertexId GiftWrapEngine::solid_apex(const Triangle& f) {
    // The new tetrahedron is (f1, f0, f2, e): e must be on the positive side of (f1, f0, f2).
    VertexId best = kNoVertex;
    for (VertexId e : candidates_) {
        if (holds(f, e)) {
            continue;
        }
        ++counters_.apex_orient_tests;
        if (geometry_.orient3d(f[1], f[0], f[2], e) != Sign::kPos) {
            continue;
        }
        if (best != kNoVertex) {
            ++counters_.insphere_calls;
            if (!geometry_.conflicts_solid({f[1], f[0], f[2], best}, e)) {
                continue;
            }
        }
        best = e;
    }
    return best;
}

bool GiftWrapEngine::in_outer_halfspace(const TetVertices& ghost, VertexId u) {
    ++counters_.apex_orient_tests;
    const Sign front = geometry_.orient3d(ghost[0], ghost[1], ghost[2], u);
    if (front != Sign::kZero) {
        return front == Sign::kPos;
    }
    // Coplanar: the perturbed in-disk test, with any vertex strictly behind orienting the plane.
    VertexId behind = kNoVertex;
    for (VertexId y : candidates_) {
        if (geometry_.orient3d(ghost[0], ghost[1], ghost[2], y) == Sign::kNeg) {
            behind = y;
            break;
        }
    }
    for (VertexId y = 0; behind == kNoVertex && y < geometry_.size(); ++y) {
        if (geometry_.orient3d(ghost[0], ghost[1], ghost[2], y) == Sign::kNeg) {
            behind = y;
        }
    }
    if (behind == kNoVertex) {
        return false;
    }
    ++counters_.insphere_calls;
    return geometry_.conflicts_ghost_in_plane(ghost, u, behind);
}

VertexId GiftWrapEngine::ghost_apex(const TetVertices& partial, VertexId behind_apex) {
    // partial = (f1, f0, f2, -) holds the ghost among its first three slots: the new tetrahedron
    // is a ghost over a new hull triangle through the finite edge of f. The apex is the candidate
    // with no other candidate in the outer halfspace of its hull triangle: the hull wrapped
    // around that edge, ties in a flat hull broken by the in-plane perturbed Delaunay test.
    const int g = partial[0] == kGhostVertex ? 0 : partial[1] == kGhostVertex ? 1 : 2;
    const Point3& a = geometry_.point(partial[static_cast<std::size_t>(g == 0 ? 1 : 0)]);
    const Point3& b = geometry_.point(partial[static_cast<std::size_t>(g == 2 ? 1 : 2)]);
    // Every candidate lies in the wedge between the finished hull triangle (a, b, z) behind
    // this facet and the hull's other side, so the outer-halfspace order is total there, except
    // on the wedge's own boundary: a candidate in the half-plane of (a, b, z) would fold the new
    // hull triangle back onto the finished one, and is skipped.
    const Point3 z = behind_apex != kNoVertex ? geometry_.point(behind_apex) : a;
    VertexId best = kNoVertex;
    TetVertices best_tet{};
    for (VertexId c : candidates_) {
        if (c == partial[0] || c == partial[1] || c == partial[2] || c == behind_apex ||
            collinear(a, b, geometry_.point(c))) {
            continue;
        }
        TetVertices t = partial;
        t[3] = c;
        t = rotate_to_last(t, g);
        if (behind_apex != kNoVertex &&
            geometry_.orient3d(t[0], t[1], t[2], behind_apex) == Sign::kZero &&
            same_side_of_line(a, b, geometry_.point(c), z)) {
            continue;
        }
        if (best == kNoVertex || in_outer_halfspace(best_tet, c)) {
            best = c;
            best_tet = t;
        }
    }
    return best;
}

void GiftWrapEngine::run() {
    while (!stack_.empty()) {
        const Triangle key = stack_.back();
        stack_.pop_back();
        const auto it = unfinished_.find(key);
        if (it == unfinished_.end()) {
            continue;  // finished from its other side meanwhile
        }
        const Triangle f = it->second.seen;
        const VertexId behind = it->second.apex;
        unfinished_.erase(it);
        ++counters_.facets_wrapped;
        TetVertices t{f[1], f[0], f[2], kNoVertex};
        if (!holds(f, kGhostVertex)) {
            t[3] = solid_apex(f);
            if (t[3] == kNoVertex) {
                if (!ghost_allowed_) {
                    ++hull_triangles_;
                    ++counters_.hull_facets;
                    continue;
                }
                t[3] = kGhostVertex;
            }
        } else {
            const VertexId c = ghost_apex(t, behind);
            if (c == kNoVertex) {
                throw Error("gift-wrapping failed: no vertex to close hull edge facet " +
                            name(f[0]) + " " + name(f[1]) + " " + name(f[2]));
            }
            t[3] = c;
            t = rotate_to_last(t, t[0] == kGhostVertex ? 0 : t[1] == kGhostVertex ? 1 : 2);
        }
        tets_.push_back(t);
        ++counters_.tets_created;
        for (int k = 0; k < 4; ++k) {
            const Triangle side = facet_vertices(t, k);
            if (sorted(side) != key) {
                offer(side, t[static_cast<std::size_t>(k)]);
            }
        }
    }
}

}  // namespace cavity::core::detail
