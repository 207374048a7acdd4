# Storage, Bowyer–Watson insertion, point location, validation.
target_sources(cavity_core PRIVATE
  src/face_hash_storage.cpp
  src/facet_gluer.cpp
  src/geometry.cpp
  src/bootstrap.cpp
  src/duplicates.cpp
  src/triangulate.cpp
  src/validate.cpp
  src/orientation.cpp
  src/tet_adjacency.cpp
  src/page_releaser.cpp
  src/point_kd_tree.cpp
  src/conflict_counter.cpp
)
