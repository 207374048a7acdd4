#pragma once

#include "cavity/core/input/point_set.h"
#include "cavity/experiments/run.h"

/// The measurements of each suite kind (one file each); execute_run dispatches to them.
namespace cavity::experiments::measure {

/// Triangulates with the counting engine: time, work counters, predicate stages, memory, the
/// canonical hash of the output and (when the suite asks) exact validation.
RunOutput triangulation(const Suite& suite, const RunSpec& run);
std::vector<std::string> triangulation_columns();

/// Exact f_j and F_j by the pencil sweep, with the closed form for skew lines.
RunOutput jtets(const RunSpec& run);
std::vector<std::string> jtets_columns();
std::vector<std::string> jtets_j_columns();

/// Many insertion orders of one point set: the life of every created tetrahedron checked
/// against the creation rule, and created j-tetrahedra tallied against f_j (q_j estimates).
RunOutput creation(const Suite& suite, const TierSettings& tier, const RunSpec& run);
std::vector<std::string> creation_columns();
std::vector<std::string> creation_j_columns();

/// Many insertion orders of one point set, too large for the pencil sweep: the created
/// j-tetrahedra of each order counted exactly (ConflictCountingObserver), their mean per order by
/// j (h_j), and Σj. Under a uniform order E[h_j] = f_j / C(j+4, 4), so a BRIO's q_j is estimated
/// as its mean h_j over the uniform order's, times 1/C(j+4, 4) (Proposition 5.3 at large n).
RunOutput hj(const Suite& suite, const TierSettings& tier, const RunSpec& run);
std::vector<std::string> hj_columns();
std::vector<std::string> hj_j_columns();

/// §5.3's locality: the engine's tetrahedron and point records touched per insertion, as 64-byte
/// lines and 4 KiB pages, and the misses of LRU caches of several sizes (memory_model.h), with the
/// walk as locator. Compares uniform, BRIO and space-filling orders.
RunOutput locality(const Suite& suite, const RunSpec& run);
std::vector<std::string> locality_columns();

/// cavity against its peers on the same points, each engine in a child process of its own: CPU
/// seconds, tetrahedra and peak memory of cavity (order + triangulation), CGAL's
/// Delaunay_triangulation_3 (when built with CGAL) and TetGen (when `tetgen` is on PATH), and
/// cavity's ratios to each. A peer that is not there is reported as unavailable, never an error.
RunOutput peers(const Suite& suite, const RunSpec& run);
std::vector<std::string> peers_columns();

/// §5.6: gift-wrapping against Bowyer-Watson (in the suite's order) on the same points: times,
/// gift-wrapping's apex orient3d tests and insphere calls against n h, Bowyer-Watson's predicate
/// calls, and whether the two give the same tetrahedra.
RunOutput giftwrap(const Suite& suite, const RunSpec& run);
std::vector<std::string> giftwrap_columns();

/// Vertex deletion by gift-wrapping the star: the tier's number of random vertices deleted one
/// by one, the work of each against its degree (per-deletion rows), and the result compared with
/// the triangulation rebuilt without them.
RunOutput deletion(const Suite& suite, const TierSettings& tier, const RunSpec& run);
std::vector<std::string> deletion_columns();
std::vector<std::string> deletion_j_columns();

/// §5.8: the CDT of a generated PLC (plc_families.h), edge-protected first: flips and events
/// per polygon against m^2 and m^2 log m (Proposition 5.5, per-polygon rows) and over the whole
/// sequence against n^2 (Proposition 5.6).
RunOutput cdt(const Suite& suite, const RunSpec& run);
std::vector<std::string> cdt_columns();
std::vector<std::string> cdt_j_columns();

/// Exercise 2: Del S given (S from the run's distribution, n points), t points T uniform in
/// S's bounding box inserted in a uniform order with the conflict graph; per size of T
/// (`added`), the tier's number of orders: tetrahedra and conflicts created while inserting T,
/// the conflict graph of Del S, and the same points built from scratch in a uniform order.
RunOutput extend(const Suite& suite, const TierSettings& tier, const RunSpec& run);
std::vector<std::string> extend_columns();
/// The extend kind's point set: S (input indices 0..s-1) and then t points uniform in S's
/// bounding box, drawn from `seed` (the run's seed).
core::PointSet extend_points(const core::PointSet& s_points, std::uint64_t t, std::uint64_t seed);
std::vector<std::string> extend_j_columns();

}  // namespace cavity::experiments::measure
