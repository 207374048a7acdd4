# Reading and writing points and meshes, generators, insertion orders.
target_sources(cavity_core PRIVATE
  src/atomic_file.cpp
  src/text_input.cpp
  src/read_node.cpp
  src/read_xyz.cpp
  src/read_ply.cpp
  src/point_io.cpp
  src/read_ele.cpp
  src/write_mesh.cpp
  src/points_fingerprint.cpp
  src/write_tetgen_adjacency.cpp
  src/write_vtu.cpp
  src/vtk_binary.cpp
  src/lattice_sphere.cpp
  src/generate.cpp
  src/spatial_sort.cpp
  src/insertion_order.cpp
)
# .vtu arrays are zlib-compressed as VTK writes them.
target_link_libraries(cavity_core PRIVATE ZLIB::ZLIB)
