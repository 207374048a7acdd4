#pragma once

// The payload of a VTK XML DataArray in format="binary": base64 text, zlib-compressed in blocks,
// as vtkZLibDataCompressor writes it with header_type="UInt64".

#include <cstddef>
#include <string>
#include <string_view>

namespace cavity::core {

/// How zlib packs a block: with its fastest search for repeated strings, or Huffman codes alone.
/// Measured per 32 KiB block on CDT outputs (cheese, refined_elephant, bunny00 .off): on
/// coordinates the search is as fast as Huffman alone where it pays (cheese: 1.21 MB to 0.41 MB
/// instead of 1.03 MB) and costs little time where it does not; on Int32 connectivity it saved 4%
/// to 17% of the bytes at 1.6 to 2 times the time, a tenth of a surface model's run.
enum class VtkPacking { kSearch, kHuffmanOnly };

/// Collects the raw little-endian bytes of one array and encodes them. Memory: the compressed
/// blocks of the array, a third to nine tenths of the raw size on CDT outputs.
class VtkBinaryArray {
public:
    explicit VtkBinaryArray(VtkPacking packing) : packing_(packing) {}

    /// Appends the bytes of a value (the writers call it with fixed-width little-endian types).
    template <typename T>
    void append(T value) {
        // Inline while the block has room: a call per value was a tenth of writing a mesh.
        if (block_.size() + sizeof value < kBlockSize) {
            block_.append(reinterpret_cast<const char*>(&value), sizeof value);
            return;
        }
        bytes(std::string_view(reinterpret_cast<const char*>(&value), sizeof value));
    }

    /// VTK's default block size: each block is compressed alone, so readers can inflate in
    /// parallel.
    static constexpr std::size_t kBlockSize = std::size_t{1} << 15;

    /// The base64 text of the header (block count, block size, last block size, compressed
    /// sizes), then that of the compressed blocks: VTK decodes the two separately.
    std::string encode();

private:
    void bytes(std::string_view raw);
    void compress_block();

    VtkPacking packing_;
    std::string block_;            // raw bytes not yet compressed
    std::string compressed_;       // the compressed blocks, end to end
    std::string sizes_;            // the header's compressed sizes, as UInt64
    std::size_t block_count_ = 0;  // full and partial blocks compressed so far
    std::size_t last_block_ = 0;   // raw size of the latest block
};

/// Standard base64 (RFC 4648, with '=' padding).
std::string base64(std::string_view raw);

}  // namespace cavity::core
