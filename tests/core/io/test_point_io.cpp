#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/io/point_io.h"
#include "temp_dir.h"

namespace cavity::core {
namespace {

using test::TempDir;

std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

// Values that a careless writer or reader would change: -0, subnormals, extremes, 0.1.
PointSet tricky_points(bool weighted, int index_base) {
    PointSet set;
    set.index_base = index_base;
    const double min_subnormal = std::numeric_limits<double>::denorm_min();
    const double max_double = std::numeric_limits<double>::max();
    set.points = {{0.1, -0.0, 1e300},
                  {min_subnormal, -2.2250738585072009e-308, 1e-300},
                  {-max_double, 0x1.fffffffffffffp-1, 123456789.0},
                  {1.0 / 3.0, -1e-310, 4.0}};
    if (weighted) {
        set.weights = {0.0, -1e-300, 1e300, 2.0 / 3.0};
    }
    return set;
}

void expect_identical(const PointSet& expected, const PointSet& actual) {
    ASSERT_EQ(expected.size(), actual.size());
    ASSERT_EQ(expected.weights.size(), actual.weights.size());
    EXPECT_EQ(expected.index_base, actual.index_base);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(bits(expected.points[i].x), bits(actual.points[i].x)) << "point " << i;
        EXPECT_EQ(bits(expected.points[i].y), bits(actual.points[i].y)) << "point " << i;
        EXPECT_EQ(bits(expected.points[i].z), bits(actual.points[i].z)) << "point " << i;
        if (expected.weighted()) {
            EXPECT_EQ(bits(expected.weights[i]), bits(actual.weights[i])) << "weight " << i;
        }
    }
}

// The message of the Error that reading `content` as `name` raises.
std::string read_error(const TempDir& dir,
                       const std::string& name,
                       std::string_view content,
                       bool weighted = false) {
    const auto file = dir.write(name, content);
    try {
        read_points(file, weighted);
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << name << ": no error for:\n" << content;
    return {};
}

// Checks that reading fails with "FILE:LINE: ..." (or "FILE: ..." without a line) mentioning
// `detail`.
void expect_error(const TempDir& dir,
                  const std::string& name,
                  std::string_view content,
                  std::optional<std::size_t> line,
                  const std::string& detail,
                  bool weighted = false) {
    const std::string message = read_error(dir, name, content, weighted);
    std::string prefix = (dir.path() / name).string();
    if (line) {
        prefix += ':';
        prefix += std::to_string(*line);
    }
    prefix += ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u)
        << "message: " << message << "\nexpected prefix " << prefix;
    EXPECT_NE(message.find(detail), std::string::npos)
        << "message: " << message << "\nexpected to mention " << detail;
}

TEST(PointIo, TextFormatsRoundTripBitForBit) {
    TempDir dir;
    for (const char* name : {"p.xyz", "p.csv", "p.txt", "p.node", "P.XYZ"}) {
        for (const bool weighted : {false, true}) {
            SCOPED_TRACE(std::string(name) + (weighted ? " weighted" : ""));
            const PointSet set = tricky_points(weighted, 0);
            write_points(dir.path() / name, set);
            expect_identical(set, read_points(dir.path() / name, weighted));
        }
    }
}

TEST(PointIo, NodeKeepsOneBasedNumbering) {
    TempDir dir;
    const PointSet set = tricky_points(true, 1);
    write_points(dir.path() / "one.node", set);
    const PointSet back = read_points(dir.path() / "one.node", true);
    EXPECT_EQ(back.index_base, 1);
    expect_identical(set, back);
}

TEST(PointIo, ReadsHexFloatsCommentsBlankLinesAndCrlf) {
    TempDir dir;
    const auto file = dir.write("hex.xyz",
                                "# header comment\r\n"
                                "\r\n"
                                "0x1.8p+1 -0x1p-1074 0x1.fffffffffffffp+1023  # trailing\r\n"
                                "  1 , 2 ,3\n");
    const PointSet set = read_points(file, false);
    ASSERT_EQ(set.size(), 2u);
    EXPECT_EQ(set.points[0].x, 3.0);
    EXPECT_EQ(set.points[0].y, -std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(set.points[0].z, std::numeric_limits<double>::max());
    EXPECT_EQ(set.points[1].z, 3.0);
    EXPECT_EQ(set.index_base, 0);
    EXPECT_FALSE(set.weighted());
}

TEST(PointIo, NodeAttributesAndMarkers) {
    TempDir dir;
    const std::string text =
        "# TetGen node file\n"
        "3 3 2 1\n"
        "1 0 0 0  0.5 9  1\n"
        "2 1 0 0  -2 9   0  # comment\n"
        "\n"
        "3 0 1 0  0x1p-3 9  1\n";
    const auto file = dir.write("attr.node", text);
    const PointSet weighted = read_points(file, true);
    EXPECT_EQ(weighted.index_base, 1);
    ASSERT_EQ(weighted.weights.size(), 3u);
    EXPECT_EQ(weighted.weights[0], 0.5);
    EXPECT_EQ(weighted.weights[1], -2.0);
    EXPECT_EQ(weighted.weights[2], 0.125);
    const PointSet plain = read_points(file, false);
    EXPECT_FALSE(plain.weighted());
    EXPECT_EQ(plain.points[2].y, 1.0);
}

TEST(PointIo, NodeHeaderFieldsDefault) {
    TempDir dir;
    const PointSet set = read_points(dir.write("short.node", "2\n0 1 2 3\n1 4 5 6\n"), false);
    ASSERT_EQ(set.size(), 2u);
    EXPECT_EQ(set.points[1].x, 4.0);
}

TEST(PointIo, TextErrorsNameFileAndLine) {
    TempDir dir;
    expect_error(dir, "a.xyz", "", std::nullopt, "empty");
    expect_error(dir, "b.xyz", "# only a comment\n\n", std::nullopt, "empty");
    expect_error(dir,
                 "c.xyz",
                 "1 2 3\n4 5 6\n\n7 8\n",
                 4,
                 "expected 3 fields, as on the first data line, found 2");
    expect_error(dir, "d.xyz", "1 2\n", 1, "expected at least 3 numbers (x y z), found 2");
    expect_error(dir, "d2.csv", "x,y,z\n1,2,3\nx,y,z\n", 3, "x: not a number");
    expect_error(dir,
                 "d3.xyz",
                 "x y z nx ny nz\n1 2 3 0 0 1\n4 5 6 0 1\n",
                 3,
                 "expected 6 fields, as on the first data line, found 5");
    expect_error(dir, "e.xyz", "1 2 3\n1 nan 3\n", 2, "NaN");
    expect_error(dir, "f.xyz", "1 2 inf\n", 1, "infinity");
    expect_error(dir, "g.xyz", "1 2 1e999\n", 1, "out of the range");
    expect_error(dir, "h.xyz", "1 2 1e-400\n", 1, "underflows");
    expect_error(dir, "i.csv", "1,2,3\n1,,3\n", 2, "empty number");
    expect_error(dir, "j.txt", "1 2 abc\n", 1, "not a number");
    expect_error(dir, "k.xyz", "1 2 3\n", 1, "expected at least 4 numbers (x y z weight)", true);
    expect_error(dir, "l.dat", "1 2 3\n", std::nullopt, "unknown point format");
}

// What point clouds come as: a CSV header row, extra columns (normals, colours) after x y z,
// columns named in another order.
TEST(PointIo, HeaderRowsAndExtraColumns) {
    TempDir dir;
    const PointSet csv = read_points(dir.write("a.csv", "x,y,z\n1,2,3\n4,5,6\n"), false);
    ASSERT_EQ(csv.size(), 2u);
    EXPECT_EQ(csv.points[1].z, 6.0);
    const PointSet normals =
        read_points(dir.write("b.xyz", "1 2 3 0 0 1 255 0 0\n4 5 6 0 1 0 0 255 0\n"), false);
    ASSERT_EQ(normals.size(), 2u);
    EXPECT_EQ(normals.points[1].x, 4.0);
    EXPECT_EQ(normals.points[1].z, 6.0);
    const PointSet named = read_points(dir.write("c.csv", "id,Z,weight,X,Y\n7,3,0.5,1,2\n"), true);
    ASSERT_EQ(named.size(), 1u);
    EXPECT_EQ(named.points[0].x, 1.0);
    EXPECT_EQ(named.points[0].y, 2.0);
    EXPECT_EQ(named.points[0].z, 3.0);
    EXPECT_EQ(named.weights[0], 0.5);
}

TEST(PointIo, MissingFileIsNamed) {
    TempDir dir;
    const auto file = dir.path() / "absent.xyz";
    try {
        read_points(file, false);
        FAIL() << "no error for a missing file";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": cannot open", 0), 0u) << e.what();
    }
}

TEST(PointIo, NodeErrorsNameFileAndLine) {
    TempDir dir;
    expect_error(dir, "a.node", "", std::nullopt, "empty");
    expect_error(dir, "b.node", "# comment\n2 2 0 0\n0 1 2\n1 3 4\n", 2, "dimension is 2");
    expect_error(dir, "c.node", "3 3 0 0\n0 1 2 3\n1 4 5 6\n", 3, "after 2 of 3 points");
    expect_error(dir, "d.node", "3 3 0 0\n0 1 2 3\n1 4 5 6\n3 7 8 9\n", 4, "out of sequence");
    expect_error(dir, "e.node", "1 3 0 0\n2 1 2 3\n", 2, "first point index must be 0 or 1");
    expect_error(dir, "f.node", "1 3 0 0\n0 1 2 3\n", 1, "weight", true);
    expect_error(dir, "g.node", "1 3 0 0\n0 1 2 3\n1 4 5 6\n", 3, "data after the 1 points");
    expect_error(dir, "h.node", "1 3 1 0\n0 1 2 3\n", 2, "expected 5 fields, found 4");
    expect_error(dir, "i.node", "2 3 0 0\n0 1 2 3\n1 4 nan 6\n", 3, "NaN");
    expect_error(dir, "j.node", "0 3 0 0\n", 1, "no points");
    expect_error(dir, "k.node", "x 3 0 0\n", 1, "number of points");
    expect_error(dir, "l.node", "1 3 0 2\n0 1 2 3 4 5\n", 1, "boundary markers");
    expect_error(dir, "m.node", "1 3 0 0 7\n0 1 2 3\n", 1, "more than 4 fields");
}

// Writes PLY files byte by byte, independently of the reader, in either byte order.
class PlyBuilder {
public:
    PlyBuilder(std::string_view format, std::string_view header_body) {
        bytes_ = "ply\nformat " + std::string(format) + " 1.0\ncomment made by the test\n" +
                 std::string(header_body) + "end_header\n";
        big_ = format == "binary_big_endian";
    }

    template <class T>
    PlyBuilder& put(T value) {
        auto raw = std::bit_cast<std::array<char, sizeof(T)>>(value);
        if (big_ == (std::endian::native == std::endian::little)) {
            std::reverse(raw.begin(), raw.end());
        }
        bytes_.append(raw.data(), raw.size());
        return *this;
    }

    PlyBuilder& text(std::string_view s) {
        bytes_ += s;
        return *this;
    }

    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
    bool big_ = false;
};

// A face element before the vertices, properties of several types around x, y, z and w, and an
// element after them: everything but x, y, z and w must be skipped correctly.
constexpr std::string_view kMixedHeader =
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property float quality\n"
    "element vertex 3\n"
    "property uchar red\n"
    "property double x\n"
    "property float y\n"
    "property list ushort short ring\n"
    "property int z\n"
    "property double w\n"
    "property short tag\n"
    "element edge 1\n"
    "property int a\n";

PlyBuilder mixed_binary(std::string_view format) {
    PlyBuilder ply(format, kMixedHeader);
    ply.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    ply.put<float>(0.5f);
    ply.put<std::uint8_t>(4)
        .put<std::int32_t>(0)
        .put<std::int32_t>(1)
        .put<std::int32_t>(2)
        .put<std::int32_t>(0);
    ply.put<float>(0.25f);
    const double xs[3] = {std::numeric_limits<double>::denorm_min(), -1e300, 0.1};
    const float ys[3] = {1.5f, -0.0f, 3.0e38f};
    const std::int32_t zs[3] = {-7, 2147483647, 0};
    const double ws[3] = {1e-300, 2.0, -3.0};
    for (int i = 0; i < 3; ++i) {
        ply.put<std::uint8_t>(255).put<double>(xs[i]).put<float>(ys[i]);
        ply.put<std::uint16_t>(static_cast<std::uint16_t>(i));
        for (int k = 0; k < i; ++k) {
            ply.put<std::int16_t>(-1);
        }
        ply.put<std::int32_t>(zs[i]).put<double>(ws[i]).put<std::int16_t>(-5);
    }
    ply.put<std::int32_t>(42);
    return ply;
}

void expect_mixed(const PointSet& set, bool weighted) {
    ASSERT_EQ(set.size(), 3u);
    EXPECT_EQ(bits(set.points[0].x), bits(std::numeric_limits<double>::denorm_min()));
    EXPECT_EQ(set.points[1].x, -1e300);
    EXPECT_EQ(set.points[2].x, 0.1);
    EXPECT_EQ(set.points[0].y, 1.5);
    EXPECT_EQ(bits(set.points[1].y), bits(-0.0));
    EXPECT_EQ(set.points[2].y, static_cast<double>(3.0e38f));
    EXPECT_EQ(set.points[0].z, -7.0);
    EXPECT_EQ(set.points[1].z, 2147483647.0);
    EXPECT_EQ(set.points[2].z, 0.0);
    EXPECT_EQ(set.index_base, 0);
    if (weighted) {
        ASSERT_EQ(set.weights.size(), 3u);
        EXPECT_EQ(set.weights[0], 1e-300);
        EXPECT_EQ(set.weights[2], -3.0);
    } else {
        EXPECT_FALSE(set.weighted());
    }
}

TEST(PointIo, BinaryPlyBothByteOrders) {
    TempDir dir;
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const auto file = dir.write(std::string(format) + ".ply", mixed_binary(format).bytes());
        expect_mixed(read_points(file, false), false);
        expect_mixed(read_points(file, true), true);
    }
}

TEST(PointIo, AsciiPly) {
    TempDir dir;
    PlyBuilder ply("ascii", kMixedHeader);
    ply.text("3 0 1 2 0.5\n4 0 1 2 0 0.25\n")
        .text("255 4.9406564584124654e-324 1.5 0 -7 1e-300 -5\n")
        .text("255 -1e300 -0 1 -1 2147483647 2 -5\n")
        .text("255 0.1 0x1.1c3e5ep+127 2 -1 -1 0 -3 -5\n")
        .text("42\n");
    const auto file = dir.write("ascii.ply", ply.bytes());
    const PointSet set = read_points(file, true);
    ASSERT_EQ(set.size(), 3u);
    EXPECT_EQ(bits(set.points[0].x), bits(std::numeric_limits<double>::denorm_min()));
    EXPECT_EQ(set.points[2].y, 0x1.1c3e5ep+127);
    EXPECT_EQ(set.points[1].z, 2147483647.0);
    EXPECT_EQ(set.weights[0], 1e-300);
}

TEST(PointIo, PlyWeightMayBeNamedWeight) {
    TempDir dir;
    PlyBuilder ply("ascii",
                   "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                   "property float weight\n");
    ply.text("1 2 3 4\n");
    const PointSet set = read_points(dir.write("w.ply", ply.bytes()), true);
    EXPECT_EQ(set.weights.at(0), 4.0);
}

TEST(PointIo, PlyErrors) {
    TempDir dir;
    const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
    expect_error(dir, "a.ply", "", std::nullopt, "empty");
    expect_error(dir, "b.ply", "plyx\n", 1, "not a PLY file");
    expect_error(dir,
                 "c.ply",
                 PlyBuilder("ascii", "element face 1\nproperty int a\n").text("1\n").bytes(),
                 std::nullopt,
                 "no vertex element");
    expect_error(dir,
                 "d.ply",
                 PlyBuilder("ascii", "element vertex 1\nproperty float x\n").bytes(),
                 4,
                 "no 'y' property");
    expect_error(dir,
                 "e.ply",
                 PlyBuilder("ascii", "element vertex 1\n" + xyz).text("1 2 3\n").bytes(),
                 4,
                 "'weight' or 'w'",
                 true);
    expect_error(dir,
                 "f.ply",
                 PlyBuilder("ascii", "element vertex 2\n" + xyz).text("1 2 3\n4 5\n").bytes(),
                 10,
                 "file ends in vertex 1");
    expect_error(dir,
                 "g.ply",
                 PlyBuilder("ascii", "element vertex 2\n" + xyz).text("1 2 3\n4 nan 6\n").bytes(),
                 10,
                 "vertex 1 y");
    expect_error(dir,
                 "h.ply",
                 PlyBuilder("utf8", "element vertex 1\n" + xyz).bytes(),
                 2,
                 "unknown PLY format");
    expect_error(dir,
                 "i.ply",
                 PlyBuilder("ascii", "element vertex 1\nproperty float128 x\n").bytes(),
                 5,
                 "unknown PLY property type");
    expect_error(dir, "j.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", 4, "no end_header");
    expect_error(
        dir, "k.ply", PlyBuilder("ascii", "element vertex 0\n" + xyz).bytes(), 4, "no points");

    PlyBuilder truncated("binary_little_endian", "element vertex 3\n" + xyz);
    truncated.put<float>(1).put<float>(2).put<float>(3).put<float>(4).put<float>(5);
    expect_error(dir, "l.ply", truncated.bytes(), std::nullopt, "vertex 1");

    PlyBuilder nan("binary_big_endian", "element vertex 2\n" + xyz);
    nan.put<float>(1).put<float>(2).put<float>(3);
    nan.put<float>(4).put<float>(std::numeric_limits<float>::quiet_NaN()).put<float>(6);
    expect_error(dir, "m.ply", nan.bytes(), std::nullopt, "vertex 1 y: not a finite number");

    PlyBuilder inf("binary_little_endian", "element vertex 1\n" + xyz);
    inf.put<float>(std::numeric_limits<float>::infinity()).put<float>(2).put<float>(3);
    expect_error(dir, "n.ply", inf.bytes(), std::nullopt, "vertex 0 x: not a finite number");
}

}  // namespace
}  // namespace cavity::core
