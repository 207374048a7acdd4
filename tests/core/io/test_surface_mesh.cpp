// The surface-mesh readers of `cavity cdt`: OFF, STL (ASCII and binary), OBJ and PLY (ASCII and
// both binary byte orders), each face a facet of one loop numbered as the file numbers it, and
// malformed files refused naming the file and the line (or the byte, in binary data).
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/io/parse_poly.h"
#include "cavity/core/io/surface_mesh.h"
#include "temp_dir.h"

namespace cavity::core {
namespace {

using test::TempDir;

using Loop = std::vector<std::uint32_t>;

/// A tetrahedron with a vertex at the origin: its 4 corners and 4 outward triangles.
const std::vector<Point3> kCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<Loop> kFaces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

std::string error_of(const TempDir& dir, const std::string& name, std::string_view bytes) {
    try {
        read_surface_mesh(dir.write(name, bytes));
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << name << " was read without an error";
    return {};
}

/// The error names the file, then `where` (":LINE: " or ": "), and mentions `detail`.
void expect_refused(const TempDir& dir,
                    const std::string& name,
                    std::string_view bytes,
                    const std::string& where,
                    const std::string& detail) {
    SCOPED_TRACE(name);
    const std::string message = error_of(dir, name, bytes);
    EXPECT_EQ(message.rfind((dir.path() / name).string() + where, 0), 0u) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
}

void expect_tetrahedron(const Plc& plc, int base) {
    ASSERT_EQ(plc.points.size(), 4u);
    EXPECT_EQ(plc.points.index_base, base);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(plc.points.points[i].x, kCorners[i].x);
        EXPECT_EQ(plc.points.points[i].y, kCorners[i].y);
        EXPECT_EQ(plc.points.points[i].z, kCorners[i].z);
    }
    ASSERT_EQ(plc.facets.size(), 4u);
    for (std::size_t f = 0; f < 4; ++f) {
        ASSERT_EQ(plc.facets[f].loops.size(), 1u);
        EXPECT_EQ(plc.facets[f].loops[0], kFaces[f]);
        EXPECT_EQ(plc.facets[f].number, f + static_cast<std::size_t>(base));
    }
    EXPECT_TRUE(plc.segments.empty());
}

std::string tetrahedron_off() {
    return "OFF\n# a comment\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n"
           "3 0 3 2\n";
}

TEST(SurfaceMesh, OffFacetsKeepTheirLinesAndNumbers) {
    TempDir dir;
    const Plc plc = read_surface_mesh(dir.write("t.off", tetrahedron_off()));
    expect_tetrahedron(plc, 0);
    EXPECT_EQ(plc.facets[0].line, 8u);
    EXPECT_EQ(plc.facets[3].line, 11u);
    EXPECT_EQ(facet_name(plc, 2), "facet 2 (line 10)");
}

TEST(SurfaceMesh, OffVariantsAndPolygons) {
    TempDir dir;
    // Counts on the keyword line, vertex colours (COFF), a face colour, an upper-case extension,
    // and a quadrilateral kept as one polygon.
    const Plc plc = read_surface_mesh(
        dir.write("q.OFF",
                  "COFF 5 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 1 0 0 1\n0 1 0 1 0 0 1\n"
                  "0 0 1 1 0 0 1\n4 0 1 2 3 255 0 0\n3 0 1 4\n"));
    ASSERT_EQ(plc.facets.size(), 2u);
    EXPECT_EQ(plc.facets[0].loops[0], (Loop{0, 1, 2, 3}));
    EXPECT_EQ(plc.facets[1].loops[0], (Loop{0, 1, 4}));
}

TEST(SurfaceMesh, OffReadsTheFacesItsCountsDeclare) {
    // A face more than the counts declare (as in CGAL's prim.off), after a blank line and a
    // comment: the declared tetrahedron is read, and where the rest begins is reported.
    TempDir dir;
    std::size_t unread_line = 0;
    const Plc plc = read_surface_mesh(dir.write("t.off", tetrahedron_off() + "\n# more\n3 1 2 0\n"),
                                      &unread_line);
    expect_tetrahedron(plc, 0);
    EXPECT_EQ(unread_line, 14u);
    read_surface_mesh(dir.write("u.off", tetrahedron_off() + "\n# nothing more\n"), &unread_line);
    EXPECT_EQ(unread_line, 0u);
}

TEST(SurfaceMesh, OffMalformed) {
    TempDir dir;
    expect_refused(dir, "a.off", "", ": ", "empty");
    expect_refused(dir, "b.off", "PLY\n", ":1: ", "not an OFF file");
    expect_refused(dir,
                   "c.off",
                   "OFF\n4 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 4\n",
                   ":7: ",
                   "vertex index 4 is not a point (points are numbered 0 to 3)");
    expect_refused(dir,
                   "d.off",
                   "OFF\n4 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 1\n",
                   ":7: ",
                   "face 0 has 2 corners");
    expect_refused(dir,
                   "e.off",
                   "OFF\n4 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
                   ":7: ",
                   "file ends in face 1 of the 2 declared");
    expect_refused(dir, "f.off", "OFF\n4 1\n0 0 0\n1 0 0\n0 1 x\n0 0 1\n3 0 1 2\n", ":5: ", "z");
    expect_refused(dir,
                   "g.off",
                   "OFF\n4 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1\n",
                   ":7: ",
                   "declares 3 corners but lists 2");
    expect_refused(dir, "i.off", "OFF\n4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", ": ", "no faces");
}

std::string tetrahedron_obj() {
    return "# tetrahedron\nmtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\ng all\n"
           "f 1 3 2\nf 1/1 2/2 4/3\nf 2//1 3//1 4//1\nf -4/1/1 -1 -2\n";
}

TEST(SurfaceMesh, ObjNumbersFromOneWithRelativeAndSlashedCorners) {
    TempDir dir;
    const Plc plc = read_surface_mesh(dir.write("t.obj", tetrahedron_obj()));
    expect_tetrahedron(plc, 1);
    EXPECT_EQ(plc.facets[0].line, 9u);
    EXPECT_EQ(facet_name(plc, 3), "facet 4 (line 12)");
}

TEST(SurfaceMesh, ObjMalformed) {
    TempDir dir;
    expect_refused(dir,
                   "a.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n",
                   ":4: ",
                   "vertex index 0: OBJ numbers vertices from 1");
    expect_refused(dir,
                   "b.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
                   ":4: ",
                   "vertex index 4 is not a point (points are numbered 1 to 3)");
    expect_refused(dir,
                   "c.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 -4 2\n",
                   ":4: ",
                   "vertex index -4 is not a point");
    expect_refused(dir, "d.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", ":3: ", "a face has 2 corners");
    expect_refused(dir, "e.obj", "v 0 0\n", ":1: ", "found 2 numbers");
    expect_refused(dir, "f.obj", "v 0 0 0 2\n", ":1: ", "weight w other than 1");
    expect_refused(dir, "g.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", ":4: ", "vertex index");
}

std::string tetrahedron_stl_ascii() {
    std::string s = "solid tet\n";
    for (const Loop& f : kFaces) {
        s += "  facet normal 0 0 0\n    outer loop\n";
        for (const std::uint32_t v : f) {
            const Point3& p = kCorners[v];
            s += "      vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " +
                 std::to_string(p.z) + "\n";
        }
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid tet\n";
}

/// A binary STL of the tetrahedron's faces, with `header` as the first bytes of the 80.
std::string tetrahedron_stl_binary(const std::string& header) {
    std::string s = header;
    s.resize(80, ' ');
    const auto put32 = [&s](std::uint32_t v) {
        for (int k = 0; k < 4; ++k) {
            s += static_cast<char>((v >> (8 * k)) & 0xFF);
        }
    };
    put32(static_cast<std::uint32_t>(kFaces.size()));
    for (const Loop& f : kFaces) {
        for (int k = 0; k < 3; ++k) {
            put32(std::bit_cast<std::uint32_t>(0.0f));  // the normal, ignored
        }
        for (const std::uint32_t v : f) {
            const Point3& p = kCorners[v];
            for (const double c : {p.x, p.y, p.z}) {
                put32(std::bit_cast<std::uint32_t>(static_cast<float>(c)));
            }
        }
        s += std::string(2, '\0');
    }
    return s;
}

TEST(SurfaceMesh, StlMergesEqualCoordinatesInOrderOfFirstAppearance) {
    TempDir dir;
    // Faces list corners 0, 2, 1 first, so the merged numbering is 0, 2, 1, 3 of kCorners.
    for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
             {"ascii.stl", tetrahedron_stl_ascii()},
             {"binary.stl", tetrahedron_stl_binary("binary")},
             {"solid_header.StL", tetrahedron_stl_binary("solid but binary")}}) {
        SCOPED_TRACE(name);
        const Plc plc = read_surface_mesh(dir.write(name, bytes));
        ASSERT_EQ(plc.points.size(), 4u);
        EXPECT_EQ(plc.points.index_base, 0);
        EXPECT_EQ(plc.points.points[1].y, 1.0);  // kCorners[2], met second
        EXPECT_EQ(plc.points.points[2].x, 1.0);  // kCorners[1]
        ASSERT_EQ(plc.facets.size(), 4u);
        EXPECT_EQ(plc.facets[0].loops[0], (Loop{0, 1, 2}));
        EXPECT_EQ(plc.facets[2].loops[0], (Loop{2, 1, 3}));
        EXPECT_EQ(plc.facets[3].number, 3u);
        EXPECT_EQ(plc.facets[1].line, name == "ascii.stl" ? 9u : 0u);
    }
}

TEST(SurfaceMesh, StlNormalsAreNotRead) {
    TempDir dir;
    std::string s = tetrahedron_stl_ascii();
    s.replace(s.find("normal 0 0 0"), 12, "normal -nan nan 1e999");
    EXPECT_EQ(read_surface_mesh(dir.write("n.stl", s)).facets.size(), 4u);
}

TEST(SurfaceMesh, StlMergesSignedZeros) {
    TempDir dir;
    std::string s = tetrahedron_stl_ascii();
    const auto at = s.find("vertex 0.000000 0.000000 0.000000");
    ASSERT_NE(at, std::string::npos);
    s.replace(at, 33, "vertex -0.0 0 -0");
    EXPECT_EQ(read_surface_mesh(dir.write("z.stl", s)).points.size(), 4u);
}

TEST(SurfaceMesh, StlMalformed) {
    TempDir dir;
    std::string truncated = tetrahedron_stl_binary("b");
    truncated.pop_back();
    expect_refused(dir, "a.stl", truncated, ": ", "4 triangles has 284 bytes, this one has 283");
    std::string nan = tetrahedron_stl_binary("b");
    const auto bits = std::bit_cast<std::uint32_t>(std::numeric_limits<float>::quiet_NaN());
    for (int k = 0; k < 4; ++k) {
        nan[84 + 50 + 12 + 4 + static_cast<std::size_t>(k)] = static_cast<char>(bits >> (8 * k));
    }
    expect_refused(dir, "b.stl", nan, ": ", "triangle 1 corner 0: not a finite number (byte 150)");
    std::string no_endloop = tetrahedron_stl_ascii();
    no_endloop.erase(no_endloop.find("    endloop\n"), 12);
    expect_refused(dir, "c.stl", no_endloop, ":7: ", "expected 'vertex x y z' or 'endloop'");
    expect_refused(dir,
                   "d.stl",
                   "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n",
                   ":4: ",
                   "file ends in the facet of line 2");
    expect_refused(dir, "e.stl", "solid x\n", ":1: ", "before 'endsolid'");
}

/// A PLY surface of the tetrahedron: a vertex element with an extra property, a face element
/// whose corner list has `count_type`/`index_type` and is preceded by a scalar.
std::string tetrahedron_ply(const std::string& format,
                            const std::string& list_name = "vertex_indices") {
    std::string s = "ply\nformat " + format +
                    " 1.0\ncomment made by the test\nelement vertex 4\nproperty float x\n"
                    "property double y\nproperty uchar red\nproperty float z\nelement face 4\n"
                    "property int flags\nproperty list uchar int " +
                    list_name + "\nend_header\n";
    const bool big = format == "binary_big_endian";
    const auto put = [&s, big](std::uint64_t bits, int bytes) {
        for (int k = 0; k < bytes; ++k) {
            const int shift = 8 * (big ? bytes - 1 - k : k);
            s += static_cast<char>((bits >> shift) & 0xFF);
        }
    };
    for (const Point3& p : kCorners) {
        if (format == "ascii") {
            s += std::to_string(p.x) + " " + std::to_string(p.y) + " 7 " + std::to_string(p.z) +
                 "\n";
        } else {
            put(std::bit_cast<std::uint32_t>(static_cast<float>(p.x)), 4);
            put(std::bit_cast<std::uint64_t>(p.y), 8);
            put(7, 1);
            put(std::bit_cast<std::uint32_t>(static_cast<float>(p.z)), 4);
        }
    }
    for (const Loop& f : kFaces) {
        if (format == "ascii") {
            s += "0 3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
                 std::to_string(f[2]) + "\n";
        } else {
            put(0, 4);
            put(3, 1);
            for (const std::uint32_t v : f) {
                put(v, 4);
            }
        }
    }
    return s;
}

TEST(SurfaceMesh, PlyInEveryEncoding) {
    TempDir dir;
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const Plc plc = read_surface_mesh(dir.write(format + ".ply", tetrahedron_ply(format)));
        expect_tetrahedron(plc, 0);
        EXPECT_EQ(plc.facets[1].line, format == "ascii" ? 18u : 0u);
    }
    expect_tetrahedron(
        read_surface_mesh(dir.write("index.ply", tetrahedron_ply("ascii", "vertex_index"))), 0);
}

TEST(SurfaceMesh, PlyMalformed) {
    TempDir dir;
    std::string bad_index = tetrahedron_ply("ascii");
    bad_index.replace(bad_index.rfind("0 3 0 3 2"), 9, "0 3 0 3 9");
    expect_refused(dir,
                   "a.ply",
                   bad_index,
                   ":20: ",
                   "face 3: vertex index 9 is not a point (points are numbered 0 to 3)");
    std::string binary = tetrahedron_ply("binary_little_endian");
    binary[binary.size() - 4] = 9;  // the last corner of face 3
    expect_refused(dir,
                   "b.ply",
                   binary,
                   ": ",
                   "face 3: vertex index 9 is not a point (points are numbered 0 to 3) (byte " +
                       std::to_string(binary.size() - 4) + ")");
    std::string truncated = tetrahedron_ply("binary_big_endian");
    truncated.resize(truncated.size() - 3);
    expect_refused(dir, "c.ply", truncated, ": ", "file ends in face 3 of the 4 declared");
    expect_refused(dir,
                   "d.ply",
                   tetrahedron_ply("ascii", "corners"),
                   ":9: ",
                   "the face element has no 'vertex_indices' list");
    std::string two = tetrahedron_ply("ascii");
    two.replace(two.rfind("0 3 0 3 2"), 9, "0 2 0 3");
    expect_refused(dir, "e.ply", two, ":20: ", "face 3 has 2 corners");
    std::string no_faces = tetrahedron_ply("ascii");
    no_faces = no_faces.substr(0, no_faces.find("element face")) + "end_header\n" +
               "0 0 7 0\n1 0 7 0\n0 1 7 0\n0 0 7 1\n";
    expect_refused(dir, "f.ply", no_faces, ": ", "has no face element");
}

TEST(SurfaceMesh, ExtensionsChooseTheFormat) {
    EXPECT_TRUE(is_surface_mesh_file("a.off"));
    EXPECT_TRUE(is_surface_mesh_file("a.STL"));
    EXPECT_TRUE(is_surface_mesh_file("dir.x/a.Obj"));
    EXPECT_TRUE(is_surface_mesh_file("a.ply"));
    EXPECT_FALSE(is_surface_mesh_file("a.poly"));
    EXPECT_FALSE(is_surface_mesh_file("a.smesh"));
    EXPECT_FALSE(is_surface_mesh_file("off"));
}

TEST(SurfaceMesh, SmeshFacetsAreOnePolygonEach) {
    TempDir dir;
    // TetGen's .smesh: the .poly's parts, but each facet one polygon with an optional marker.
    const std::string points = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
    const Plc plc = parse_poly(
        dir.write("t.Smesh", points + "4 1\n3 1 3 2 5\n3 1 2 4 6\n3 2 3 4\n3 1 4 3 8\n0\n0\n"));
    ASSERT_EQ(plc.facets.size(), 4u);
    EXPECT_EQ(plc.points.index_base, 1);
    EXPECT_EQ(plc.facets[0].loops[0], (Loop{0, 2, 1}));
    EXPECT_EQ(plc.facets[0].marker, 5);
    EXPECT_EQ(plc.facets[2].marker, 0);
    EXPECT_EQ(plc.facets[3].marker, 8);
    EXPECT_EQ(plc.facets[3].line, 10u);
    EXPECT_EQ(facet_name(plc, 3), "facet 4 (line 10)");
    try {
        parse_poly(dir.write("bad.smesh", points + "1 0\n3 1 2 4 6\n"));
        ADD_FAILURE() << "a marker was accepted where the header declares none";
    } catch (const Error& e) {
        EXPECT_NE(
            std::string(e.what()).find("bad.smesh:7: the facet declares 3 corners but lists 4"),
            std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace cavity::core
