#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

/// A suite: one question of the chapter, and the grid of runs that answers it.
///
/// Suite files are line based: `key value value ...`, `#` starts a comment, blank lines are
/// ignored. Keys (each at most once):
///   question  TEXT                      what the suite checks (required)
///   kind      runs|jtets|creation|degenerate|peers|giftwrap|deletion|cdt|hj|locality|extend
///                                       (required)
///   dist      NAME...                   generate_points distributions; for cdt, PLC families
///                                       (plc_families.h) (required)
///   n.quick   N...   n.full N...        sizes per tier (required)
///   seeds.quick S... seeds.full S...    point (and order) seeds; `A..B` is a range (required)
///   n.paper   N...   seeds.paper S...   the paper tier (optional; a suite without it has none)
///   order     NAME...                   input random brio brio-noreverse hilbert zorder
///                                       (default random)
///   locate    walk|conflict-graph|conflict-graph-all...   (default walk)
///   storage   array|hash...             (default array)
///   count-conflicts yes|no              runs: count every tetrahedron's conflicts (default no)
///   bootstrap widest|first              runs: the first tetrahedron (default widest); `first`
///                                       keeps a uniform order an exactly uniform permutation
///   brio-ratio R                        (default 0.5) fraction carried into earlier rounds,
///                                       in [0, 1): CGAL's and geogram's 1/8 is 0.125
///   orders.quick R  orders.full R       creation, hj: insertion orders per point set (default 100)
///   (order names: brio:R is BRIO with ratio R, e.g. brio:0.125, whatever brio-ratio says)
///   deletions.quick K deletions.full K  deletion: vertices deleted per run (default 100; at
///                                       most half the points)
///   added.quick T... added.full T...    extend: sizes t of the point set T inserted into Del S
///                                       (S is the run's n points; required for extend)
///   validate  yes|no|N                  check every output exactly (default: yes for degenerate
///                                       and cdt); N: only the runs of at most N points
///   cap       DIST N                    leave out the sizes above N for DIST (a generator's
///                                       limit, e.g. cospherical); may be given once per DIST
/// Anything else is an Error naming the file and the line.
namespace cavity::experiments {

enum class SuiteKind {
    kRuns,
    kJTets,
    kCreation,
    kDegenerate,
    kPeers,
    kGiftWrap,
    kDeletion,
    kCdt,
    kHj,
    kLocality,
    kExtend
};

std::string_view suite_kind_name(SuiteKind kind);

struct TierSettings {
    std::vector<std::uint64_t> sizes;
    std::vector<std::uint64_t> seeds;
    std::uint64_t orders = 100;
    std::uint64_t deletions = 100;
    std::vector<std::uint64_t> added;  ///< extend: the sizes of T
};

struct Suite {
    std::string name;  ///< file stem
    std::string file;  ///< where it was read from, for messages
    std::string question;
    SuiteKind kind = SuiteKind::kRuns;
    std::vector<std::string> distributions;
    std::vector<std::string> orders{"random"};
    std::vector<std::string> locators{"walk"};
    std::vector<std::string> storages{"array"};
    double brio_ratio = 0.5;
    /// `count-conflicts yes`: every run counts Theorem 5.4's conflicts with the kd-tree counter
    /// (the full conflict graph counts them anyway); its time is then in time_s.
    bool count_conflicts = false;
    /// `bootstrap first`: the order's own first four affinely independent points start the
    /// triangulation, so a uniform order stays the permutation Theorem 5.4 assumes.
    bool bootstrap_first = false;
    /// `prefix K`: every run inserts only the first K points of its order (after the bootstrap
    /// four), counting their conflicts against all n points: the early part of a full run, whose
    /// seed-to-seed spread dominates Σj's (core::TriangulateOptions::prefix). 0: whole runs.
    std::uint64_t prefix = 0;
    bool validate = false;
    std::uint64_t validate_max = UINT64_MAX;  ///< `validate N`: larger runs are not checked

    bool validates(std::uint64_t n) const { return validate && n <= validate_max; }

    /// Distribution -> largest size run (the `cap` key); sizes above it are not enumerated.
    std::map<std::string, std::uint64_t> caps;
    TierSettings quick;
    TierSettings full;
    TierSettings paper;  ///< empty sizes: the suite has no paper tier

    /// "quick", "full" or "paper" (when the suite has one); throws Error otherwise.
    const TierSettings& tier(std::string_view name) const;
};

/// Parses suite text; `file` names it in error messages (file:line: what).
Suite parse_suite(std::string_view text, const std::string& file, const std::string& name);

/// Reads and parses a suite file. \throws Error naming the file (and line) on any problem.
Suite read_suite(const std::filesystem::path& path);

}  // namespace cavity::experiments
