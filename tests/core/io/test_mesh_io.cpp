#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cavity/core/base/error.h"
#include "cavity/core/check/orientation.h"
#include "cavity/core/io/atomic_file.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/point_io.h"
#include "cavity/core/io/points_fingerprint.h"
#include "temp_dir.h"

namespace cavity::core {
namespace {

using test::TempDir;

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

PointSet cube_corners(bool weighted, int index_base) {
    PointSet set;
    set.index_base = index_base;
    for (int i = 0; i < 8; ++i) {
        set.points.push_back({static_cast<double>(i & 1) * 0.1,
                              static_cast<double>((i >> 1) & 1),
                              static_cast<double>(i >> 2) * 1e-310});
        if (weighted) {
            set.weights.push_back(i * 0.3);
        }
    }
    return set;
}

const std::vector<Tet> kTets = {
    {0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};

TEST(MeshIo, TetgenRoundTrip) {
    TempDir dir;
    for (const int base : {0, 1}) {
        for (const bool weighted : {false, true}) {
            SCOPED_TRACE("base " + std::to_string(base) + (weighted ? " weighted" : ""));
            const PointSet set = cube_corners(weighted, base);
            const auto prefix = dir.path() / "mesh";
            write_tetgen(prefix, set, kTets);
            const PointSet back = read_points(dir.path() / "mesh.node", weighted);
            EXPECT_EQ(back.index_base, base);
            ASSERT_EQ(back.size(), set.size());
            for (std::size_t i = 0; i < set.size(); ++i) {
                EXPECT_EQ(back.points[i].x, set.points[i].x);
                EXPECT_EQ(back.points[i].z, set.points[i].z);
            }
            EXPECT_EQ(back.weights, set.weights);
            // The API's tetrahedra have positive right-hand volume, TetGen's convention: the
            // file lists them as they are.
            const std::vector<Tet> read = read_ele(dir.path() / "mesh.ele", base);
            EXPECT_EQ(read, kTets);
            EXPECT_EQ(count_orientations(set, read).positive, kTets.size());
            const std::string ele = contents(dir.path() / "mesh.ele");
            EXPECT_EQ(ele.substr(0, ele.find('\n')),
                      "6 4 0  " + points_fingerprint_comment(points_fingerprint(set)));
            EXPECT_EQ(read_points_fingerprint(dir.path() / "mesh.ele"), points_fingerprint(set));
            const std::string first = base == 0 ? "\n0 0 1 3 7\n" : "\n1 1 2 4 8\n";
            EXPECT_NE(ele.find(first), std::string::npos) << ele;
        }
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"mesh.ele", "mesh.node"}));
}

TEST(MeshIo, VtuIsAnUnstructuredGridOfTetrahedra) {
    TempDir dir;
    VtuOptions ascii;
    ascii.encoding = VtuEncoding::kAscii;
    write_vtu(dir.path() / "mesh", cube_corners(true, 1), kTets, ascii);
    const std::string vtu = contents(dir.path() / "mesh.vtu");
    EXPECT_NE(vtu.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
    EXPECT_NE(vtu.find("NumberOfPoints=\"8\" NumberOfCells=\"6\""), std::string::npos);
    EXPECT_NE(vtu.find("\n0 1 3 7\n"), std::string::npos) << "connectivity is 0-based";
    EXPECT_NE(vtu.find("Name=\"offsets\" format=\"ascii\">\n4\n8\n"), std::string::npos);
    std::size_t tetra = 0;
    for (std::size_t at = vtu.find("\n10\n"); at != std::string::npos;
         at = vtu.find("\n10\n", at + 3)) {
        ++tetra;
    }
    EXPECT_EQ(tetra, 6u);
    EXPECT_NE(vtu.find("Name=\"weight\""), std::string::npos);
    // Cell data: each cell's number in the .ele file, here 1-based as the input.
    EXPECT_NE(vtu.find("Name=\"tet_id\" format=\"ascii\">\n1\n2\n3\n4\n5\n6\n"), std::string::npos);
    EXPECT_NE(vtu.find("</VTKFile>"), std::string::npos);
}

// The default encoding is VTK's zlib-compressed base64 (decoded and checked by meshio in the
// cli.meshio_vtu test); here only its declaration and that no ASCII array is left.
TEST(MeshIo, VtuIsCompressedBinaryByDefault) {
    TempDir dir;
    write_vtu(dir.path() / "mesh", cube_corners(false, 0), kTets);
    const std::string vtu = contents(dir.path() / "mesh.vtu");
    EXPECT_NE(vtu.find("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\""),
              std::string::npos);
    EXPECT_EQ(vtu.find("format=\"ascii\""), std::string::npos);
    // Indices that fit are Int32 (half the bytes to compress; VTK and meshio read either).
    EXPECT_NE(vtu.find("<DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\""),
              std::string::npos);
    EXPECT_NE(vtu.find("<DataArray type=\"Int32\" Name=\"offsets\""), std::string::npos);
}

TEST(MeshIo, FailedWriteLeavesNothingBehind) {
    TempDir dir;
    const PointSet set = cube_corners(false, 0);
    // A bad tet is refused: neither file may appear, and an older .node survives untouched.
    const auto old_node = dir.write("mesh.node", "old contents");
    const std::vector<Tet> bad = {{0, 1, 2, 8}};
    EXPECT_THROW(write_tetgen(dir.path() / "mesh", set, bad), Error);
    EXPECT_THROW(write_vtu(dir.path() / "mesh", set, bad), Error);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"mesh.node"}));
    EXPECT_EQ(contents(old_node), "old contents");
}

TEST(MeshIo, UnwritableDirectoryIsReported) {
    TempDir dir;
    // A path below a regular file cannot be created, whoever runs the test (root included).
    const auto blocker = dir.write("file", "x");
    try {
        write_tetgen(blocker / "mesh", cube_corners(false, 0), kTets);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find((blocker / "mesh.node").string()), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(write_points(blocker / "p.xyz", cube_corners(false, 0)), Error);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"file"}));
}

TEST(AtomicFile, NothingVisibleBeforeCommitNothingLeftWithout) {
    TempDir dir;
    {
        AtomicFileGroup group;
        group.add(dir.path() / "a.txt").write("alpha");
        group.add(dir.path() / "b.txt").write("beta");
        for (const std::string& name : dir.entries()) {
            EXPECT_EQ(name[0], '.') << "only hidden temporaries before commit: " << name;
        }
        EXPECT_EQ(dir.entries().size(), 2u);
    }
    EXPECT_TRUE(dir.entries().empty());
    {
        AtomicFileGroup group;
        group.add(dir.path() / "a.txt").write("alpha");
        group.add(dir.path() / "b.txt").write(std::string(200000, 'b'));
        group.commit();
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.txt", "b.txt"}));
    EXPECT_EQ(contents(dir.path() / "a.txt"), "alpha");
    EXPECT_EQ(contents(dir.path() / "b.txt"), std::string(200000, 'b'));
}

// A writer killed before it could clean up leaves a temporary named after its process; the next
// group writing the same target removes it once that process is gone, and no other.
TEST(AtomicFile, StaleTemporariesOfDeadWritersAreRemoved) {
    TempDir dir;
    const pid_t child = ::fork();
    if (child == 0) {
        ::_exit(0);
    }
    ASSERT_GT(child, 0);
    ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // reaped: the pid names no process now
    const std::string dead = ".a.txt.tmp." + std::to_string(child) + ".0";
    const std::string alive = ".a.txt.tmp." + std::to_string(::getppid()) + ".3";
    const std::string other = ".b.txt.tmp." + std::to_string(child) + ".0";
    dir.write(dead, "half");
    dir.write(alive, "busy");
    dir.write(other, "not ours");
    AtomicFileGroup group;
    group.add(dir.path() / "a.txt").write("alpha");
    group.commit();
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{alive, other, "a.txt"}));
}

TEST(AtomicFile, FailedRenameIsAnError) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "taken" / "inside");
    {
        AtomicFileGroup group;
        group.add(dir.path() / "taken").write("x");
        EXPECT_THROW(group.commit(), Error);
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"taken"}));
}

TEST(ReadEle, ErrorsNameFileAndLine) {
    TempDir dir;
    const auto expect_line = [&dir](const std::string& name,
                                    const std::string& text,
                                    int base,
                                    std::size_t line,
                                    const std::string& detail) {
        const auto file = dir.write(name, text);
        try {
            read_ele(file, base);
            ADD_FAILURE() << name << ": no error";
        } catch (const Error& e) {
            const std::string message = e.what();
            const std::string prefix = file.string() + ":" + std::to_string(line) + ": ";
            EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
            EXPECT_NE(message.find(detail), std::string::npos) << message;
        }
    };
    expect_line("a.ele", "1 10 0\n0 0 1 2 3 4 5 6 7 8 9\n", 0, 1, "4 nodes per tet");
    expect_line("b.ele", "2 4 0\n0 0 1 2 3\n", 0, 2, "after 1 of 2 tets");
    expect_line("c.ele", "2 4 0\n0 0 1 2 3\n2 0 1 2 3\n", 0, 3, "out of sequence");
    expect_line("d.ele", "1 4 0\n1 0 1 2 3\n", 1, 2, "vertex 0 outside");
    expect_line("e.ele", "1 4 1\n0 0 1 2 3\n", 0, 2, "expected 6 fields");
    expect_line("f.ele", "1 4 0\n0 0 1 -2 3\n", 0, 2, "vertex");
    expect_line("g.ele", "1 4 0\n0 0 1 2 3\n1 0 1 2 3\n", 0, 3, "data after");
    EXPECT_THROW(read_ele(dir.path() / "missing.ele", 0), Error);
}

TEST(ReadEle, AttributesAndCommentsAreSkipped) {
    TempDir dir;
    const auto file = dir.write("x.ele", "# tets\n2 4 1\n1 1 2 3 4 7.5\n\n2 5 6 7 8 0 # c\n");
    EXPECT_EQ(read_ele(file, 1), (std::vector<Tet>{{0, 1, 2, 3}, {4, 5, 6, 7}}));
}

}  // namespace
}  // namespace cavity::core
