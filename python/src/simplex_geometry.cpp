#include "simplex_geometry.h"

#include <array>
#include <cmath>
#include <limits>

namespace cavity::python {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 minus(const core::Point3& a, const core::Point3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// det of the 3x3 matrix with rows a, b, c.
double det3(const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot(a, cross(b, c));
}

}  // namespace

std::vector<double> barycentric_transforms(std::span<const core::Point3> points,
                                           std::span<const core::Tet> simplices) {
    std::vector<double> out(12 * simplices.size());
    for (std::size_t t = 0; t < simplices.size(); ++t) {
        const core::Tet& s = simplices[t];
        const core::Point3& last = points[s[3]];
        const Vec3 a = minus(points[s[0]], last);
        const Vec3 b = minus(points[s[1]], last);
        const Vec3 c = minus(points[s[2]], last);
        // The inverse of the matrix with columns a, b, c has rows b x c, c x a, a x b over det.
        const std::array<Vec3, 3> rows{cross(b, c), cross(c, a), cross(a, b)};
        const double det = dot(a, rows[0]);
        double* o = &out[12 * t];
        for (std::size_t r = 0; r < 3; ++r) {
            for (std::size_t k = 0; k < 3; ++k) {
                o[3 * r + k] =
                    det == 0.0 ? std::numeric_limits<double>::quiet_NaN() : rows[r][k] / det;
            }
        }
        o[9] = last.x;
        o[10] = last.y;
        o[11] = last.z;
    }
    return out;
}

std::vector<double> lifted_hyperplanes(std::span<const core::Point3> points,
                                       std::span<const core::Tet> simplices,
                                       double scale,
                                       double shift) {
    std::vector<double> out(5 * simplices.size());
    const auto lift = [&](const core::Point3& p) {
        return std::array<double, 4>{
            p.x, p.y, p.z, scale * (p.x * p.x + p.y * p.y + p.z * p.z) + shift};
    };
    for (std::size_t t = 0; t < simplices.size(); ++t) {
        const core::Tet& s = simplices[t];
        const std::array<double, 4> z0 = lift(points[s[0]]);
        std::array<std::array<double, 4>, 3> e{};
        for (std::size_t i = 0; i < 3; ++i) {
            const std::array<double, 4> zi = lift(points[s[i + 1]]);
            for (std::size_t k = 0; k < 4; ++k) {
                e[i][k] = zi[k] - z0[k];
            }
        }
        // The 4-D cross product of the three edges, by cofactors along the missing column.
        std::array<double, 4> n{};
        for (std::size_t k = 0; k < 4; ++k) {
            std::array<Vec3, 3> minor{};
            for (std::size_t i = 0; i < 3; ++i) {
                std::size_t c = 0;
                for (std::size_t j = 0; j < 4; ++j) {
                    if (j != k) {
                        minor[i][c++] = e[i][j];
                    }
                }
            }
            n[k] = (k % 2 == 0 ? 1.0 : -1.0) * det3(minor[0], minor[1], minor[2]);
        }
        double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
        if (n[3] > 0) {
            norm = -norm;  // outward from the lower hull: downwards
        }
        double* o = &out[5 * t];
        double offset = 0.0;
        for (std::size_t k = 0; k < 4; ++k) {
            o[k] = n[k] / norm;
            offset -= o[k] * z0[k];
        }
        o[4] = offset;
    }
    return out;
}

}  // namespace cavity::python
