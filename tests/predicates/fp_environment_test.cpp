#include "cavity/predicates/fp_environment.h"

#include <cfenv>

#include <gtest/gtest.h>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace cavity::predicates {

namespace {

TEST(FpEnvironment, TheTestEnvironmentIsExact) {
    EXPECT_TRUE(fp_environment_is_exact());
}

// The check must be able to say no: each case breaks one assumption, then restores it.
TEST(FpEnvironment, ADirectedRoundingModeIsRejected) {
    for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        ASSERT_EQ(std::fesetround(mode), 0);
        const bool exact = fp_environment_is_exact();
        std::fesetround(FE_TONEAREST);
        EXPECT_FALSE(exact) << "rounding mode " << mode;
    }
}

#if defined(__SSE__)
TEST(FpEnvironment, FlushToZeroAndDenormalsAreZeroAreRejected) {
    const unsigned saved = _mm_getcsr();
    constexpr unsigned kFlushToZero = 0x8000;
    constexpr unsigned kDenormalsAreZero = 0x0040;
    for (const unsigned bit : {kFlushToZero, kDenormalsAreZero}) {
        _mm_setcsr(saved | bit);
        const bool exact = fp_environment_is_exact();
        _mm_setcsr(saved);
        EXPECT_FALSE(exact) << "MXCSR bit " << bit;
    }
}
#endif

}  // namespace

}  // namespace cavity::predicates
