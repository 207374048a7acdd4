#include "cavity/experiments/run.h"

#include <algorithm>
#include <cmath>

#include "cavity/experiments/measure.h"

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
    const bool triangulates = suite.kind == SuiteKind::kRuns ||
                              suite.kind == SuiteKind::kDegenerate ||
                              suite.kind == SuiteKind::kPeers;
    // The locality kind traces the array storage, so only its locator varies.
    const bool locates = triangulates || suite.kind == SuiteKind::kLocality;
    const std::vector<std::string> none{"-"};
    // Only insertion-order experiments vary the order: jtets has none, deletion builds with a
    // BRIO (its result does not depend on the order), cdt inserts the PLC's points in input order.
    const bool ordered = suite.kind != SuiteKind::kJTets && suite.kind != SuiteKind::kDeletion &&
                         suite.kind != SuiteKind::kCdt;
    const auto& orders = ordered ? suite.orders : none;
    const auto& locators = locates ? suite.locators : none;
    const auto& storages = triangulates ? suite.storages : none;
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
    const auto n = static_cast<double>(run.n);
    switch (suite.kind) {
        case SuiteKind::kJTets:
            return std::pow(n, 4) * 1e-3;
        case SuiteKind::kCreation:
            return n * n * static_cast<double>(tier.orders);
        case SuiteKind::kHj:
            return n * std::log(n + 1) * static_cast<double>(tier.orders);
        case SuiteKind::kDegenerate:
            return n * 10;
        case SuiteKind::kPeers:
            return n * 3;
        case SuiteKind::kLocality:
            return n * 4;
        case SuiteKind::kGiftWrap:
            return n * n * 0.1;  // O(nh) apex tests
        case SuiteKind::kDeletion:
            return n * 3 + static_cast<double>(tier.deletions) * 100;
        case SuiteKind::kCdt:
            return n * n * 0.01;    // region scans: O(h) per polygon
        case SuiteKind::kExtend: {  // Exercise 2's bound t^2 + t s^2 for the largest T, per order
            const double t =
                tier.added.empty()
                    ? n
                    : static_cast<double>(*std::max_element(tier.added.begin(), tier.added.end()));
            return static_cast<double>(tier.orders) * t * (t + n * n);
        }
        case SuiteKind::kRuns:
            break;
    }
    return n * (suite.validates(run.n) ? 10 : 1);
}

std::vector<std::string> metric_columns(SuiteKind kind) {
    switch (kind) {
        case SuiteKind::kJTets:
            return measure::jtets_columns();
        case SuiteKind::kCreation:
            return measure::creation_columns();
        case SuiteKind::kHj:
            return measure::hj_columns();
        case SuiteKind::kPeers:
            return measure::peers_columns();
        case SuiteKind::kLocality:
            return measure::locality_columns();
        case SuiteKind::kGiftWrap:
            return measure::giftwrap_columns();
        case SuiteKind::kDeletion:
            return measure::deletion_columns();
        case SuiteKind::kCdt:
            return measure::cdt_columns();
        case SuiteKind::kExtend:
            return measure::extend_columns();
        case SuiteKind::kRuns:
        case SuiteKind::kDegenerate:
            break;
    }
    return measure::triangulation_columns();
}

std::vector<std::string> j_columns(SuiteKind kind) {
    switch (kind) {
        case SuiteKind::kJTets:
            return measure::jtets_j_columns();
        case SuiteKind::kCreation:
            return measure::creation_j_columns();
        case SuiteKind::kHj:
            return measure::hj_j_columns();
        case SuiteKind::kDeletion:
            return measure::deletion_j_columns();
        case SuiteKind::kCdt:
            return measure::cdt_j_columns();
        case SuiteKind::kExtend:
            return measure::extend_j_columns();
        case SuiteKind::kGiftWrap:
        case SuiteKind::kPeers:
        case SuiteKind::kLocality:
        case SuiteKind::kRuns:
        case SuiteKind::kDegenerate:
            break;
    }
    return {};
}

RunOutput execute_run(const Suite& suite, const TierSettings& tier, const RunSpec& run) {
    switch (suite.kind) {
        case SuiteKind::kJTets:
            return measure::jtets(run);
        case SuiteKind::kCreation:
            return measure::creation(suite, tier, run);
        case SuiteKind::kHj:
            return measure::hj(suite, tier, run);
        case SuiteKind::kPeers:
            return measure::peers(suite, run);
        case SuiteKind::kLocality:
            return measure::locality(suite, run);
        case SuiteKind::kGiftWrap:
            return measure::giftwrap(suite, run);
        case SuiteKind::kDeletion:
            return measure::deletion(suite, tier, run);
        case SuiteKind::kCdt:
            return measure::cdt(suite, run);
        case SuiteKind::kExtend:
            return measure::extend(suite, tier, run);
        case SuiteKind::kRuns:
        case SuiteKind::kDegenerate:
            break;
    }
    return measure::triangulation(suite, run);
}

}  // namespace cavity::experiments
