// libFuzzer target: the input bytes are read as doubles (non-finite ones skipped) and fill one
// orient3d, one insphere and one orient4d query; each predicate and its _staged variant must give
// the oracle's sign. A disagreement prints the query as a `cavity sign` line and aborts.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"

namespace {

using namespace cavity::predicates;

constexpr std::size_t kValues = 20;  // the largest query, orient4d: 5 points x (x y z w)

// The finite doubles of the input, cycled to fill kValues entries (zeros for an input with none),
// so short inputs still produce queries with repeated, hence degenerate-prone, coordinates.
std::array<double, kValues> values_from(const std::uint8_t* data, std::size_t size) {
    std::array<double, kValues> finite{};
    std::size_t count = 0;
    for (std::size_t offset = 0; offset + sizeof(double) <= size && count < kValues;
         offset += sizeof(double)) {
        double x = 0.0;
        std::memcpy(&x, data + offset, sizeof x);
        if (std::isfinite(x)) {
            finite[count++] = x;
        }
    }
    for (std::size_t i = count; count > 0 && i < kValues; ++i) {
        finite[i] = finite[i % count];
    }
    return finite;
}

void check(const char* name, const double* v, std::size_t n, Sign fast, Sign staged, Sign exact) {
    if (fast == exact && staged == exact) {
        return;
    }
    std::fprintf(stderr,
                 "%s: plain %d, staged %d, oracle %d\nreplay: echo '%s",
                 name,
                 to_int(fast),
                 to_int(staged),
                 to_int(exact),
                 name);
    for (std::size_t i = 0; i < n; ++i) {
        std::fprintf(stderr, " %a", v[i]);
    }
    std::fprintf(stderr, "' | cavity sign --stage\n");
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::array<double, kValues> v = values_from(data, size);
    const auto p = [&](std::size_t i) { return Point3{v[3 * i], v[3 * i + 1], v[3 * i + 2]}; };
    const auto w = [&](std::size_t i) {
        return WeightedPoint3{v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]};
    };
    check("orient3d",
          v.data(),
          12,
          orient3d(p(0), p(1), p(2), p(3)),
          orient3d_staged(p(0), p(1), p(2), p(3)).sign,
          oracle::orient3d(p(0), p(1), p(2), p(3)));
    check("insphere",
          v.data(),
          15,
          insphere(p(0), p(1), p(2), p(3), p(4)),
          insphere_staged(p(0), p(1), p(2), p(3), p(4)).sign,
          oracle::insphere(p(0), p(1), p(2), p(3), p(4)));
    check("orient4d",
          v.data(),
          20,
          orient4d(w(0), w(1), w(2), w(3), w(4)),
          orient4d_staged(w(0), w(1), w(2), w(3), w(4)).sign,
          oracle::orient4d(w(0), w(1), w(2), w(3), w(4)));
    return 0;
}
