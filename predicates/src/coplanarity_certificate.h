#pragma once

#include <span>

#include "cavity/predicates/generic_point.h"

// A structural proof that orient3d or insphere of generic points is exactly zero, from exact
// orient3d on their defining doubles alone: the exact stage's GMP determinants decide nothing else
// so often in a protected CDT (flat hull faces, the validator), and there no filter can help.
namespace cavity::predicates::detail {

/// True only when every point of g lies on one plane, or on one line, spanned by defining doubles
/// of g (a point whose homogeneous W is zero counts as lying anywhere); false when no such proof
/// was found, which says nothing. When true, the exact stage's orient3d of four points and
/// insphere of five are both zero (coplanarity_certificate.cpp proves it).
bool certified_coplanar(std::span<const GenericPoint3* const> g);

}  // namespace cavity::predicates::detail
