#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/exact_points_file.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/check/orientation.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/input/plc.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/point_io.h"
#include "cavity/core/io/points_fingerprint.h"
#include "commands.h"
#include "integer_option.h"
#include "out_of_memory.h"
#include "point_ids.h"
#include "progress_bar.h"

namespace cavity::cli {

namespace {

struct CheckArgs {
    std::string points;
    std::string mesh;
    std::string poly;
    std::vector<std::uint64_t> deleted;
    bool weighted = false;
    bool convex_hull = false;
    bool quiet = false;
    std::string exact;
};

/// --poly: the mesh must be the constrained Delaunay tetrahedralization of the PLC: of the domain
/// it bounds (as `cavity cdt` carves it), or with --convex-hull of the whole hull.
void run_cdt_check(const CheckArgs& args) {
    // The exact Steiner points first: the facets' planes are checked on them.
    const core::Plc plc = core::read_poly(args.poly, args.exact);
    // The PLC carries the points; the point file must list the same ones, so that a mesh is
    // never checked against points other than those it was written with.
    const core::PointSet points = core::read_points(args.points, false);
    const auto base = static_cast<std::size_t>(plc.points.index_base);
    if (points.size() != plc.points.size()) {
        throw core::Error(args.points + ": " + std::to_string(points.size()) + " points, but " +
                          args.poly + " has " + std::to_string(plc.points.size()));
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& a = points.points[i];
        const auto& b = plc.points.points[i];
        if (a.x != b.x || a.y != b.y || a.z != b.z) {
            throw core::Error(args.points + ": point " + std::to_string(i + base) +
                              " differs from point " + std::to_string(i + base) + " of " +
                              args.poly);
        }
    }
    core::check_points_fingerprint(args.mesh, args.points, points);
    const auto tets = core::read_ele(args.mesh, plc.points.index_base);
    core::refuse_inverted_mesh(args.mesh, plc.points, tets);
    const core::CdtValidation report = core::validate_cdt(
        plc, tets, args.convex_hull ? core::CdtDomain::kConvexHull : core::CdtDomain::kCarved);
    if (!report.ok()) {
        std::string message = args.mesh + ": not the constrained Delaunay tetrahedralization of " +
                              args.poly + " (" + std::to_string(report.problem_count) +
                              " problem(s)):";
        for (const auto& p : report.problems) {
            message += "\n  " + p;
        }
        if (!args.convex_hull) {
            message +=
                "\n(checked as the domain the PLC bounds; a mesh of the whole convex hull, "
                "from `cavity cdt --convex-hull`, is checked with --convex-hull)";
        }
        throw core::Error(message);
    }
    if (!args.quiet) {
        std::printf("valid: constrained Delaunay tetrahedralization of %s (%s, %zu tetrahedra)\n",
                    args.poly.c_str(),
                    args.convex_hull ? "its convex hull" : "the domain it bounds",
                    tets.size());
    }
}

void run_check(const CheckArgs& args) {
    if (!args.poly.empty()) {
        run_cdt_check(args);
        return;
    }
    const core::PointSet points = naming_memory("reading " + args.points, [&] {
        ProgressStage stage("reading " + args.points, !args.quiet);
        return core::read_points(args.points, args.weighted);
    });
    core::check_points_fingerprint(args.mesh, args.points, points);
    const auto tets = naming_memory("reading " + args.mesh, [&] {
        ProgressStage stage("reading " + args.mesh, !args.quiet);
        return core::read_ele(args.mesh, points.index_base);
    });
    core::refuse_inverted_mesh(args.mesh, points, tets);
    const core::ValidationReport report = naming_memory(
        "checking " + args.mesh + " (" + std::to_string(tets.size()) + " tetrahedra)", [&] {
            ProgressStage stage("checking " + args.mesh, !args.quiet);
            return core::validate(points, tets, zero_based_ids(points, args.deleted, "--deleted"));
        });
    if (!args.quiet) {
        std::printf(
            "%zu points: %zu vertices, %zu edges, %zu triangles (%zu on the hull), %zu tetrahedra; "
            "%zu duplicate(s), %zu redundant\n",
            points.size(),
            report.vertices,
            report.edges,
            report.triangles,
            report.hull_triangles,
            report.tets,
            report.duplicates,
            report.redundant);
    }
    if (!report.ok()) {
        std::string message = args.mesh + ": not the Delaunay triangulation of " + args.points +
                              " (" + std::to_string(report.problem_count) + " problem(s)):";
        for (const auto& p : report.problems) {
            message += "\n  " + p;
        }
        throw core::Error(message);
    }
    if (!args.quiet) {
        std::printf("valid: exact %sDelaunay triangulation under the symbolic perturbation\n",
                    args.weighted ? "weighted " : "");
    }
}

}  // namespace

void add_check_command(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    CLI::App* cmd = app.add_subcommand(
        "check",
        "Exactly validate a tetrahedral mesh (TetGen .ele) as the Delaunay triangulation of a "
        "point "
        "file; exit status 0 when valid, 1 otherwise. Tetrahedra must have positive volume by the "
        "right-hand rule, as TetGen and cavity write them");
    cmd->add_option("points", args->points, "the points (.node, .xyz, .ply)")->required();
    cmd->add_option("mesh", args->mesh, "the tetrahedra (.ele), numbered like the points")
        ->required();
    cmd->add_flag("--weighted", args->weighted, "weighted Delaunay (weights from the point file)");
    cmd->add_option("--poly",
                    args->poly,
                    "check a constrained Delaunay tetrahedralization of this PLC (TetGen .poly) "
                    "carved to the domain it bounds, as `cavity cdt` writes it (its boundary must "
                    "be polygon triangles); the point file must list the same points as the PLC");
    cmd->add_option("--exact",
                    args->exact,
                    "with --poly: the exact Steiner points `cavity cdt` wrote (PREFIX.exact); the "
                    "mesh is checked on them instead of their rounded coordinates");
    cmd->add_flag(
        "--convex-hull",
        args->convex_hull,
        "with --poly: the mesh covers the whole convex hull (`cavity cdt --convex-hull`)");
    cmd->add_option("--deleted",
                    args->deleted,
                    "points removed by `cavity triangulate --delete` (the same comma-separated "
                    "list): the mesh must be the triangulation of the other points")
        ->delimiter(',')
        ->transform(integer_in("a --deleted point", 0, 0xFFFF'FFFFu));
    cmd->add_flag("--quiet", args->quiet, "print only problems");
    cmd->callback([args] { run_check(*args); });
}

}  // namespace cavity::cli
