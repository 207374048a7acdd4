#include <cstdio>
#include <memory>
#include <string>

#include "cavity/core/atomic_file.h"
#include "cavity/core/cdt.h"
#include "cavity/core/error.h"
#include "cavity/core/mesh_io.h"
#include "cavity/core/plc.h"
#include "commands.h"

namespace cavity::cli {

namespace {

struct CdtArgs {
    std::string input;
    std::string prefix;
    bool protect = false;
    bool quiet = false;
};

/// PREFIX.face: the polygons' triangles, numbered like the points, with the facet markers.
void write_faces(const std::string& prefix, const core::Cdt& cdt) {
    core::AtomicFileGroup group;
    auto& out = group.add(prefix + ".face");
    const auto base = static_cast<std::uint32_t>(cdt.plc.points.index_base);
    out.write(std::to_string(cdt.faces.size()) + " 1\n");
    for (std::size_t i = 0; i < cdt.faces.size(); ++i) {
        const auto& f = cdt.faces[i];
        out.write(std::to_string(i + base) + " " + std::to_string(f.v[0] + base) + " " +
                  std::to_string(f.v[1] + base) + " " + std::to_string(f.v[2] + base) + " " +
                  std::to_string(f.marker) + "\n");
    }
    group.commit();
}

void run_cdt(const CdtArgs& args) {
    core::Plc plc = core::read_poly(args.input);
    const core::Cdt cdt = core::build_cdt(std::move(plc), core::CdtOptions{args.protect});
    core::write_tetgen(args.prefix, cdt.plc.points, cdt.tets);
    write_faces(args.prefix, cdt);
    core::write_vtu(args.prefix, cdt.plc.points, cdt.tets);
    if (args.quiet) {
        return;
    }
    const auto base = static_cast<std::uint32_t>(cdt.plc.points.index_base);
    for (std::uint32_t v : cdt.protection.inserted) {
        const auto& p = cdt.plc.points.points[v];
        std::printf("protecting vertex %u: %.17g %.17g %.17g\n", v + base, p.x, p.y, p.z);
    }
    const auto& c = cdt.counters;
    std::printf("%zu points (%zu inserted for protection), %zu polygons: %zu tetrahedra, %zu polygon "
                "triangles\n",
                cdt.plc.points.size(), cdt.protection.inserted.size(), cdt.plc.facets.size(),
                cdt.tets.size(), cdt.faces.size());
    std::printf("flips 2-3 %llu, 3-2 %llu, 4-4 %llu; events queued %llu, stale %llu, held back %llu; "
                "region tetrahedra %llu, largest region %llu vertices\n",
                static_cast<unsigned long long>(c.flips.flip_count(core::FlipKind::k23)),
                static_cast<unsigned long long>(c.flips.flip_count(core::FlipKind::k32)),
                static_cast<unsigned long long>(c.flips.flip_count(core::FlipKind::k44)),
                static_cast<unsigned long long>(c.events_queued),
                static_cast<unsigned long long>(c.events_stale),
                static_cast<unsigned long long>(c.events_held),
                static_cast<unsigned long long>(c.region_tets),
                static_cast<unsigned long long>(c.max_region_vertices));
    std::printf("valid: constrained Delaunay (checked exactly); wrote %s.node, .ele, .face, .vtu\n",
                args.prefix.c_str());
}

}  // namespace

void add_cdt_command(CLI::App& app) {
    auto args = std::make_shared<CdtArgs>();
    CLI::App* cmd = app.add_subcommand(
        "cdt",
        "Constrained Delaunay tetrahedralization of a TetGen .poly PLC: Delaunay triangulation of "
        "its vertices, then flip-based polygon insertion (§5.8); the PLC must be edge-protected");
    cmd->add_option("input", args->input, "the PLC (.poly)")->required();
    cmd->add_option("-o,--output", args->prefix, "output prefix: PREFIX.node .ele .face .vtu")
        ->required();
    cmd->add_flag("--protect", args->protect,
                  "split PLC edges that are not Delaunay (at exact midpoints) until it is "
                  "edge-protected");
    cmd->add_flag("--quiet", args->quiet, "print nothing on success");
    cmd->callback([args] { run_cdt(*args); });
}

}  // namespace cavity::cli
