#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>

namespace cavity::python {

namespace py = pybind11;

/// A read-only numpy array of Out that takes ownership of `values` without copying them. For the
/// default int32, T is std::int32_t, std::uint32_t (ids < 2^31, so the bits are the same) or an
/// array of them; otherwise T is Out.
template <class Out = std::int32_t, class T>
py::array_t<Out> adopt(std::vector<T>&& values, const std::vector<py::ssize_t>& shape) {
    static_assert(sizeof(T) % sizeof(Out) == 0);
    auto* heap = new std::vector<T>(std::move(values));
    py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    py::array_t<Out> array(shape, reinterpret_cast<const Out*>(heap->data()), owner);
    array.attr("setflags")(py::arg("write") = false);
    return array;
}

}  // namespace cavity::python
