#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/edge_protection.h"
#include "cavity/core/cdt/polygon_insertion.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/experiments/measure.h"
#include "cavity/experiments/plc_families.h"
#include "format.h"

namespace cavity::experiments::measure {

namespace {

using detail::number;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double ratio(double a, double b) {
    return b > 0 ? a / b : 0.0;
}

/// m^2 log m, the event bound of Proposition 5.5 (natural log; 0 for m < 2).
double m2_log_m(double m) {
    return m >= 2 ? m * m * std::log(m) : 0.0;
}

std::uint64_t total_flips(const core::RetriangulationCounters& c) {
    return std::accumulate(c.flips.begin(), c.flips.end(), std::uint64_t{0});
}

}  // namespace

std::vector<std::string> cdt_columns() {
    return {"points",
            "polygons",
            "protection_points",
            "vertices",
            "tets",
            "protect_s",
            "dt_s",
            "insert_s",
            "validate_s",
            "flips",
            "flips_23",
            "flips_32",
            "flips_14",
            "flips_41",
            "flips_22",
            "flips_44",
            "flips_refused",
            "certify_calls",
            "events_queued",
            "events_stale",
            "events_held",
            "region_tets",
            "sum_m",
            "max_m",
            "rotary_steps",
            "search_visited",
            "search_per_region_tet",
            "flips_per_n2",
            "events_per_n2_log_n",
            "polygon_records",
            "sum_m2",
            "flips_per_sum_m2",
            "max_flips_per_m2",
            "polygons_at_or_over_m2",
            "max_events_per_m2_log_m",
            "valid",
            "cdt_problems"};
}

std::vector<std::string> cdt_j_columns() {
    return {"polygon",
            "facet",
            "m",
            "region_tets",
            "rotary_steps",
            "search_visited",
            "flips",
            "events_queued",
            "flips_per_m2",
            "events_per_m2_log_m",
            "flips_below_m2",
            "us"};
}

RunOutput cdt(const Suite& suite, const RunSpec& run) {
    core::Plc plc = make_plc_family(run.dist, run.n, run.seed);
    const std::size_t input_points = plc.points.size();
    // build_cdt's steps one by one, each on its own clock: edge protection, the Delaunay
    // triangulation of the vertices, then FlipInsertPolygon for each polygon in order (timed
    // alone: build_cdt also validates, whose cost is not the algorithm's).
    auto start = Clock::now();
    const core::Protection protection = core::protect_edges(plc, 1000000);
    const double protect_s = seconds_since(start);

    std::vector<std::uint32_t> sequence(plc.points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    start = Clock::now();
    const core::Triangulation dt = core::triangulate(plc.points, sequence, {});
    const double dt_s = seconds_since(start);
    if (!dt.duplicates.empty() || !core::unprotected_edges(plc, dt.tets).empty()) {
        throw core::Error(plc.source + ": repeated points or unprotected edges after protection");
    }

    core::ArrayStorage storage = core::complex_from_tets(dt.tets);
    const core::Geometry geometry = core::geometry_by_index(plc.points);
    core::ConstrainedFaces constrained;
    core::PolygonInsertionCounters c;
    std::vector<double> polygon_s;
    double insert_s = 0;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        start = Clock::now();
        core::insert_polygon(storage, geometry, plc, f, constrained, c);
        polygon_s.push_back(seconds_since(start));
        insert_s += polygon_s.back();
    }
    const std::vector<std::array<std::uint32_t, 4>> tets = core::solid_tets(storage);

    // An invalid result is a finding to tabulate (valid 0, its problem count), not a reason to
    // lose the suite's other runs.
    std::string valid = "-";
    std::string problems = "-";
    double validate_s = 0;
    if (suite.validates(run.n)) {
        start = Clock::now();
        const core::CdtValidation check = core::validate_cdt(plc, tets);
        validate_s = seconds_since(start);
        valid = check.ok() ? "1" : "0";
        problems = number(std::uint64_t{check.problem_count});
    }

    const std::uint64_t flips = total_flips(c.flips);
    const auto n = static_cast<double>(plc.points.size());
    RunOutput out;
    double sum_m2 = 0, max_flips_m2 = 0, max_events = 0;
    std::uint64_t over = 0;
    for (std::size_t i = 0; i < c.per_polygon.size(); ++i) {
        const core::PolygonWork& w = c.per_polygon[i];
        const auto m = static_cast<double>(w.region_vertices);
        const double flips_m2 = ratio(static_cast<double>(w.flips), m * m);
        const double events = ratio(static_cast<double>(w.events_queued), m2_log_m(m));
        sum_m2 += m * m;
        max_flips_m2 = std::max(max_flips_m2, flips_m2);
        max_events = std::max(max_events, events);
        // Fewer than m^2 flips; an empty region (the polygon already a union of faces) needs none.
        const bool below = static_cast<double>(w.flips) < std::max(m * m, 1.0);
        over += below ? 0 : 1;
        out.j_rows.push_back({number(std::uint64_t{i}),
                              number(std::uint64_t{w.facet}),
                              number(w.region_vertices),
                              number(w.region_tets),
                              number(w.rotary_steps),
                              number(w.search_visited),
                              number(w.flips),
                              number(w.events_queued),
                              number(flips_m2),
                              number(events),
                              below ? "1" : "0",
                              i < polygon_s.size() ? number(polygon_s[i] * 1e6) : "-"});
    }
    // Without per-polygon records the per-polygon columns are unknown, never zero.
    const bool records = !c.per_polygon.empty();
    const auto known = [records](const std::string& value) {
        return records ? value : std::string("-");
    };
    out.values = {number(std::uint64_t{input_points}),
                  number(std::uint64_t{plc.facets.size()}),
                  number(std::uint64_t{protection.inserted.size()}),
                  number(std::uint64_t{plc.points.size()}),
                  number(std::uint64_t{tets.size()}),
                  number(protect_s),
                  number(dt_s),
                  number(insert_s),
                  number(validate_s),
                  number(flips)};
    for (std::uint64_t k : c.flips.flips) {
        out.values.push_back(number(k));
    }
    const auto events = static_cast<double>(c.events_queued);
    const std::vector<std::string> rest{
        number(c.flips.flips_refused),
        number(c.certify_calls),
        number(c.events_queued),
        number(c.events_stale),
        number(c.events_held),
        number(c.region_tets),
        number(c.region_vertices),
        number(c.max_region_vertices),
        number(c.rotary_steps),
        number(c.search_visited),
        number(ratio(static_cast<double>(c.search_visited), static_cast<double>(c.region_tets))),
        number(ratio(static_cast<double>(flips), n * n)),
        number(ratio(events, n * n * std::log(n))),
        number(std::uint64_t{c.per_polygon.size()}),
        known(number(sum_m2)),
        known(number(ratio(static_cast<double>(flips), sum_m2))),
        known(number(max_flips_m2)),
        known(number(over)),
        known(number(max_events)),
        valid,
        problems};
    out.values.insert(out.values.end(), rest.begin(), rest.end());
    return out;
}

}  // namespace cavity::experiments::measure
