#include "cavity/predicates/fp_environment.h"

#include <cfenv>
#include <cfloat>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace cavity::predicates {

// Extended-precision evaluation (x87) would double-round the error-free transformations; it is a
// property of the build, so it is rejected at compile time.
static_assert(FLT_EVAL_METHOD == 0, "the predicates need double evaluated in double precision");

bool fp_environment_is_exact() {
    if (std::fegetround() != FE_TONEAREST) {
        return false;
    }
#if defined(__SSE2__)
    // MXCSR bit 15 is flush-to-zero, bit 6 denormals-are-zero: either loses the tails of products.
    constexpr unsigned kFlushToZero = 1U << 15;
    constexpr unsigned kDenormalsAreZero = 1U << 6;
    if ((_mm_getcsr() & (kFlushToZero | kDenormalsAreZero)) != 0) {
        return false;
    }
#endif
    return true;
}

}  // namespace cavity::predicates
