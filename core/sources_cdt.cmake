# Flips, gift-wrapping, vertex deletion (Cheng, Dey & Shewchuk §4.4, §5.6) and constrained
# Delaunay tetrahedralizations of PLCs (§5.8).
target_sources(cavity_core PRIVATE
  src/star.cpp
  src/replace_tetrahedra.cpp
  src/complex_from_tets.cpp
  src/flips.cpp
  src/gift_wrap_engine.cpp
  src/gift_wrap.cpp
  src/vertex_deletion.cpp
  src/exact_plane.cpp
  src/read_poly.cpp
  src/plc_validity.cpp
  src/protection_point.cpp
  src/edge_protection.cpp
  src/polygon_insertion.cpp
  src/polygon_region.cpp
  src/cdt_validate.cpp
  src/cdt.cpp
  src/cdt_regions.cpp
  src/cdt_vertex_insertion.cpp
  src/write_poly.cpp
)
# Exact event times and facet geometry of polygon insertion.
target_link_libraries(cavity_core PRIVATE cavity::gmp Boost::headers)
