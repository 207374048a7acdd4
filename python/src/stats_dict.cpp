#include "stats_dict.h"

#include <array>
#include <string>

namespace cavity::python {

py::dict counters_dict(const core::Counters& c) {
    py::dict d;
    // Theorem 5.4's conflicts are zero unless the run counted them (locate="conflict-graph-all").
    for (const core::CounterField& counter : core::kCounterFields) {
        d[py::str(std::string(counter.name))] = c.*counter.field;
    }
    py::dict stages;
    for (std::size_t k = 0; k < core::kPredicateKindNames.size(); ++k) {
        py::dict per_stage;
        for (int s = 0; s < predicates::kStageCount; ++s) {
            per_stage[py::str(
                std::string(predicates::stage_name(static_cast<predicates::Stage>(s))))] =
                c.stage_calls[k][static_cast<std::size_t>(s)];
        }
        stages[py::str(std::string(core::kPredicateKindNames[k]))] = per_stage;
    }
    d["stage_calls"] = stages;
    return d;
}

}  // namespace cavity::python
