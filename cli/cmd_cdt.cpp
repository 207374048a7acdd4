#include <charconv>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/cdt/cdt_carve.h"
#include "cavity/core/cdt/cdt_vertex_insertion.h"
#include "cavity/core/cdt/exact_points_file.h"
#include "cavity/core/cdt/read_plc.h"
#include "cavity/core/check/orientation.h"
#include "cavity/core/input/plc.h"
#include "cavity/core/io/atomic_file.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/point_io.h"
#include "cavity/core/io/write_poly.h"
#include "commands.h"

namespace cavity::cli {

namespace {

struct CdtArgs {
    std::string input;
    std::string prefix;
    std::string insert;
    bool protect = false;
    std::size_t max_protection_points = core::CdtOptions{}.max_protection_points;
    bool convex_hull = false;
    bool keep_faces = false;
    bool all_or_nothing = false;
    bool quiet = false;
};

/// PREFIX.face: the polygons' triangles, numbered like the points, with the facet markers.
void write_faces(core::AtomicFileGroup::Writer& out, const core::Cdt& cdt) {
    const auto base = static_cast<std::uint32_t>(cdt.plc.points.index_base);
    // Each line formatted in place and appended whole, the lines written in large pieces: a
    // string per number and a write per line cost as much as the .ele.
    std::string text = std::to_string(cdt.faces.size()) + " 1\n";
    char line[5 * 21];
    for (std::size_t i = 0; i < cdt.faces.size(); ++i) {
        const auto& f = cdt.faces[i];
        char* end = std::to_chars(line, line + sizeof line, i + base).ptr;
        for (const std::uint32_t v : f.v) {
            *end++ = ' ';
            end = std::to_chars(end, line + sizeof line, v + base).ptr;
        }
        *end++ = ' ';
        end = std::to_chars(end, line + sizeof line, f.marker).ptr;
        *end++ = '\n';
        text.append(line, static_cast<std::size_t>(end - line));
        if (text.size() > (std::size_t{1} << 16)) {
            out.write(text);
            text.clear();
        }
    }
    out.write(text);
}

/// Inserts the points of `file` in order. A refused point (or a duplicate) is reported on stderr
/// by its number in the file, or, with --all-or-nothing, stops the run before anything is written.
void insert_points(core::LiveCdt& live, const CdtArgs& args) {
    const core::PointSet points = core::read_points(args.insert, false);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& p = points.points[i];
        const core::CdtInsertion r = live.insert_vertex(p);
        if (r.inserted()) {
            continue;
        }
        char where[160];
        std::snprintf(where,
                      sizeof where,
                      "point %zu (%.17g %.17g %.17g): ",
                      i + static_cast<std::size_t>(points.index_base),
                      p.x,
                      p.y,
                      p.z);
        const std::string message =
            core::located_message(args.insert, std::nullopt, where + r.message);
        if (args.all_or_nothing) {
            throw core::Error(message + " (--all-or-nothing: nothing written)");
        }
        std::fprintf(stderr, "cavity: %s\n", message.c_str());
    }
    // The constructor checked the CDT of the PLC; check again what the insertions made of it.
    live.validate();
}

void print_insertions(const core::Cdt& cdt, const CdtArgs& args) {
    const auto& c = cdt.insertion;
    std::printf(
        "inserted %llu of %llu points from %s (%llu left out: %llu not star-shaped, %llu "
        "through the cavity, %llu not Delaunay, %llu duplicates)\n",
        static_cast<unsigned long long>(c.inserted),
        static_cast<unsigned long long>(c.attempts),
        args.insert.c_str(),
        static_cast<unsigned long long>(c.attempts - c.inserted),
        static_cast<unsigned long long>(c.refused_not_star_shaped),
        static_cast<unsigned long long>(c.refused_through_cavity),
        static_cast<unsigned long long>(c.refused_not_delaunay),
        static_cast<unsigned long long>(c.duplicates));
    std::printf(
        "insertion: %llu on polygons, %llu on PLC edges; tetrahedra deleted %llu, created "
        "%llu; conflict tests %llu, new-face tests %llu, walk steps %llu\n",
        static_cast<unsigned long long>(c.on_polygon),
        static_cast<unsigned long long>(c.on_plc_edge),
        static_cast<unsigned long long>(c.tets_deleted),
        static_cast<unsigned long long>(c.tets_created),
        static_cast<unsigned long long>(c.conflict_tests),
        static_cast<unsigned long long>(c.face_tests),
        static_cast<unsigned long long>(c.walk_steps));
}

/// The domain's volume in doubles: each tetrahedron's, summed in order (not exact; the
/// tetrahedra are).
double volume(const std::vector<core::Point3>& pts, const std::vector<core::Tet>& tets) {
    double sum = 0;
    for (const core::Tet& t : tets) {
        const core::Point3& a = pts[t[0]];
        const core::Point3 u{pts[t[1]].x - a.x, pts[t[1]].y - a.y, pts[t[1]].z - a.z};
        const core::Point3 v{pts[t[2]].x - a.x, pts[t[2]].y - a.y, pts[t[2]].z - a.z};
        const core::Point3 w{pts[t[3]].x - a.x, pts[t[3]].y - a.y, pts[t[3]].z - a.z};
        sum += (u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) +
                u.z * (v.x * w.y - v.y * w.x)) /
               6;
    }
    return sum;
}

void run_cdt(const CdtArgs& args) {
    core::SurfaceReading reading;
    core::Plc plc = core::read_plc(args.input, &reading, !args.keep_faces);
    if (reading.unread_line > 0 && !args.quiet) {
        std::fprintf(stderr,
                     "cavity: note: %s:%zu: data after the faces the counts declare was not read\n",
                     args.input.c_str(),
                     reading.unread_line);
    }
    if (reading.warped_faces > 0 && !args.quiet) {
        std::fprintf(stderr,
                     "cavity: note: %s: %zu polygon faces whose corners are not coplanar were cut "
                     "into triangles\n",
                     args.input.c_str(),
                     reading.warped_faces);
    }
    if (reading.merged_faces > 0 && !args.quiet) {
        std::fprintf(stderr,
                     "cavity: note: %s: %zu exactly coplanar neighbouring faces were merged into "
                     "%zu polygons (--keep-faces keeps each face a polygon)\n",
                     args.input.c_str(),
                     reading.merged_faces,
                     reading.merged_polygons);
    }
    core::LiveCdt live(std::move(plc), core::CdtOptions{args.protect, args.max_protection_points});
    if (!args.insert.empty()) {
        insert_points(live, args);
    }
    const core::Cdt cdt = live.snapshot();
    const core::CarvedCdt domain = core::carve_cdt(cdt, args.convex_hull);
    core::AtomicFileGroup group;
    core::write_tetgen(group, args.prefix, cdt.plc.points, domain.tets);
    write_faces(group.add(args.prefix + ".face"), cdt);
    // TetGen's region attributes become the cell data `region` (0: no region).
    core::VtuOptions vtu;
    if (!cdt.plc.regions.empty()) {
        vtu.regions = domain.regions;
    }
    core::write_vtu(group, args.prefix, cdt.plc.points, domain.tets, vtu);
    core::write_poly(group.add(args.prefix + ".poly"), cdt.plc);
    const bool implicit = !cdt.plc.points.exact.empty();
    if (implicit) {
        // The .node has the implicit Steiner points rounded; the exact mesh is this file's.
        group.add(args.prefix + ".exact").write(core::exact_points_text(cdt.plc.points));
    }
    group.commit();
    if (args.quiet) {
        return;
    }
    if (domain.tets.empty() && !cdt.tets.empty()) {
        // Most likely polygons that do not close a surface, not an intended empty mesh.
        std::fprintf(stderr,
                     "cavity: warning: %s: the polygons enclose no volume, so every tetrahedron "
                     "was removed as exterior or hole (--convex-hull keeps the hull)\n",
                     args.input.c_str());
    }
    const auto base = static_cast<std::uint32_t>(cdt.plc.points.index_base);
    for (std::uint32_t v : cdt.protection.inserted) {
        const auto& p = cdt.plc.points.points[v];
        std::printf("protecting vertex %u: %.17g %.17g %.17g\n", v + base, p.x, p.y, p.z);
    }
    const auto& c = cdt.counters;
    std::printf(
        "%zu points (%zu inserted for protection), %zu polygons: %zu tetrahedra, %zu polygon "
        "triangles\n",
        cdt.plc.points.size(),
        cdt.protection.inserted.size(),
        cdt.plc.facets.size(),
        cdt.tets.size(),
        cdt.faces.size());
    std::printf("domain (%s): %zu tetrahedra kept, %zu removed, volume %.17g",
                args.convex_hull ? "convex hull" : "exterior and holes removed",
                domain.tets.size(),
                domain.removed,
                volume(cdt.plc.points.points, domain.tets));
    if (!cdt.plc.regions.empty()) {
        std::map<std::int32_t, std::size_t> count;
        for (std::int32_t r : domain.regions) {
            ++count[r];
        }
        std::printf("; region markers");
        for (const auto& [marker, n] : count) {
            std::printf(" %d: %zu", marker, n);
        }
    }
    std::printf("\n");
    if (implicit) {
        // The files' coordinates are rounded: say whether that turns any kept tetrahedron over.
        core::PointSet rounded = cdt.plc.points;
        rounded.exact.clear();
        const core::OrientationCount count = core::count_orientations(rounded, domain.tets);
        std::printf(
            "implicit Steiner points: exact in %s.exact; rounded to doubles in %s.node, %zu of the "
            "kept tetrahedra are inverted and %zu flat\n",
            args.prefix.c_str(),
            args.prefix.c_str(),
            count.negative,
            count.flat);
    }
    std::printf(
        "flips 2-3 %llu, 3-2 %llu, 4-4 %llu; events queued %llu, stale %llu, held back %llu; "
        "region tetrahedra %llu, largest region %llu vertices; found by rotary searches over "
        "%llu and depth-first searches over %llu tetrahedra\n",
        static_cast<unsigned long long>(c.flips.flip_count(core::FlipKind::k23)),
        static_cast<unsigned long long>(c.flips.flip_count(core::FlipKind::k32)),
        static_cast<unsigned long long>(c.flips.flip_count(core::FlipKind::k44)),
        static_cast<unsigned long long>(c.events_queued),
        static_cast<unsigned long long>(c.events_stale),
        static_cast<unsigned long long>(c.events_held),
        static_cast<unsigned long long>(c.region_tets),
        static_cast<unsigned long long>(c.max_region_vertices),
        static_cast<unsigned long long>(c.rotary_steps),
        static_cast<unsigned long long>(c.search_visited));
    if (!args.insert.empty()) {
        print_insertions(cdt, args);
    }
    std::printf(
        "valid: constrained Delaunay (checked exactly); wrote %s.node, .ele, .face, .vtu, "
        ".poly%s\n",
        args.prefix.c_str(),
        implicit ? ", .exact" : "");
}

}  // namespace

void add_cdt_command(CLI::App& app) {
    auto args = std::make_shared<CdtArgs>();
    CLI::App* cmd = app.add_subcommand(
        "cdt",
        "Constrained Delaunay tetrahedralization of a TetGen .poly or .smesh PLC, or of a closed "
        "surface mesh (.off, .stl, .obj, .ply; refused, naming its facets, when it has open or "
        "non-manifold edges, degenerate or intersecting facets): Delaunay triangulation of "
        "its vertices, then flip-based polygon insertion (§5.8); the PLC must be edge-protected. "
        "As TetGen's -p, the domain the polygons bound is kept: the tetrahedra reachable from the "
        "convex hull without crossing a polygon are removed, and so are those reachable from each "
        "volume hole point of the .poly");
    cmd->add_option(
           "input",
           args->input,
           "the PLC (.poly, .smesh) or surface mesh (.off, .stl, .obj, .ply; by extension, "
           "case-insensitive)")
        ->required();
    cmd->add_option("-o,--output",
                    args->prefix,
                    "output prefix: PREFIX.node .ele .face .vtu, and PREFIX.poly, the PLC the mesh "
                    "conforms to (with protecting and inserted vertices) for `cavity check --poly`")
        ->required();
    cmd->add_flag(
        "--protect",
        args->protect,
        "split PLC edges that are not Delaunay until it is edge-protected, the shortest missing "
        "piece first, inserting each point into one live Delaunay triangulation, at points lying "
        "exactly on them: aimed at the middle (or, when an earlier split point encroaches, at the "
        "point nearest the middle that frees the piece of it; a piece already shorter than "
        "2^-12 of its edge, at an input vertex where another edge's split point encroaches, on "
        "the sphere about that vertex of radius a power of two), a point with double coordinates "
        "near the aim when one exists, else an implicit point at an exact dyadic parameter of "
        "the input edge (kept exactly: "
        "PREFIX.exact; .node has it rounded, and the summary counts tetrahedra the rounding "
        "inverts)");
    cmd->add_option("--max-protection-points",
                    args->max_protection_points,
                    "with --protect: refuse the PLC (exit status 1, nothing written) when it is "
                    "still not edge-protected after this many points; a guard against a cascade "
                    "of splits between close, acutely meeting features")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{0}, std::size_t{2147483647}));
    cmd->add_flag("--convex-hull",
                  args->convex_hull,
                  "keep the whole convex hull of the points: neither the exterior nor the volume "
                  "holes are removed (hole points are still checked)");
    cmd->add_flag("--keep-faces",
                  args->keep_faces,
                  "a surface mesh's faces stay polygons of their own; by default each group of "
                  "exactly coplanar faces joined by their sides is merged into one polygon (with "
                  "holes), as TetGen does without -M: the sides inside a flat face are no "
                  "constraints, and need no protection");
    cmd->add_option("--insert",
                    args->insert,
                    "after the polygons, insert these points (.node, .xyz, .ply) in file order "
                    "(§5.7); a point that cannot be inserted (or repeats a vertex) is reported on "
                    "stderr by its number in the file and left out, and the exit status stays 0");
    cmd->add_flag("--all-or-nothing",
                  args->all_or_nothing,
                  "with --insert: any point left out is an error (exit status 1, nothing written)");
    cmd->add_flag("--quiet", args->quiet, "print nothing on success (refusals still go to stderr)");
    cmd->callback([args] { run_cdt(*args); });
}

}  // namespace cavity::cli
