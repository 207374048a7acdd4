#pragma once

#include "cavity/perturbation/sos.h"

/// The conflict test of a ghost tetrahedron (Cheng, Dey & Shewchuk §5.2).
///
/// Let vwx be a convex-hull triangle, oriented so that its back adjoins the positively oriented
/// solid tetrahedron x w v y, and let vwxg be its ghost tetrahedron. u conflicts with vwxg when u
/// is in the outer halfspace of vwx: the open halfspace in front of vwx, or u coplanar with vwx and
/// inside its open circumdisk (the limit of the circumball of vwxg as g moves away). The disk test
/// needs no constructed point: for u in the plane of vwx, u is inside the circumdisk exactly when
/// it is inside the circumball of x w v y. When u lies on the circumcircle, the tie is broken by
/// the same weight perturbation restricted to the plane: the hull triangulation of a flat hull face
/// is the 2D perturbed Delaunay triangulation of the points in it, so only v, w, x and u take part
/// (y only orients the plane).
namespace cavity::perturbation {

/// kPos when u is in the perturbed outer halfspace of hull triangle vwx, kNeg otherwise; never
/// kZero for distinct points. y is the apex of the solid tetrahedron x w v y behind vwx. keys holds
/// the perturbation keys of v, w, x, u in that order.
Sign outer_halfspace_sos(const Point3& v,
                         const Point3& w,
                         const Point3& x,
                         const Point3& y,
                         const Point3& u,
                         const Keys4& keys);

SosVerdict outer_halfspace_sos_staged(const Point3& v,
                                      const Point3& w,
                                      const Point3& x,
                                      const Point3& y,
                                      const Point3& u,
                                      const Keys4& keys);

/// On any mix of input and implicit points (keys as stated in sos.h).
Sign outer_halfspace_sos(const GenericPoint3& v,
                         const GenericPoint3& w,
                         const GenericPoint3& x,
                         const GenericPoint3& y,
                         const GenericPoint3& u,
                         const Keys4& keys);

SosVerdict outer_halfspace_sos_staged(const GenericPoint3& v,
                                      const GenericPoint3& w,
                                      const GenericPoint3& x,
                                      const GenericPoint3& y,
                                      const GenericPoint3& u,
                                      const Keys4& keys);

/// The weighted version: the in-plane test is the 2D power test of u against v, w, x.
Sign outer_halfspace_weighted_sos(const WeightedPoint3& v,
                                  const WeightedPoint3& w,
                                  const WeightedPoint3& x,
                                  const WeightedPoint3& y,
                                  const WeightedPoint3& u,
                                  const Keys4& keys);

SosVerdict outer_halfspace_weighted_sos_staged(const WeightedPoint3& v,
                                               const WeightedPoint3& w,
                                               const WeightedPoint3& x,
                                               const WeightedPoint3& y,
                                               const WeightedPoint3& u,
                                               const Keys4& keys);

}  // namespace cavity::perturbation
