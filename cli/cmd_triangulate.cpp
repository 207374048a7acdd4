#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "cavity/core/base/error.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/io/atomic_file.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/point_io.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/core/version.h"
#include "commands.h"
#include "integer_option.h"
#include "json_writer.h"
#include "out_of_memory.h"
#include "point_ids.h"
#include "progress_bar.h"

namespace cavity::cli {

namespace {

struct TriangulateArgs {
    std::string input;
    std::string prefix;
    std::string order = "brio";
    std::string locate = "walk";
    std::string storage = "array";
    std::string bootstrap = "widest";
    std::string format = "tetgen";
    std::string stats;
    std::vector<std::uint64_t> delete_ids;
    std::uint64_t seed = 0;
    unsigned threads = 0;  ///< 0: the sequential engine
    double brio_ratio = 0.125;
    bool no_reverse_rounds = false;
    bool weighted = false;
    bool check = false;
    bool quiet = false;
    bool neighbors = false;
    bool hull_faces = false;
    bool ascii = false;
    bool count_conflicts = false;

    /// Conflicts are counted when asked, and always by the full conflict graph, which keeps them.
    bool conflicts_counted() const { return count_conflicts || locate == "conflict-graph-all"; }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::uint64_t peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024u;  // Linux reports KiB
}

/// `conflicts`: the run counted conflicts (--count-conflicts); their keys appear only then.
void write_counters(JsonWriter& json, const core::Counters& c, bool conflicts) {
    json.begin_object("counters");
    for (const core::CounterField& counter : core::kCounterFields) {
        if (conflicts || counter.group != core::CounterGroup::kConflicts) {
            json.integer(counter.name, c.*counter.field);
        }
    }
    json.begin_object("predicate_stages");
    for (int k = 0; k < core::kPredicateKindCount; ++k) {
        json.begin_object(core::kPredicateKindNames[static_cast<std::size_t>(k)]);
        for (int s = 0; s < predicates::kStageCount; ++s) {
            json.integer(predicates::stage_name(static_cast<predicates::Stage>(s)),
                         c.stage_calls[static_cast<std::size_t>(k)][static_cast<std::size_t>(s)]);
        }
        json.end_object();
    }
    json.end_object();
    json.end_object();
}

struct Timings {
    double read_s = 0;
    double order_s = 0;
    double triangulate_s = 0;
    double delete_s = 0;
    double check_s = 0;
    double write_s = 0;
};

/// Adds the --stats file to the run's group, so that it is committed with the mesh or not at all.
void write_stats(core::AtomicFileGroup& files,
                 const TriangulateArgs& args,
                 const core::PointSet& points,
                 const core::Triangulation& tri,
                 const Timings& timings) {
    JsonWriter json;
    json.begin_object();
    json.string("version", core::kVersion);
    json.string("input", args.input);
    json.integer("points", points.size());
    json.boolean("weighted", args.weighted);
    json.boolean("checked", args.check);
    json.boolean("conflicts_counted", args.conflicts_counted());
    json.string("order", args.order);
    json.string("locate", args.locate);
    json.string("storage", args.storage);
    json.string("bootstrap", args.bootstrap);
    json.integer("seed", args.seed);
    json.begin_object("timings");
    // --stats runs the counting engine (the plain engine's cascade plus its counters: within
    // about 1 % of the plain engine's instructions at 10^5 points), with the exact conflict
    // counter on top for --count-conflicts: timings from here are that engine's.
    // --threads runs the parallel construction, which has no counters.
    json.string("engine",
                args.threads > 0       ? "parallel, " + std::to_string(args.threads) + " threads"
                : args.count_conflicts ? "counting+conflict-counter"
                                       : "counting");
    json.integer("threads", args.threads);
    json.number("read_s", timings.read_s);
    json.number("order_s", timings.order_s);
    json.number("triangulate_s", timings.triangulate_s);
    json.number("delete_s", timings.delete_s);
    json.number("check_s", timings.check_s);
    json.number("write_s", timings.write_s);
    json.end_object();
    json.begin_object("counts");
    json.integer("tets", tri.tets.size());
    json.integer("hull_triangles", tri.hull_triangles);
    json.integer("duplicates", tri.duplicates.size());
    json.integer("redundant", tri.redundant.size());
    json.end_object();
    if (args.threads == 0) {
        write_counters(json, tri.counters, args.conflicts_counted());
    }
    json.integer("storage_bytes", tri.storage_bytes);
    json.integer("peak_rss_bytes", peak_rss_bytes());
    json.begin_array("duplicates");
    for (const auto& d : tri.duplicates) {
        json.begin_array();
        json.element(d[0] + static_cast<std::uint64_t>(points.index_base));
        json.element(d[1] + static_cast<std::uint64_t>(points.index_base));
        json.end_array();
    }
    json.end_array();
    json.begin_array("redundant");
    for (std::uint32_t r : tri.redundant) {
        json.element(r + static_cast<std::uint64_t>(points.index_base));
    }
    json.end_array();
    json.end_object();
    files.add(args.stats).write(json.text());
}

/// Adds the mesh files to the run's group: TetGen's .node/.ele (with .neigh and .face when asked,
/// read off the live triangulation and numbered along the insertion order so that neighbours are
/// near in the files) or .vtu.
void write_mesh(core::AtomicFileGroup& files,
                const TriangulateArgs& args,
                const core::PointSet& points,
                const core::Triangulation& tri,
                const std::optional<core::Adjacency>& adjacency) {
    if (args.format == "vtu") {
        core::VtuOptions options;
        options.encoding = args.ascii ? core::VtuEncoding::kAscii : core::VtuEncoding::kBinary;
        core::write_vtu(files, args.prefix, points, tri.tets, options);
        return;
    }
    if (!adjacency) {
        core::write_tetgen(files, args.prefix, points, tri.tets);
        return;
    }
    core::write_tetgen(files, args.prefix, points, *adjacency, {args.neighbors, args.hull_faces});
}

/// Duplicates and redundant points are never dropped silently: a summary goes to stderr (the
/// full lists to --stats).
void report_skipped(const core::PointSet& points, const core::Triangulation& tri) {
    const auto base = static_cast<std::uint64_t>(points.index_base);
    if (!tri.duplicates.empty()) {
        std::fprintf(stderr,
                     "cavity: %zu duplicate point(s) skipped, each mapped to its first occurrence:",
                     tri.duplicates.size());
        for (std::size_t i = 0; i < tri.duplicates.size() && i < 10; ++i) {
            std::fprintf(stderr,
                         " %llu->%llu",
                         static_cast<unsigned long long>(tri.duplicates[i][0]) + base,
                         static_cast<unsigned long long>(tri.duplicates[i][1]) + base);
        }
        std::fprintf(stderr, "%s\n", tri.duplicates.size() > 10 ? " ..." : "");
    }
    if (!tri.redundant.empty()) {
        std::fprintf(stderr,
                     "cavity: %zu redundant (submerged) weighted point(s), not vertices:",
                     tri.redundant.size());
        for (std::size_t i = 0; i < tri.redundant.size() && i < 10; ++i) {
            std::fprintf(stderr, " %llu", static_cast<unsigned long long>(tri.redundant[i]) + base);
        }
        std::fprintf(stderr, "%s\n", tri.redundant.size() > 10 ? " ..." : "");
    }
}

void run_triangulate(const TriangulateArgs& args) {
    Timings timings;
    auto clock = std::chrono::steady_clock::now();
    std::error_code no_size;
    const double file_bytes = static_cast<double>(std::filesystem::file_size(args.input, no_size));
    const std::string reading =
        "reading " + args.input + (no_size ? "" : " (" + about_bytes(file_bytes) + " file)");
    core::PointSet points = naming_memory(reading, [&] {
        ProgressStage stage("reading " + args.input, !args.quiet);
        return core::read_points(args.input, args.weighted);
    });
    timings.read_s = seconds_since(clock);
    // What the engine needs, measured: about 250 bytes per point at 10^6 uniform points (peak
    // resident size of this command, the engine borrowing the points), for the messages that
    // name a run's size.
    const std::string size = std::to_string(points.size()) + " points, " +
                             about_bytes(250.0 * static_cast<double>(points.size()));

    clock = std::chrono::steady_clock::now();
    core::OrderOptions order_options;
    order_options.kind = core::parse_order_kind(args.order);
    order_options.seed = args.seed;
    order_options.brio_ratio = args.brio_ratio;
    order_options.reverse_alternate_rounds = !args.no_reverse_rounds;
    order_options.threads = std::max(1u, args.threads);
    core::InsertionOrder order = naming_memory("ordering " + args.input + " (" + size + ")", [&] {
        return core::make_insertion_order(points.points, order_options);
    });
    timings.order_s = seconds_since(clock);

    core::TriangulateOptions options;
    options.locate = core::parse_locate_kind(args.locate);
    options.storage = core::parse_storage_kind(args.storage);
    options.seed = args.seed;
    options.bootstrap = core::parse_bootstrap_rule(args.bootstrap);
    options.count = (!args.stats.empty() && args.threads == 0) || args.conflicts_counted();
    options.threads = args.threads;
    options.count_conflicts = args.count_conflicts;
    ProgressBar bar("triangulating", !args.quiet);
    options.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
    clock = std::chrono::steady_clock::now();
    // Deletion and the adjacency files work on the live triangulation; a plain run releases it
    // as it writes the list of tetrahedra (a lower peak).
    const bool adjacency_files = args.format == "tetgen" && (args.neighbors || args.hull_faces);
    const bool live = adjacency_files || !args.delete_ids.empty();
    // Errors name the input file.
    const auto named = [&](auto&& build) {
        try {
            return build();
        } catch (const core::Error& e) {
            throw core::Error(args.input + ": " + e.what(), e.kind());
        }
    };
    core::Triangulation tri;
    std::optional<core::Adjacency> adjacency;
    if (!live) {
        tri = naming_memory("triangulating " + args.input + " (" + size + ")", [&] {
            // The engine borrows the points (they are back when it returns) and keeps the
            // sequence: no copy of either at the peak.
            return named([&] {
                return core::triangulate_in_place(points, std::move(order.sequence), options);
            });
        });
        bar.finish();
        timings.triangulate_s = seconds_since(clock);
    } else {
        core::DelaunayTriangulation dt =
            naming_memory("triangulating " + args.input + " (" + size + ")", [&] {
                return named(
                    [&] { return core::DelaunayTriangulation(points, order.sequence, options); });
            });
        bar.finish();
        timings.triangulate_s = seconds_since(clock);
        if (!args.delete_ids.empty()) {
            clock = std::chrono::steady_clock::now();
            naming_memory("deleting vertices of " + args.input + " (" + size + ")", [&] {
                dt.remove(zero_based_ids(points, args.delete_ids, "--delete"));
                return 0;
            });
            timings.delete_s = seconds_since(clock);
        }
        if (adjacency_files) {
            adjacency = dt.adjacency();
        }
        tri = std::move(dt).release();
        // The counters describe the build; the lists, what is left after the deletions.
        tri.counters.duplicates = tri.duplicates.size();
        tri.counters.redundant = tri.redundant.size();
    }
    report_skipped(points, tri);

    if (args.check) {
        clock = std::chrono::steady_clock::now();
        const core::ValidationReport report =
            naming_memory("checking the triangulation of " + args.input + " (" + size + ")", [&] {
                ProgressStage stage("checking", !args.quiet);
                return core::validate(
                    points, tri.tets, zero_based_ids(points, args.delete_ids, "--delete"));
            });
        timings.check_s = seconds_since(clock);
        if (!report.ok()) {
            std::string message = "validation failed (" + std::to_string(report.problem_count) +
                                  " problem(s)); no mesh written:";
            for (const auto& p : report.problems) {
                message += "\n  " + p;
            }
            throw core::Error(message);
        }
    }

    // Every file of the run (mesh and stats) is written to a temporary first and committed
    // together: a failure anywhere leaves the previous files untouched.
    core::AtomicFileGroup files;
    clock = std::chrono::steady_clock::now();
    naming_memory("writing the mesh of " + args.input + " (" + size + ")", [&] {
        ProgressStage stage("writing " + args.prefix, !args.quiet);
        write_mesh(files, args, points, tri, adjacency);
        timings.write_s = seconds_since(clock);
        if (!args.stats.empty()) {
            write_stats(files, args, points, tri, timings);
        }
        files.commit();
    });
    if (!args.quiet) {
        std::printf("%zu points -> %zu tetrahedra, %zu hull triangles%s in %.3f s (order %.3f s)\n",
                    points.size(),
                    tri.tets.size(),
                    tri.hull_triangles,
                    args.check ? ", valid," : "",
                    timings.triangulate_s,
                    timings.order_s);
        if (args.conflicts_counted()) {
            const core::Counters& c = tri.counters;
            std::printf(
                "conflicts: %llu created by solid tetrahedra (sum of j), %llu by ghosts; "
                "%llu and %llu deleted; at most %llu live\n",
                static_cast<unsigned long long>(c.conflicts_created),
                static_cast<unsigned long long>(c.ghost_conflicts_created),
                static_cast<unsigned long long>(c.conflicts_deleted),
                static_cast<unsigned long long>(c.ghost_conflicts_deleted),
                static_cast<unsigned long long>(c.live_conflicts_max));
        }
    }
}

/// `-o mesh.vtu --format vtu` means the prefix `mesh`, not `mesh.vtu.vtu`; likewise a prefix ending
/// in .node or .ele for TetGen files.
std::string output_prefix(const std::string& prefix, const std::string& format) {
    const auto strip = [&prefix](std::string_view extension) {
        return prefix.size() > extension.size() &&
               prefix.compare(prefix.size() - extension.size(), extension.size(), extension) == 0;
    };
    for (const std::string_view extension : format == "vtu"
                                                ? std::vector<std::string_view>{".vtu"}
                                                : std::vector<std::string_view>{".node", ".ele"}) {
        if (strip(extension)) {
            return prefix.substr(0, prefix.size() - extension.size());
        }
    }
    return prefix;
}

/// A --stats path that names the input or one of the run's mesh files would overwrite it: refused
/// before anything is computed.
void refuse_stats_over_a_file_of_the_run(const TriangulateArgs& args) {
    if (args.stats.empty()) {
        return;
    }
    std::vector<std::string> files = {args.input};
    for (const char* suffix : {".node", ".ele", ".neigh", ".face", ".vtu"}) {
        files.push_back(args.prefix + suffix);
    }
    std::error_code error;
    const auto stats = std::filesystem::weakly_canonical(args.stats, error);
    for (const std::string& file : files) {
        std::error_code other_error;
        if (!error && std::filesystem::weakly_canonical(file, other_error) == stats &&
            !other_error) {
            throw CLI::ValidationError("--stats", "'" + args.stats + "' would overwrite " + file);
        }
    }
}

}  // namespace

void add_triangulate_command(CLI::App& app) {
    auto args = std::make_shared<TriangulateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "triangulate",
        "Exact Delaunay (or weighted Delaunay) triangulation of a point file (.node, .xyz/.csv, "
        ".ply); writes PREFIX.node and PREFIX.ele (TetGen) or PREFIX.vtu");
    cmd->add_option("input", args->input, "input points")->required();
    cmd->add_option("-o,--output",
                    args->prefix,
                    "output prefix: PREFIX.node and PREFIX.ele, or PREFIX.vtu (a prefix ending in "
                    "the format's extension is taken without it)")
        ->required();
    cmd->add_option("--order", args->order, "insertion order: " + core::help_of(core::kOrderKinds))
        ->check(CLI::IsMember(core::names_of(core::kOrderKinds)))
        ->capture_default_str();
    cmd->add_option(
           "--locate", args->locate, "point location: " + core::help_of(core::kLocateKinds))
        ->check(CLI::IsMember(core::names_of(core::kLocateKinds)))
        ->capture_default_str();
    cmd->add_option(
           "--storage", args->storage, "tetrahedron storage: " + core::help_of(core::kStorageKinds))
        ->check(CLI::IsMember(core::names_of(core::kStorageKinds)))
        ->capture_default_str();
    cmd->add_option("--bootstrap",
                    args->bootstrap,
                    "first tetrahedron: " + core::help_of(core::kBootstrapRules))
        ->check(CLI::IsMember(core::names_of(core::kBootstrapRules)))
        ->capture_default_str();
    cmd->add_option("--seed", args->seed, "seed of the random choices (order, walk)")
        ->transform(integer_in("--seed", 0, UINT64_MAX))
        ->capture_default_str();
    cmd->add_option("--brio-ratio",
                    args->brio_ratio,
                    "BRIO: fraction of the points carried into the earlier rounds, in [0, 1) "
                    "(Amenta-Choi-Rote's, CGAL's and geogram's convention; the theory's ratio is "
                    "1/2, CGAL's "
                    "and geogram's 1/8)")
        ->capture_default_str();
    cmd->add_flag("--no-reverse-rounds",
                  args->no_reverse_rounds,
                  "BRIO: do not reverse the curve order on alternate rounds");
    cmd->add_flag("--weighted",
                  args->weighted,
                  "weighted Delaunay: the first .node attribute (or 4th column) is the weight");
    cmd->add_option(
           "--delete",
           args->delete_ids,
           "after triangulating, delete these points (input numbering, comma-separated) "
           "by vertex deletion; the output keeps the input's numbering and all its points, "
           "so check it with `cavity check --deleted` and the same list")
        ->delimiter(',')
        ->transform(integer_in("a --delete point", 0, 0xFFFF'FFFFu));
    cmd->add_option("--threads",
                    args->threads,
                    "build with N threads (1 to 127): the same tetrahedra, written in a canonical "
                    "order that is the same for every N; the plain engine, so --stats has timings "
                    "and counts but no counters (default: the sequential engine)")
        ->transform(integer_in("--threads", 1, 127));
    cmd->add_flag("--check", args->check, "validate the result exactly before writing it");
    cmd->add_flag("--count-conflicts",
                  args->count_conflicts,
                  "count every created tetrahedron's conflicts exactly (Theorem 5.4's sum of j; "
                  "about one exact test per conflict, ~81 n ln n for uniform points) and report "
                  "them in the summary and --stats");
    cmd->add_option(
        "--stats", args->stats, "write timings, counts and instrumentation counters as JSON");
    cmd->add_flag("--quiet", args->quiet, "no progress bar or summary");
    cmd->add_option("--format", args->format, "output format")
        ->check(CLI::IsMember({"tetgen", "vtu"}))
        ->capture_default_str();
    cmd->add_flag("-n,--neigh",
                  args->neighbors,
                  "also write PREFIX.neigh: each tetrahedron's four neighbours (TetGen's -n)");
    cmd->add_flag("-f,--faces",
                  args->hull_faces,
                  "also write PREFIX.face: the convex hull's triangles, counter-clockwise seen "
                  "from outside (TetGen's boundary faces)");
    cmd->add_flag("--ascii",
                  args->ascii,
                  "with --format vtu: ASCII arrays instead of zlib-compressed base64");
    cmd->callback([args] {
        args->prefix = output_prefix(args->prefix, args->format);
        refuse_stats_over_a_file_of_the_run(*args);
        if (args->format != "tetgen" && (args->neighbors || args->hull_faces)) {
            throw CLI::ValidationError("--neigh/--faces", "TetGen files: not with --format vtu");
        }
        if (args->storage != "array" &&
            (args->neighbors || args->hull_faces || !args->delete_ids.empty())) {
            throw CLI::ValidationError("--storage",
                                       "--delete, --neigh and --faces use the live triangulation, "
                                       "which keeps the array storage");
        }
        if (args->threads > 0 &&
            (args->locate != "walk" || args->storage != "array" || args->count_conflicts)) {
            throw CLI::ValidationError("--threads",
                                       "the parallel construction uses --locate walk and "
                                       "--storage array, and counts no conflicts");
        }
        if (args->format != "vtu" && args->ascii) {
            throw CLI::ValidationError("--ascii", "only with --format vtu");
        }
        run_triangulate(*args);
    });
}

}  // namespace cavity::cli
