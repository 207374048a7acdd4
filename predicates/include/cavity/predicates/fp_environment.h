#pragma once

namespace cavity::predicates {

/// True when the floating-point environment is the one the predicates were proved for:
/// round-to-nearest, no flush-to-zero or denormals-are-zero, double evaluated as double
/// (FLT_EVAL_METHOD == 0). Checked at start-up by the CLI and by the tests.
bool fp_environment_is_exact();

}  // namespace cavity::predicates
