// libFuzzer target for one of cavity's file readers, chosen at compile time (CAVITY_FUZZ_SUFFIX:
// ".node", ".ele", ".poly", ".ply", ".xyz", ".off", ".stl" or ".obj"; surface meshes go through
// read_plc, so the surface check is fuzzed with them). The input bytes are the file. Refusing it
// with a cavity Error is the expected outcome for malformed input; anything else (a crash, another
// exception, a sanitizer report, a hang or a huge allocation, which libFuzzer's -rss_limit_mb
// catches) is a bug.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/read_plc.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/input/plc.h"
#include "cavity/core/io/mesh_io.h"
#include "cavity/core/io/point_io.h"

namespace {

// The readers take paths (they name the file in every message), so each input is written to a
// file of this process first: a tmpfs keeps that cheap.
const std::filesystem::path& scratch_file() {
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("cavity_fuzz_" + std::to_string(::getpid()) + CAVITY_FUZZ_SUFFIX);
    return file;
}

void read_as_file() {
    const std::string suffix = CAVITY_FUZZ_SUFFIX;
    if (suffix == ".ele") {
        (void)cavity::core::read_ele(scratch_file(), 0);
        (void)cavity::core::read_ele(scratch_file(), 1);
    } else if (suffix == ".poly") {
        (void)cavity::core::read_poly(scratch_file());
    } else if (suffix == ".off" || suffix == ".stl" || suffix == ".obj") {
        (void)cavity::core::read_plc(scratch_file());
    } else {
        if (suffix == ".ply") {
            try {
                (void)cavity::core::read_plc(scratch_file());
            } catch (const cavity::core::Error&) {
                // a PLY of points only is no surface; the point reader below still runs
            }
        }
        (void)cavity::core::read_points(scratch_file(), false);
        (void)cavity::core::read_points(scratch_file(), true);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    {
        std::ofstream out(scratch_file(), std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        read_as_file();
    } catch (const cavity::core::Error&) {
        // a refused file: the expected outcome for most inputs
    } catch (const std::exception& e) {
        std::fprintf(stderr, "reader threw a non-cavity exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}
