#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

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
    VtkBinaryArray array(VtkPacking::kSearch);
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

std::string from_base64(const std::string& text) {
    std::string out;
    std::uint32_t bits = 0;
    int count = 0;
    for (const char c : text) {
        const std::string digits =
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        if (c == '=') {
            break;
        }
        bits = (bits << 6) | static_cast<std::uint32_t>(digits.find(c));
        if ((count += 6) >= 8) {
            count -= 8;
            out += static_cast<char>((bits >> count) & 0xFF);
        }
    }
    return out;
}

std::uint64_t word(const std::string& bytes, std::size_t k) {
    std::uint64_t v = 0;
    bytes.copy(reinterpret_cast<char*>(&v), sizeof v, 8 * k);
    return v;
}

// Both packings give blocks that zlib's own uncompress() (what VTK's reader calls) restores,
// over several blocks and a partial last one; Huffman codes alone still compress.
TEST(VtkBinaryArray, EveryBlockInflatesToItsBytes) {
    for (const VtkPacking packing : {VtkPacking::kSearch, VtkPacking::kHuffmanOnly}) {
        VtkBinaryArray array(packing);
        std::string raw;
        std::uint32_t state = 12345;
        for (int i = 0; i < 30000; ++i) {
            state = state * 1103515245u + 12345u;
            const std::int32_t value = static_cast<std::int32_t>(state >> 20);  // 12 bits
            array.append(value);
            raw.append(reinterpret_cast<const char*>(&value), sizeof value);
        }
        const std::string encoded = array.encode();
        const std::uint64_t blocks = (raw.size() + 32767) / 32768;
        const std::size_t header_chars = ((3 + blocks) * 8 + 2) / 3 * 4;
        const std::string header = from_base64(encoded.substr(0, header_chars));
        const std::string body = from_base64(encoded.substr(header_chars));
        ASSERT_EQ(word(header, 0), blocks);
        ASSERT_EQ(word(header, 2), raw.size() % 32768);
        std::size_t at = 0;
        std::string restored;
        for (std::uint64_t b = 0; b < blocks; ++b) {
            const std::uint64_t size = word(header, 3 + b);
            std::vector<Bytef> out(32768);
            uLongf length = out.size();
            ASSERT_EQ(uncompress(out.data(),
                                 &length,
                                 reinterpret_cast<const Bytef*>(body.data() + at),
                                 static_cast<uLong>(size)),
                      Z_OK);
            restored.append(reinterpret_cast<const char*>(out.data()), length);
            at += size;
        }
        EXPECT_EQ(at, body.size());
        EXPECT_EQ(restored, raw);
        EXPECT_LT(body.size(), raw.size() * 3 / 4);  // 12 random bits in 32: Huffman pays too
    }
}

}  // namespace
}  // namespace cavity::core
