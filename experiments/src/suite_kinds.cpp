#include "suite_kinds.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "cavity/experiments/measure.h"

namespace cavity::experiments {

namespace {

using Tier = TierSettings;

// Costs are rough operation counts, only compared with each other.
constexpr std::array<SuiteKindInfo, 11> kKinds{{
    {SuiteKind::kRuns,
     "runs",
     [](const Suite& s, const Tier&, const RunSpec& r) { return measure::triangulation(s, r); },
     measure::triangulation_columns,
     nullptr,
     [](const Suite& s, const Tier&, const RunSpec& r) {
         return static_cast<double>(r.n) * (s.validates(r.n) ? 10 : 1);
     },
     true,
     true,
     true,
     false,
     true},
    {SuiteKind::kJTets,
     "jtets",
     [](const Suite&, const Tier&, const RunSpec& r) { return measure::jtets(r); },
     measure::jtets_columns,
     measure::jtets_j_columns,
     [](const Suite&, const Tier&, const RunSpec& r) {
         return std::pow(static_cast<double>(r.n), 4) * 1e-3;
     },
     false,
     false,
     false,
     false,
     false},
    {SuiteKind::kCreation,
     "creation",
     measure::creation,
     measure::creation_columns,
     measure::creation_j_columns,
     [](const Suite&, const Tier& t, const RunSpec& r) {
         const auto n = static_cast<double>(r.n);
         return n * n * static_cast<double>(t.orders);
     },
     true,
     false,
     false,
     true,
     false},
    {SuiteKind::kDegenerate,
     "degenerate",
     [](const Suite& s, const Tier&, const RunSpec& r) { return measure::triangulation(s, r); },
     measure::triangulation_columns,
     nullptr,
     [](const Suite&, const Tier&, const RunSpec& r) { return static_cast<double>(r.n) * 10; },
     true,
     true,
     true,
     false,
     true},
    {SuiteKind::kPeers,
     "peers",
     [](const Suite& s, const Tier&, const RunSpec& r) { return measure::peers(s, r); },
     measure::peers_columns,
     nullptr,
     [](const Suite&, const Tier&, const RunSpec& r) { return static_cast<double>(r.n) * 3; },
     true,
     true,
     true,
     false,
     false},
    {SuiteKind::kGiftWrap,
     "giftwrap",
     [](const Suite& s, const Tier&, const RunSpec& r) { return measure::giftwrap(s, r); },
     measure::giftwrap_columns,
     nullptr,
     [](const Suite&, const Tier&, const RunSpec& r) {  // O(nh) apex tests
         const auto n = static_cast<double>(r.n);
         return n * n * 0.1;
     },
     true,
     false,
     false,
     false,
     false},
    {SuiteKind::kDeletion,
     "deletion",
     measure::deletion,
     measure::deletion_columns,
     measure::deletion_j_columns,
     [](const Suite&, const Tier& t, const RunSpec& r) {
         return static_cast<double>(r.n) * 3 + static_cast<double>(t.deletions) * 100;
     },
     false,
     false,
     false,
     false,
     false},
    {SuiteKind::kCdt,
     "cdt",
     [](const Suite& s, const Tier&, const RunSpec& r) { return measure::cdt(s, r); },
     measure::cdt_columns,
     measure::cdt_j_columns,
     [](const Suite&, const Tier&, const RunSpec& r) {  // region scans: O(h) per polygon
         const auto n = static_cast<double>(r.n);
         return n * n * 0.01;
     },
     false,
     false,
     false,
     false,
     false},
    {SuiteKind::kHj,
     "hj",
     measure::hj,
     measure::hj_columns,
     measure::hj_j_columns,
     [](const Suite&, const Tier& t, const RunSpec& r) {
         const auto n = static_cast<double>(r.n);
         return n * std::log(n + 1) * static_cast<double>(t.orders);
     },
     true,
     false,
     false,
     true,
     false},
    {SuiteKind::kLocality,
     "locality",
     [](const Suite& s, const Tier&, const RunSpec& r) { return measure::locality(s, r); },
     measure::locality_columns,
     nullptr,
     // It traces the array storage, so only its locator varies.
     [](const Suite&, const Tier&, const RunSpec& r) { return static_cast<double>(r.n) * 4; },
     true,
     true,
     false,
     false,
     false},
    {SuiteKind::kExtend,
     "extend",
     measure::extend,
     measure::extend_columns,
     measure::extend_j_columns,
     [](const Suite&, const Tier& t, const RunSpec& r) {
         // Exercise 2's bound t^2 + t s^2 for the largest T, per order.
         const auto n = static_cast<double>(r.n);
         const double added =
             t.added.empty()
                 ? n
                 : static_cast<double>(*std::max_element(t.added.begin(), t.added.end()));
         return static_cast<double>(t.orders) * added * (added + n * n);
     },
     true,
     false,
     false,
     true,
     false},
}};

// Row i describes the kind whose value is i, so that a lookup is an index.
static_assert([] {
    for (std::size_t i = 0; i < kKinds.size(); ++i) {
        if (static_cast<std::size_t>(kKinds[i].kind) != i) {
            return false;
        }
    }
    return static_cast<std::size_t>(SuiteKind::kExtend) + 1 == kKinds.size();
}());

}  // namespace

std::span<const SuiteKindInfo> suite_kinds() {
    return kKinds;
}

const SuiteKindInfo& suite_kind_info(SuiteKind kind) {
    return kKinds[static_cast<std::size_t>(kind)];
}

}  // namespace cavity::experiments
