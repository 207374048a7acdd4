// cavity.orient3d / insphere / orient4d: the exact predicates over arrays of queries.

#include <array>
#include <cstdint>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"
#include "input_arrays.h"

namespace cavity::python {

namespace {

/// One argument of a vectorised predicate: a single point (shape (width,)), used for every query,
/// or one point per query (shape (k, width)).
struct Operand {
    DoubleArray values;
    bool single = false;
};

template <std::size_t Arity>
struct Queries {
    std::array<Operand, Arity> operands;
    py::ssize_t count = 1;
    bool scalar = true;  ///< every operand was a single point: return a 0-d array
};

template <std::size_t Arity>
Queries<Arity> read_queries(const std::array<py::handle, Arity>& args, py::ssize_t width) {
    constexpr std::array<const char*, 5> kNames{"a", "b", "c", "d", "e"};
    Queries<Arity> q;
    for (std::size_t i = 0; i < Arity; ++i) {
        DoubleArray a = DoubleArray::ensure(args[i]);
        if (a && a.ndim() == 1) {
            // A single point: check it as a one-row array, then keep it flat.
            a = require_rows(a.reshape({py::ssize_t{1}, a.shape(0)}), kNames[i], width);
            q.operands[i] = {a, true};
            continue;
        }
        a = require_rows(args[i], kNames[i], width);
        if (!q.scalar && a.shape(0) != q.count) {
            throw py::value_error(std::string(kNames[i]) + " has " + std::to_string(a.shape(0)) +
                                  " rows, the other arguments " + std::to_string(q.count));
        }
        q.count = a.shape(0);
        q.scalar = false;
        q.operands[i] = {a, false};
    }
    return q;
}

template <std::size_t Arity, class Point, class Predicate>
py::array_t<std::int8_t> evaluate(const std::array<py::handle, Arity>& args, Predicate predicate) {
    constexpr auto width = static_cast<py::ssize_t>(sizeof(Point) / sizeof(double));
    const Queries<Arity> q = read_queries<Arity>(args, width);
    py::array_t<std::int8_t> signs(q.scalar ? std::vector<py::ssize_t>{}
                                            : std::vector<py::ssize_t>{q.count});
    std::int8_t* out = signs.mutable_data();
    std::array<const Point*, Arity> base{};
    std::array<py::ssize_t, Arity> stride{};
    for (std::size_t i = 0; i < Arity; ++i) {
        base[i] = reinterpret_cast<const Point*>(q.operands[i].values.data());
        stride[i] = q.operands[i].single ? 0 : 1;
    }
    py::gil_scoped_release nogil;
    for (py::ssize_t k = 0; k < q.count; ++k) {
        std::array<const Point*, Arity> p{};
        for (std::size_t i = 0; i < Arity; ++i) {
            p[i] = base[i] + k * stride[i];
        }
        out[k] = static_cast<std::int8_t>(predicates::to_int(
            std::apply([&](const auto*... pts) { return predicate(*pts...); }, p)));
    }
    return signs;
}

}  // namespace

void bind_predicates(py::module_& m) {
    using predicates::Point3;
    using predicates::WeightedPoint3;
    m.def(
        "orient3d",
        [](const py::handle& a, const py::handle& b, const py::handle& c, const py::handle& d) {
            return evaluate<4, Point3>({a, b, c, d},
                                       [](const auto&... p) { return predicates::orient3d(p...); });
        },
        py::arg("a"),
        py::arg("b"),
        py::arg("c"),
        py::arg("d"),
        R"doc(Exact sign of det[a-d; b-d; c-d] for each query, as int8 (-1, 0, +1).

+1 when a, b, c, d are positively oriented: d lies below the plane of a, b, c seen with a, b, c
counter-clockwise from above (Shewchuk's convention). Each argument is an (k, 3) array (one point
per query) or a (3,) point used for every query; with only (3,) arguments the result is 0-d.
Exact for every finite double; ValueError for NaN, infinity or a wrong shape.)doc");
    m.def(
        "insphere",
        [](const py::handle& a,
           const py::handle& b,
           const py::handle& c,
           const py::handle& d,
           const py::handle& e) {
            return evaluate<5, Point3>({a, b, c, d, e},
                                       [](const auto&... p) { return predicates::insphere(p...); });
        },
        py::arg("a"),
        py::arg("b"),
        py::arg("c"),
        py::arg("d"),
        py::arg("e"),
        R"doc(Exact insphere sign for each query, as int8 (-1, 0, +1).

+1 when e lies inside the circumsphere of a, b, c, d if they are positively oriented (the sign
flips when they are negatively oriented), 0 when the five points are cospherical or a, b, c, d are
coplanar. Arguments as for orient3d.)doc");
    m.def(
        "orient4d",
        [](const py::handle& a,
           const py::handle& b,
           const py::handle& c,
           const py::handle& d,
           const py::handle& e) {
            return evaluate<5, WeightedPoint3>(
                {a, b, c, d, e}, [](const auto&... p) { return predicates::orient4d(p...); });
        },
        py::arg("a"),
        py::arg("b"),
        py::arg("c"),
        py::arg("d"),
        py::arg("e"),
        R"doc(Exact power test for weighted points [x, y, z, w], as int8 (-1, 0, +1).

Sign of det[p-e, h_p-h_e] over p = a, b, c, d with lifted heights h = x^2+y^2+z^2-w computed
exactly: +1 when e is in conflict with the weighted tetrahedron abcd if it is positively oriented.
Equals insphere when every weight is 0. Each argument is (k, 4) or (4,).)doc");
}

}  // namespace cavity::python
