#include "cavity/experiments/run.h"

#include "suite_kinds.h"

namespace cavity::experiments {

std::vector<std::string> key_columns() {
    return {"dist", "n", "order", "locate", "storage", "seed"};
}

std::vector<std::string> key_values(const RunSpec& run) {
    return {run.dist,
            std::to_string(run.n),
            run.order,
            run.locate,
            run.storage,
            std::to_string(run.seed)};
}

std::vector<RunSpec> enumerate_runs(const Suite& suite, const TierSettings& tier) {
    std::vector<RunSpec> runs;
    const SuiteKindInfo& kind = suite_kind_info(suite.kind);
    const std::vector<std::string> none{"-"};
    const auto& orders = kind.ordered ? suite.orders : none;
    const auto& locators = kind.locates ? suite.locators : none;
    const auto& storages = kind.stores ? suite.storages : none;
    // Sizes outermost: a long tier, stopped and resumed, has finished every smaller size first.
    for (std::uint64_t n : tier.sizes) {
        for (const std::string& dist : suite.distributions) {
            const auto cap = suite.caps.find(dist);
            if (cap != suite.caps.end() && n > cap->second) {
                continue;
            }
            for (std::uint64_t seed : tier.seeds) {
                for (const std::string& order : orders) {
                    for (const std::string& locate : locators) {
                        for (const std::string& storage : storages) {
                            runs.push_back({dist, n, order, locate, storage, seed});
                        }
                    }
                }
            }
        }
    }
    return runs;
}

double run_cost(const Suite& suite, const TierSettings& tier, const RunSpec& run) {
    return suite_kind_info(suite.kind).cost(suite, tier, run);
}

std::vector<std::string> metric_columns(SuiteKind kind) {
    return suite_kind_info(kind).columns();
}

std::vector<std::string> j_columns(SuiteKind kind) {
    const auto columns = suite_kind_info(kind).j_columns;
    return columns == nullptr ? std::vector<std::string>{} : columns();
}

RunOutput execute_run(const Suite& suite, const TierSettings& tier, const RunSpec& run) {
    return suite_kind_info(suite.kind).measure(suite, tier, run);
}

}  // namespace cavity::experiments
