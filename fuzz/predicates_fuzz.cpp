// libFuzzer target: the input bytes are read as doubles (non-finite ones skipped) and fill one
// orient3d, one insphere and one orient4d query; each predicate and its _staged variant must give
// the oracle's sign. A disagreement prints the query as a `cavity sign` line and aborts.
// The same doubles also define a line-plane and a segment point (generic_point.h): the
// floating-point stage on their naively rounded coordinates (generic_filter.h), when it answers,
// must give the sign of the generic predicates' exact stages. Segment and line-plane points made
// on the plane of three of the points, with one of those, must give orient3d and insphere 0.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <variant>

#include "cavity/predicates/generic_filter.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"

namespace {

using namespace cavity::predicates;

constexpr std::size_t kValues = 20;  // the largest query, orient4d: 5 points x (x y z w)

// The finite doubles of the input, cycled to fill kValues entries (zeros for an input with none),
// so short inputs still produce queries with repeated, hence degenerate-prone, coordinates.
std::array<double, kValues> values_from(const std::uint8_t* data, std::size_t size) {
    std::array<double, kValues> finite{};
    std::size_t count = 0;
    for (std::size_t offset = 0; offset + sizeof(double) <= size && count < kValues;
         offset += sizeof(double)) {
        double x = 0.0;
        std::memcpy(&x, data + offset, sizeof x);
        if (std::isfinite(x)) {
            finite[count++] = x;
        }
    }
    for (std::size_t i = count; count > 0 && i < kValues; ++i) {
        finite[i] = finite[i % count];
    }
    return finite;
}

void check(const char* name, const double* v, std::size_t n, Sign fast, Sign staged, Sign exact) {
    if (fast == exact && staged == exact) {
        return;
    }
    std::fprintf(stderr,
                 "%s: plain %d, staged %d, oracle %d\nreplay: echo '%s",
                 name,
                 to_int(fast),
                 to_int(staged),
                 to_int(exact),
                 name);
    for (std::size_t i = 0; i < n; ++i) {
        std::fprintf(stderr, " %a", v[i]);
    }
    std::fprintf(stderr, "' | cavity sign --stage\n");
    std::abort();
}

/// g's coordinates computed in doubles, however inaccurately: the stage must be sound for any.
Point3 naive_rounding(const GenericPoint3& g) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        return *p;
    }
    const auto along = [](const Point3& a, const Point3& b, double t) {
        return Point3{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
    };
    if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
        return along(s->a, s->b, s->numerator / s->denominator);
    }
    const auto& l = std::get<LinePlanePoint>(g);
    const auto minus = [](const Point3& u, const Point3& v) {
        return Point3{u.x - v.x, u.y - v.y, u.z - v.z};
    };
    const Point3 u = minus(l.q, l.p), v = minus(l.r, l.p), d = minus(l.b, l.a),
                 pa = minus(l.p, l.a);
    const Point3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
    return along(
        l.a, l.b, (n.x * pa.x + n.y * pa.y + n.z * pa.z) / (n.x * d.x + n.y * d.y + n.z * d.z));
}

void check_rounded(const char* name, int rounded, Sign exact) {
    if (rounded != 0 && rounded != to_int(exact)) {
        std::fprintf(stderr, "%s: rounded stage %d, exact %d\n", name, rounded, to_int(exact));
        std::abort();
    }
}

void check_generic(const std::array<double, kValues>& v) {
    const auto p = [&](std::size_t i) { return Point3{v[3 * i], v[3 * i + 1], v[3 * i + 2]}; };
    const auto lpi = line_plane_point(p(0), p(1), p(2), p(3), p(4));
    const auto lnc = segment_parameter_point(p(1), p(3), v[18], v[19]);
    if (!lpi || !lnc) {
        return;
    }
    const std::array<GenericPoint3, 5> g{*lpi, p(2), *lnc, p(3), p(4)};
    std::array<RoundedPoint, 5> r;
    for (std::size_t i = 0; i < 5; ++i) {
        const Point3 rounded = naive_rounding(g[i]);
        r[i] = {rounded, rounding_error(g[i], rounded)};
    }
    check_rounded("generic orient3d",
                  orient3d_rounded(r[0], r[1], r[2], r[3]),
                  orient3d(g[0], g[1], g[2], g[3]));
    check_rounded("generic insphere",
                  insphere_rounded(r[0], r[1], r[2], r[3], r[4]),
                  insphere(g[0], g[1], g[2], g[3], g[4]));
}

/// Points on the plane of p(0), p(1), p(2) by construction (on a line when those are collinear,
/// and then the line-plane point is undefined): every orient3d and insphere of them is 0.
void check_coplanar(const std::array<double, kValues>& v) {
    const auto p = [&](std::size_t i) { return Point3{v[3 * i], v[3 * i + 1], v[3 * i + 2]}; };
    const auto lpi = line_plane_point(p(3), p(4), p(0), p(1), p(2));
    const auto on_01 = segment_parameter_point(p(0), p(1), v[18], v[19]);
    const auto on_12 = segment_parameter_point(p(1), p(2), v[19], v[18]);
    if (!lpi || !on_01 || !on_12) {
        return;
    }
    const std::array<GenericPoint3, 5> g{*on_01, p(2), *lpi, *on_12, p(0)};
    const Sign orient = orient3d(g[0], g[1], g[2], g[3]);
    const Sign sphere = insphere(g[0], g[1], g[2], g[3], g[4]);
    if (orient != Sign::kZero || sphere != Sign::kZero) {
        std::fprintf(stderr,
                     "coplanar generic points: orient3d %d, insphere %d\n",
                     to_int(orient),
                     to_int(sphere));
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::array<double, kValues> v = values_from(data, size);
    const auto p = [&](std::size_t i) { return Point3{v[3 * i], v[3 * i + 1], v[3 * i + 2]}; };
    const auto w = [&](std::size_t i) {
        return WeightedPoint3{v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]};
    };
    check("orient3d",
          v.data(),
          12,
          orient3d(p(0), p(1), p(2), p(3)),
          orient3d_staged(p(0), p(1), p(2), p(3)).sign,
          oracle::orient3d(p(0), p(1), p(2), p(3)));
    check("insphere",
          v.data(),
          15,
          insphere(p(0), p(1), p(2), p(3), p(4)),
          insphere_staged(p(0), p(1), p(2), p(3), p(4)).sign,
          oracle::insphere(p(0), p(1), p(2), p(3), p(4)));
    check("orient4d",
          v.data(),
          20,
          orient4d(w(0), w(1), w(2), w(3), w(4)),
          orient4d_staged(w(0), w(1), w(2), w(3), w(4)).sign,
          oracle::orient4d(w(0), w(1), w(2), w(3), w(4)));
    check_generic(v);
    check_coplanar(v);
    return 0;
}
