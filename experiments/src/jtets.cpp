#include "cavity/experiments/jtets.h"

#include <algorithm>
#include <cmath>

#include "cavity/core/base/error.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::experiments {

namespace {

using predicates::insphere;
using predicates::orient3d;
using predicates::Sign;

int sign_of(Sign s) {
    return static_cast<int>(s);
}

struct Vec {
    double x, y, z;
};

Vec sub(const Point3& p, const Point3& q) {
    return {p.x - q.x, p.y - q.y, p.z - q.z};
}

Vec cross(const Vec& u, const Vec& v) {
    return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

double dot(const Vec& u, const Vec& v) {
    return u.x * v.x + u.y * v.y + u.z * v.z;
}

/// One point of the pencil around a triangle: its index, the side of the triangle's plane it lies
/// on (orient3d sign) and an approximate λ used only to seed the exact sort.
struct PencilPoint {
    std::uint32_t index;
    int side;
    double lambda;
};

/// The pencil of spheres through triangle abc, with the exact order of the points by λ.
class Pencil {
public:
    Pencil(std::span<const Point3> points, std::uint32_t a, std::uint32_t b, std::uint32_t c)
        : points_(points), a_(points[a]), b_(points[b]), c_(points[c]) {
        // Circumcentre of abc relative to a, and the normal pointing to the positive side of
        // orient3d(a, b, c, .) (orient3d(a,b,c,d) = -((b-a) x (c-a)) . (d-a)).
        const Vec u = sub(b_, a_);
        const Vec v = sub(c_, a_);
        const Vec w = cross(u, v);
        const double w2 = dot(w, w);
        const Vec vw = cross(v, w);
        const Vec wu = cross(w, u);
        const double uu = dot(u, u);
        const double vv = dot(v, v);
        centre_ = {(uu * vw.x + vv * wu.x) / (2 * w2),
                   (uu * vw.y + vv * wu.y) / (2 * w2),
                   (uu * vw.z + vv * wu.z) / (2 * w2)};
        rho2_ = dot(centre_, centre_);
        normal_ = {-w.x, -w.y, -w.z};
    }

    /// Signed offset (up to a positive factor) of the centre of the sphere through a, b, c, p.
    double approximate_lambda(const Point3& p) const {
        const Vec d = sub(p, a_);
        const Vec r{d.x - centre_.x, d.y - centre_.y, d.z - centre_.z};
        const double value = (dot(r, r) - rho2_) / (2 * dot(normal_, r));
        return std::isfinite(value) ? value : 0.0;
    }

    /// sign(λ(x) - λ(y)), exactly: y is inside the ball of abcx (insphere · side(x) > 0) means
    /// λ(x) > λ(y) for y above the plane and λ(x) < λ(y) for y below.
    int compare(const PencilPoint& x, const PencilPoint& y) const {
        const Point3& px = points_[x.index];
        const Point3& py = points_[y.index];
        return sign_of(insphere(a_, b_, c_, px, py)) * x.side * y.side;
    }

    /// True when a point coplanar with abc is inside its circumcircle; `witness` is any point off
    /// the plane: every sphere through a, b, c cuts the plane in the circumcircle.
    bool inside_circle(const Point3& p, const PencilPoint& witness) const {
        return sign_of(insphere(a_, b_, c_, points_[witness.index], p)) * witness.side > 0;
    }

private:
    std::span<const Point3> points_;
    Point3 a_, b_, c_;
    Vec centre_{};
    double rho2_ = 0;
    Vec normal_{};
};

void sweep_triangle(std::span<const Point3> points,
                    std::uint32_t a,
                    std::uint32_t b,
                    std::uint32_t c,
                    std::vector<PencilPoint>& sweep,
                    std::vector<std::uint32_t>& coplanar,
                    std::vector<std::uint64_t>& f) {
    const auto n = static_cast<std::uint32_t>(points.size());
    sweep.clear();
    coplanar.clear();
    const Pencil pencil(points, a, b, c);
    for (std::uint32_t y = 0; y < n; ++y) {
        if (y == a || y == b || y == c) {
            continue;
        }
        const int side = sign_of(orient3d(points[a], points[b], points[c], points[y]));
        if (side == 0) {
            coplanar.push_back(y);
        } else {
            sweep.push_back({y, side, pencil.approximate_lambda(points[y])});
        }
    }
    if (sweep.empty()) {
        return;  // a, b, c collinear, or every point in one plane: no tetrahedron on abc
    }
    std::sort(sweep.begin(), sweep.end(), [](const PencilPoint& p, const PencilPoint& q) {
        return p.lambda < q.lambda;
    });
    // The double order is almost right; insertion sort with the exact comparison repairs it in
    // O(n + inversions) exact calls and is correct whatever order it starts from.
    for (std::size_t i = 1; i < sweep.size(); ++i) {
        const PencilPoint moving = sweep[i];
        std::size_t k = i;
        while (k > 0 && pencil.compare(sweep[k - 1], moving) > 0) {
            sweep[k] = sweep[k - 1];
            --k;
        }
        sweep[k] = moving;
    }
    std::uint64_t inside_circle = 0;
    for (std::uint32_t y : coplanar) {
        inside_circle += pencil.inside_circle(points[y], sweep.front()) ? 1 : 0;
    }
    std::uint64_t below_total = 0;
    for (const PencilPoint& p : sweep) {
        below_total += p.side < 0 ? 1 : 0;
    }
    // Walk the groups of equal λ (cospherical with abc): points of the group are on the sphere,
    // not inside it.
    std::uint64_t above_before = 0;
    std::uint64_t below_up_to = 0;
    std::size_t begin = 0;
    while (begin < sweep.size()) {
        std::size_t end = begin + 1;
        while (end < sweep.size() && pencil.compare(sweep[begin], sweep[end]) == 0) {
            ++end;
        }
        std::uint64_t group_above = 0;
        for (std::size_t i = begin; i < end; ++i) {
            (sweep[i].side > 0 ? group_above : below_up_to) += 1;
        }
        const std::uint64_t j = above_before + (below_total - below_up_to) + inside_circle;
        for (std::size_t i = begin; i < end; ++i) {
            if (sweep[i].index > c) {
                ++f[j];
            }
        }
        above_before += group_above;
        begin = end;
    }
}

JTetCounts sized_counts(std::size_t n) {
    JTetCounts counts;
    counts.f.assign(n >= 4 ? n - 3 : 0, 0);
    return counts;
}

void check_size(std::size_t n) {
    if (n > (std::size_t{1} << 20)) {
        throw core::Error("j-tetrahedra: " + std::to_string(n) +
                          " points is far beyond what exact enumeration can handle");
    }
}

}  // namespace

std::vector<std::uint64_t> JTetCounts::cumulative() const {
    std::vector<std::uint64_t> total(f.size());
    std::uint64_t sum = 0;
    for (std::size_t j = 0; j < f.size(); ++j) {
        sum += f[j];
        total[j] = sum;
    }
    return total;
}

JTetCounts count_jtets(std::span<const Point3> points, const JTetProgress& progress) {
    check_size(points.size());
    JTetCounts counts = sized_counts(points.size());
    const auto n = static_cast<std::uint32_t>(points.size());
    std::vector<PencilPoint> sweep;
    std::vector<std::uint32_t> coplanar;
    // Progress in triangles swept: each costs one sweep of the n points.
    const auto pairs = [](std::uint64_t m) { return m * (m - 1) / 2; };
    const std::uint64_t triangles = pairs(n) * (n - 2) / 3;
    std::uint64_t swept = 0;
    for (std::uint32_t a = 0; a + 3 < n; ++a) {
        for (std::uint32_t b = a + 1; b + 2 < n; ++b) {
            if (progress) {
                progress(swept, triangles);
            }
            swept += n - b - 2;
            for (std::uint32_t c = b + 1; c + 1 < n; ++c) {
                sweep_triangle(points, a, b, c, sweep, coplanar, counts.f);
            }
        }
    }
    return counts;
}

JTetCounts count_jtets_brute_force(std::span<const Point3> points) {
    check_size(points.size());
    JTetCounts counts = sized_counts(points.size());
    const auto n = static_cast<std::uint32_t>(points.size());
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
            for (std::uint32_t c = b + 1; c < n; ++c) {
                for (std::uint32_t d = c + 1; d < n; ++d) {
                    if (orient3d(points[a], points[b], points[c], points[d]) == Sign::kZero) {
                        continue;
                    }
                    ++counts.f[circumball_count(points, {a, b, c, d}, false)];
                }
            }
        }
    }
    return counts;
}

JTetCounts skew_lines_jtets(std::uint64_t m1, std::uint64_t m2) {
    JTetCounts counts = sized_counts(m1 + m2);
    for (std::uint64_t s = 0; s + 1 < m1; ++s) {
        for (std::uint64_t t = 0; t + 1 < m2; ++t) {
            counts.f[s + t] += (m1 - 1 - s) * (m2 - 1 - t);
        }
    }
    return counts;
}

std::size_t circumball_count(std::span<const Point3> points,
                             std::array<std::uint32_t, 4> tet,
                             bool perturbed) {
    const auto& [a, b, c, d] = tet;
    const Sign orientation = orient3d(points[a], points[b], points[c], points[d]);
    if (orientation == Sign::kZero) {
        throw core::Error("circumball_count: tetrahedron " + std::to_string(a) + " " +
                          std::to_string(b) + " " + std::to_string(c) + " " + std::to_string(d) +
                          " is flat");
    }
    if (orientation == Sign::kNeg) {
        std::swap(tet[0], tet[1]);
    }
    const Point3& pa = points[tet[0]];
    const Point3& pb = points[tet[1]];
    const Point3& pc = points[tet[2]];
    const Point3& pd = points[tet[3]];
    std::size_t inside = 0;
    for (std::uint32_t y = 0; y < points.size(); ++y) {
        if (y == a || y == b || y == c || y == d) {
            continue;
        }
        const Sign s = perturbed
                           ? perturbation::insphere_sos(
                                 pa, pb, pc, pd, points[y], {tet[0], tet[1], tet[2], tet[3], y})
                           : insphere(pa, pb, pc, pd, points[y]);
        inside += s == Sign::kPos ? 1 : 0;
    }
    return inside;
}

}  // namespace cavity::experiments
