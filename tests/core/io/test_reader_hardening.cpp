// Hostile inputs, one family per defect class a hostile-input audit found: counts near 2^64 that
// wrapped header arithmetic, file data converted to integers out of range, payloads that disagree
// with their declared counts, integers beyond 2^53, directories given as files. Each must end in
// an Error naming the file (and the line where there is one), never a crash, a hang, a huge
// allocation, or silently different data.

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/input/plc.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/point_io.h"
#include "temp_dir.h"

namespace cavity::core {
namespace {

using test::TempDir;

enum class Reader { kPoints, kWeighted, kEle, kPoly };

/// The message of the Error reading `content` as `name` throws; fails the test when none.
std::string error_of(const TempDir& dir,
                     const std::string& name,
                     const std::string& content,
                     Reader reader) {
    const auto file = dir.write(name, content);
    try {
        switch (reader) {
            case Reader::kPoints:
                read_points(file, false);
                break;
            case Reader::kWeighted:
                read_points(file, true);
                break;
            case Reader::kEle:
                read_ele(file, 0);
                break;
            case Reader::kPoly:
                read_poly(file);
                break;
        }
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << name << ": read without an error";
    return {};
}

void expect_refused(const TempDir& dir,
                    const std::string& name,
                    const std::string& content,
                    Reader reader,
                    const std::string& where,
                    const std::string& detail) {
    SCOPED_TRACE(name);
    const std::string message = error_of(dir, name, content, reader);
    EXPECT_EQ(message.rfind((dir.path() / name).string() + where, 0), 0u) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
}

const std::string kTetPoints = "0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
constexpr const char* kMax64 = "18446744073709551615";

TEST(ReaderHardening, HeaderCountsNear2To64AreBoundedBeforeUse) {
    TempDir dir;
    for (const char* attributes : {kMax64, "18446744073709551612", "4294967296"}) {
        expect_refused(dir,
                       "a.node",
                       std::string("4 3 ") + attributes + " 0\n" + kTetPoints,
                       Reader::kPoints,
                       ":1: ",
                       "number of attributes");
        expect_refused(dir,
                       "w.node",
                       std::string("4 3 ") + attributes + " 0\n" + kTetPoints,
                       Reader::kWeighted,
                       ":1: ",
                       "number of attributes");
        expect_refused(dir,
                       "a.ele",
                       std::string("1 4 ") + attributes + "\n0 0 1 2 3\n",
                       Reader::kEle,
                       ":1: ",
                       "number of attributes");
        expect_refused(dir,
                       "a.poly",
                       std::string("4 3 ") + attributes + " 0\n" + kTetPoints + "0\n",
                       Reader::kPoly,
                       ":1: ",
                       "number of attributes");
    }
    expect_refused(dir,
                   "m.node",
                   std::string("4 3 0 ") + kMax64 + "\n" + kTetPoints,
                   Reader::kPoints,
                   ":1: ",
                   "boundary markers");
    expect_refused(dir,
                   "n.node",
                   std::string(kMax64) + " 3 0 0\n" + kTetPoints,
                   Reader::kPoints,
                   ":1: ",
                   "32-bit indices");
    expect_refused(dir,
                   "c.poly",
                   "4 3 0 0\n" + kTetPoints + "1 0\n" + kMax64 + " 0\n",
                   Reader::kPoly,
                   ":7: ",
                   "number of polygons");
    expect_refused(dir,
                   "d.poly",
                   "4 3 0 0\n" + kTetPoints + "1 0\n1 0\n" + kMax64 + " 0 1 2\n",
                   Reader::kPoly,
                   ":8: ",
                   "number of corners");
    expect_refused(dir,
                   "f.poly",
                   "4 3 0 0\n" + kTetPoints + kMax64 + " 0\n",
                   Reader::kPoly,
                   ":6: ",
                   "number of facets");
    expect_refused(dir,
                   "h.poly",
                   "4 3 0 0\n" + kTetPoints + "1 1\n1 " + kMax64 + " 3\n",
                   Reader::kPoly,
                   ":7: ",
                   "number of holes");
    expect_refused(dir,
                   "k.poly",
                   "4 3 0 0\n" + kTetPoints + "1 1\n1 0 99999999999\n3 0 1 2\n",
                   Reader::kPoly,
                   ":7: ",
                   "facet marker");
}

// A header promising 4294967295 points (or vertices) in a tiny file is refused, or fails where the
// file ends, without reserving memory for the promise.
TEST(ReaderHardening, PromisedCountsDoNotAllocate) {
    TempDir dir;
    expect_refused(dir,
                   "big.node",
                   "4294967295 3 0 0\n" + kTetPoints,
                   Reader::kPoints,
                   ":5: ",
                   "file ends after 4 of 4294967295 points");
    expect_refused(dir,
                   "big.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4294967295\nproperty float x\n"
                   "property float y\nproperty float z\nend_header\n0 0 0\n",
                   Reader::kPoints,
                   ":3: ",
                   "declares 4294967295 instances");
}

std::string binary_ply(const std::string& face_header,
                       const std::string& face_data,
                       int vertices_declared = 4) {
    std::string text = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                       std::to_string(vertices_declared) +
                       "\nproperty double x\nproperty double y\nproperty double z\n" + face_header +
                       "end_header\n";
    const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    text.append(reinterpret_cast<const char*>(corners), sizeof corners);
    return text + face_data;
}

TEST(ReaderHardening, PlyListLengthsAreIntegersInRange) {
    TempDir dir;
    const float huge = 1e30f;
    expect_refused(dir,
                   "f.ply",
                   binary_ply("element face 1\nproperty list float int vertex_indices\n",
                              std::string(reinterpret_cast<const char*>(&huge), 4)),
                   Reader::kPoints,
                   ":8: ",
                   "list length must have an integer type");
    expect_refused(dir,
                   "d.ply",
                   binary_ply("element face 1\nproperty list double int vertex_indices\n", ""),
                   Reader::kPoints,
                   ":8: ",
                   "integer type");
    const std::int32_t negative = -5;
    expect_refused(dir,
                   "n.ply",
                   binary_ply("element face 1\nproperty list int int vertex_indices\n",
                              std::string(reinterpret_cast<const char*>(&negative), 4)),
                   Reader::kPoints,
                   ": ",
                   "negative list length");
    expect_refused(dir,
                   "i.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty int x\nproperty int y\n"
                   "property int z\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1e30\n",
                   Reader::kPoints,
                   ":11: ",
                   "not a 64-bit integer: '1e30'");
    expect_refused(dir,
                   "r.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty uchar x\nproperty int y\n"
                   "property int z\nend_header\n0 0 0\n1 0 0\n0 1 0\n256 0 1\n",
                   Reader::kPoints,
                   ":11: ",
                   "outside the range of its PLY type");
}

TEST(ReaderHardening, PlyCountsMustMatchThePayload) {
    TempDir dir;
    const std::string face = std::string("\x03", 1) + std::string(12, '\0');
    const std::string header = "element face 1\nproperty list uchar int vertex_indices\n";
    EXPECT_EQ(read_points(dir.write("ok.ply", binary_ply(header, face)), false).size(), 4u);
    expect_refused(dir,
                   "trailing.ply",
                   binary_ply(header, face + "junk"),
                   Reader::kPoints,
                   ": ",
                   "4 bytes of binary data after the elements the header declares");
    expect_refused(dir,
                   "fewer.ply",
                   binary_ply(header, face, 3),
                   Reader::kPoints,
                   ": ",
                   "bytes of binary data after the elements");
    expect_refused(
        dir, "more.ply", binary_ply(header, face, 5), Reader::kPoints, ": ", "file ends");
    expect_refused(dir,
                   "nofaces.ply",
                   binary_ply("element face 2\nproperty list uchar int v\n", face),
                   Reader::kPoints,
                   ": ",
                   "file ends in face 1 of the 2 declared");
    expect_refused(dir,
                   "ascii.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                   "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n",
                   Reader::kPoints,
                   ":12: ",
                   "data after the elements the header declares");
}

TEST(ReaderHardening, IntegersBeyond2To53AreRefusedNotRounded) {
    TempDir dir;
    expect_refused(dir,
                   "a.node",
                   "4 3 0 0\n0 0 0 0\n1 9007199254740993 0 0\n2 0 1 0\n3 0 0 1\n",
                   Reader::kPoints,
                   ":3: ",
                   "the nearest is 9007199254740992");
    expect_refused(dir,
                   "b.xyz",
                   "0 0 0\n1 0 0\n0 1 0\n0 0 -18014398509481985\n",
                   Reader::kPoints,
                   ":4: ",
                   "has no exact double");
    // Integers a double holds exactly stay accepted, however large.
    EXPECT_EQ(read_points(dir.write("c.xyz",
                                    "0 0 9007199254740992\n1 0 0\n0 1 0\n"
                                    "0 0 18014398509481984\n"),
                          false)
                  .points[3]
                  .z,
              18014398509481984.0);
    expect_refused(dir,
                   "d.ele",
                   "1 4 0\n0 0 1 2 9007199254740993\n",
                   Reader::kEle,
                   ":2: ",
                   "outside the point numbering");
    expect_refused(dir,
                   "e.ele",
                   std::string("1 4 0\n0 0 1 2 ") + kMax64 + "0\n",
                   Reader::kEle,
                   ":2: ",
                   "not a non-negative integer");
}

TEST(ReaderHardening, ADirectoryIsNamedAsOne) {
    TempDir dir;
    std::filesystem::create_directory(dir.path() / "points.node");
    std::filesystem::create_directory(dir.path() / "folder");
    for (const char* name : {"points.node", "folder"}) {
        try {
            read_points(dir.path() / name, false);
            ADD_FAILURE() << name << ": no error";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(read_ele(dir.path() / "folder", 0), Error);
}

}  // namespace
}  // namespace cavity::core
