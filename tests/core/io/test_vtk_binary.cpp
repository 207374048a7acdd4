#include <string>

#include <gtest/gtest.h>

#include "../../../core/io/src/vtk_binary.h"

namespace cavity::core {
namespace {

// RFC 4648 §10 test vectors.
TEST(Base64, Rfc4648Vectors) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foob"), "Zm9vYg==");
    EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64(std::string("\xff\xfe\x00", 3)), "//4A");
}

// The header VTK reads first: one block, of block size 32768, holding 3 bytes.
TEST(VtkBinaryArray, HeaderCountsBlocks) {
    VtkBinaryArray array;
    array.append(std::uint8_t{1});
    array.append(std::uint16_t{2});
    const std::string encoded = array.encode();
    std::string header;
    for (const std::uint64_t v : {std::uint64_t{1}, std::uint64_t{32768}, std::uint64_t{3}}) {
        header.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    // The fourth header word is the compressed size, which depends on zlib's output.
    EXPECT_EQ(encoded.substr(0, 32), base64(header));
}

}  // namespace
}  // namespace cavity::core
