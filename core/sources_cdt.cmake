# Flips, gift-wrapping and vertex deletion (Cheng, Dey & Shewchuk §4.4, §5.6).
target_sources(cavity_core PRIVATE
  src/star.cpp
  src/replace_tetrahedra.cpp
  src/complex_from_tets.cpp
  src/flips.cpp
  src/gift_wrap_engine.cpp
  src/gift_wrap.cpp
  src/vertex_deletion.cpp
)
