#include "cavity/core/cdt/exact_points_file.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <variant>
#include <vector>

#include "cavity/core/base/error.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

using predicates::GenericPoint3;
using predicates::LinePlanePoint;
using predicates::SegmentParameterPoint;

std::string hex(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%a", v);
    return buffer;
}

std::string hex(const Point3& p) {
    return hex(p.x) + " " + hex(p.y) + " " + hex(p.z);
}

bool same(const Point3& p, const Point3& q) {
    return p.x == q.x && p.y == q.y && p.z == q.z;
}

}  // namespace

std::string exact_points_text(const PointSet& points) {
    std::vector<std::size_t> implicit;
    for (std::size_t i = 0; i < points.exact.size(); ++i) {
        if (!std::holds_alternative<Point3>(points.exact[i])) {
            implicit.push_back(i);
        }
    }
    std::string text =
        "# cavity: exact Steiner points; the .node file has them rounded to nearest\n"
        "# INDEX segment A B NUMERATOR DENOMINATOR : X Y Z   (a + (NUMERATOR/DENOMINATOR)(b - a))\n"
        "# INDEX line_plane A B P Q R : X Y Z   (line AB meets plane PQR)\n"
        "# defining doubles as C99 hex floats (exact); X Y Z the exact rational coordinates\n" +
        std::to_string(implicit.size()) + "\n";
    for (std::size_t i : implicit) {
        const GenericPoint3& g = points.exact[i];
        text += std::to_string(i + static_cast<std::size_t>(points.index_base));
        if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
            text += " segment " + hex(s->a) + " " + hex(s->b) + " " + hex(s->numerator) + " " +
                    hex(s->denominator);
        } else {
            const auto& l = std::get<LinePlanePoint>(g);
            text += " line_plane " + hex(l.a) + " " + hex(l.b) + " " + hex(l.p) + " " + hex(l.q) +
                    " " + hex(l.r);
        }
        const ExactPoint e = exact_point(g);
        text += " : " + e[0].str() + " " + e[1].str() + " " + e[2].str() + "\n";
    }
    return text;
}

void read_exact_points(const std::string& file, PointSet& points) {
    std::ifstream in(file);
    if (!in) {
        throw Error(file + ": cannot open");
    }
    points.exact.assign(points.points.begin(), points.points.end());
    std::string line;
    std::size_t number = 0;
    bool counted = false;
    const auto fail = [&](const std::string& what) {
        throw Error(located_message(file, number, what));
    };
    while (std::getline(in, line)) {
        ++number;
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string first;
        if (!(words >> first)) {
            continue;
        }
        if (!counted) {
            counted = true;  // the count line: the lines that follow are the points
            continue;
        }
        const auto read = [&]() {
            std::string w;
            if (!(words >> w)) {
                fail("too few numbers");
            }
            char* end = nullptr;
            const double v = std::strtod(w.c_str(), &end);
            if (end != w.c_str() + w.size()) {
                fail("not a number: " + w);
            }
            return v;
        };
        const auto read_point = [&]() {
            const double x = read();
            const double y = read();
            const double z = read();
            return Point3{x, y, z};
        };
        const long long index = std::atoll(first.c_str()) - points.index_base;
        if (index < 0 || static_cast<std::size_t>(index) >= points.size()) {
            fail("point " + first + " is not a point of the .node file");
        }
        std::string kind;
        words >> kind;
        GenericPoint3 g;
        if (kind == "segment") {
            const Point3 a = read_point();
            const Point3 b = read_point();
            const double numerator = read();
            const double denominator = read();
            const auto s = predicates::segment_parameter_point(a, b, numerator, denominator);
            if (!s) {
                fail("not a point (zero denominator or a non-finite number)");
            }
            g = *s;
        } else if (kind == "line_plane") {
            const Point3 a = read_point();
            const Point3 b = read_point();
            const Point3 p = read_point();
            const Point3 q = read_point();
            const Point3 r = read_point();
            const auto l = predicates::line_plane_point(a, b, p, q, r);
            if (!l) {
                fail("the line does not meet the plane in one point");
            }
            g = *l;
        } else {
            fail("unknown kind '" + kind + "' (segment or line_plane)");
        }
        const auto i = static_cast<std::size_t>(index);
        if (!same(rounded_point(g), points.points[i])) {
            fail("point " + first + " rounds to other coordinates than the .node file has");
        }
        points.exact[i] = g;
    }
}

}  // namespace cavity::core
