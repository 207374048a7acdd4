#include "vtk_binary.h"

#include <bit>
#include <cstdint>
#include <new>

#include <zlib.h>

#include "cavity/core/base/error.h"

namespace cavity::core {

static_assert(std::endian::native == std::endian::little,
              "the .vtu writer declares byte_order=\"LittleEndian\" and writes native bytes");

namespace {

void append_uint64(std::string& out, std::uint64_t value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

}  // namespace

void VtkBinaryArray::bytes(std::string_view raw) {
    while (!raw.empty()) {
        const std::size_t take = std::min(raw.size(), kBlockSize - block_.size());
        block_.append(raw.substr(0, take));
        raw.remove_prefix(take);
        if (block_.size() == kBlockSize) {
            compress_block();
        }
    }
}

void VtkBinaryArray::compress_block() {
    // One zlib stream per block (VTK inflates each alone), at zlib's fastest level, with or
    // without its search for repeated strings (VtkPacking). Room first, so that a failed resize
    // leaves no stream behind: compressBound bounds deflate's output at these settings (zlib's
    // default window and memory level).
    uLong size = compressBound(static_cast<uLong>(block_.size()));
    const std::size_t at = compressed_.size();
    compressed_.resize(at + size);
    z_stream stream{};
    const int init =
        deflateInit2(&stream,
                     Z_BEST_SPEED,
                     Z_DEFLATED,
                     15,
                     8,
                     packing_ == VtkPacking::kSearch ? Z_DEFAULT_STRATEGY : Z_HUFFMAN_ONLY);
    if (init == Z_MEM_ERROR) {
        throw std::bad_alloc();
    }
    if (init != Z_OK) {
        throw InternalError("zlib deflateInit2 failed with status " + std::to_string(init));
    }
    stream.next_in = reinterpret_cast<Bytef*>(block_.data());
    stream.avail_in = static_cast<uInt>(block_.size());
    stream.next_out = reinterpret_cast<Bytef*>(compressed_.data() + at);
    stream.avail_out = static_cast<uInt>(size);
    const int status = deflate(&stream, Z_FINISH);
    size = stream.total_out;
    deflateEnd(&stream);
    if (status != Z_STREAM_END) {
        throw InternalError("zlib deflate failed with status " + std::to_string(status));
    }
    compressed_.resize(at + size);
    append_uint64(sizes_, size);
    ++block_count_;
    last_block_ = block_.size();
    block_.clear();
}

std::string VtkBinaryArray::encode() {
    if (!block_.empty() || block_count_ == 0) {
        compress_block();  // the partial last block (an empty array is one empty block)
    }
    std::string header;
    append_uint64(header, block_count_);
    append_uint64(header, kBlockSize);
    append_uint64(header, last_block_);
    header += sizes_;
    return base64(header) + base64(compressed_);
}

std::string base64(std::string_view raw) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    // Sized once and filled by index: appending a character at a time cost a length check each.
    std::string out((raw.size() / 3) * 4, '\0');
    std::size_t i = 0;
    for (std::size_t o = 0; i + 3 <= raw.size(); i += 3, o += 4) {
        const std::uint32_t v = (std::uint32_t{static_cast<unsigned char>(raw[i])} << 16) |
                                (std::uint32_t{static_cast<unsigned char>(raw[i + 1])} << 8) |
                                std::uint32_t{static_cast<unsigned char>(raw[i + 2])};
        out[o] = kDigits[(v >> 18) & 63];
        out[o + 1] = kDigits[(v >> 12) & 63];
        out[o + 2] = kDigits[(v >> 6) & 63];
        out[o + 3] = kDigits[v & 63];
    }
    if (i < raw.size()) {
        const bool two = i + 1 < raw.size();
        const std::uint32_t v =
            (std::uint32_t{static_cast<unsigned char>(raw[i])} << 16) |
            (two ? std::uint32_t{static_cast<unsigned char>(raw[i + 1])} << 8 : 0u);
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += two ? kDigits[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

}  // namespace cavity::core
