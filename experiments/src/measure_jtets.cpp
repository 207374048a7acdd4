#include <chrono>

#include "cavity/core/gen/generate.h"
#include "cavity/experiments/jtets.h"
#include "cavity/experiments/measure.h"
#include "format.h"

namespace cavity::experiments::measure {

using detail::number;

std::vector<std::string> jtets_columns() {
    return {"points", "time_s", "tets", "f0", "j_max", "closed_form_match"};
}

std::vector<std::string> jtets_j_columns() {
    return {"j", "f_j", "F_j", "closed_form_f_j"};
}

RunOutput jtets(const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    const auto start = std::chrono::steady_clock::now();
    const JTetCounts counts = count_jtets(points.points);
    const double time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::vector<std::uint64_t> cumulative = counts.cumulative();
    // Two skew lines have a closed form (generate's skew-lines: ceil(n/2) then floor(n/2)).
    const bool skew = run.dist == "skew-lines";
    const JTetCounts closed =
        skew ? skew_lines_jtets((points.size() + 1) / 2, points.size() / 2) : JTetCounts{};
    RunOutput out;
    std::uint64_t j_max = 0;
    for (std::size_t j = 0; j < counts.f.size(); ++j) {
        if (counts.f[j] == 0 && !(skew && closed.f[j] != 0)) {
            continue;
        }
        j_max = j;
        out.j_rows.push_back({number(std::uint64_t{j}),
                              number(counts.f[j]),
                              number(cumulative[j]),
                              skew ? number(closed.f[j]) : "-"});
    }
    const std::uint64_t total = cumulative.empty() ? 0 : cumulative.back();
    out.values = {number(std::uint64_t{points.size()}),
                  number(time_s),
                  number(total),
                  number(counts.f.empty() ? 0 : counts.f[0]),
                  number(j_max),
                  skew ? (closed.f == counts.f ? "1" : "0") : "-"};
    return out;
}

}  // namespace cavity::experiments::measure
