#pragma once

#include <pybind11/pybind11.h>

#include "cavity/core/geometry/counters.h"

namespace cavity::python {

namespace py = pybind11;

/// Counters as a dict: one key per counter (the names of cavity::core::Counters), and
/// "stage_calls": {predicate: {stage: calls}} for orient3d, insphere, orient4d and ghost.
py::dict counters_dict(const core::Counters& counters);

}  // namespace cavity::python
