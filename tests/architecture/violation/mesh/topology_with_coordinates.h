#pragma once

// A topology header that reaches for a predicate: include_rules.sh must refuse it
// (the test architecture.include_rules_refuse).
#include "cavity/core/mesh/tetrahedron.h"
#include "cavity/predicates/orient3d.h"
