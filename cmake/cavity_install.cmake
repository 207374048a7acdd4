# `cmake --install`: headers, the libraries, the `cavity` program and a CMake package, so that a
# consumer writes find_package(cavity) and target_link_libraries(app PRIVATE cavity::core).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CAVITY_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/cavity" CACHE STRING
    "Install directory of cavity's CMake package, relative to the prefix")

# Static libraries that may end up in a shared object (the Python module, a consumer's plugin).
# (core's folders set it themselves.)
set_target_properties(cavity_predicates cavity_oracle cavity_perturbation
                      PROPERTIES POSITION_INDEPENDENT_CODE ON)

# The layers name their headers with a source-relative `include`; an installed package must point
# at the installed copy instead (core's folders say so themselves).
foreach(_layer predicates perturbation)
  set_property(TARGET cavity_${_layer} PROPERTY INTERFACE_INCLUDE_DIRECTORIES
               "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/${_layer}/include>"
               "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
endforeach()
set_property(TARGET cavity_oracle PROPERTY INTERFACE_INCLUDE_DIRECTORIES
             "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/predicates/include>"
             "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
unset(_layer)

# GMP is found where the build found it; in the package, cavityConfig.cmake finds it again on the
# consumer's machine and names it cavity::libgmp.
set_target_properties(cavity_gmp PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "$<BUILD_INTERFACE:${GMP_INCLUDE_DIR}>"
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "$<BUILD_INTERFACE:${GMP_INCLUDE_DIR}>"
  INTERFACE_LINK_LIBRARIES "$<BUILD_INTERFACE:${GMP_LIBRARY}>;$<INSTALL_INTERFACE:cavity::libgmp>")

# cavity::<layer> everywhere: the same names in the build tree (aliases) and in the package.
set_target_properties(cavity_predicates PROPERTIES EXPORT_NAME predicates)
set_target_properties(cavity_perturbation PROPERTIES EXPORT_NAME perturbation)
set_target_properties(cavity_core PROPERTIES EXPORT_NAME core)
set_target_properties(cavity_oracle PROPERTIES EXPORT_NAME oracle)
set_target_properties(cavity_strict_fp PROPERTIES EXPORT_NAME strict_fp)
set_target_properties(cavity_gmp PROPERTIES EXPORT_NAME gmp)
# Linked PRIVATE by every library, so the package only carries it as $<LINK_ONLY:...>, which adds
# nothing to a consumer's compile flags.
set_target_properties(cavity_warnings PROPERTIES EXPORT_NAME warnings)

install(TARGETS cavity_predicates cavity_perturbation cavity_core ${CAVITY_CORE_MODULES} cavity_oracle
                cavity_strict_fp cavity_warnings cavity_gmp
        EXPORT cavityTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
if(CAVITY_BUILD_PROGRAMS)
  install(TARGETS cavity RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()
install(DIRECTORY predicates/include/ perturbation/include/
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.h")
foreach(_module IN LISTS CAVITY_CORE_MODULES)
  string(REPLACE "cavity_core_" "" _folder "${_module}")
  install(DIRECTORY "core/${_folder}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
          FILES_MATCHING PATTERN "*.h")
endforeach()
unset(_module)
unset(_folder)
install(FILES "${PROJECT_BINARY_DIR}/generated/cavity/core/version.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/cavity/core")
install(EXPORT cavityTargets NAMESPACE cavity:: DESTINATION "${CAVITY_INSTALL_CMAKEDIR}")

configure_package_config_file(cmake/cavityConfig.cmake.in
                              "${PROJECT_BINARY_DIR}/cavityConfig.cmake"
                              INSTALL_DESTINATION "${CAVITY_INSTALL_CMAKEDIR}")
# 0.x: minor versions may break the API.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cavityConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/cavityConfig.cmake"
              "${PROJECT_BINARY_DIR}/cavityConfigVersion.cmake"
        DESTINATION "${CAVITY_INSTALL_CMAKEDIR}")

# CI: install into a temporary prefix, then configure, build and run examples/consumer against it.
if(CAVITY_BUILD_TESTS)
  set(_cavity_consumer_args "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}")
  if(CAVITY_SANITIZE)
    list(APPEND _cavity_consumer_args "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
         "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
  endif()
  add_test(NAME install.consumer
           COMMAND "${PROJECT_SOURCE_DIR}/scripts/test-install.sh" "${PROJECT_BINARY_DIR}"
                   ${_cavity_consumer_args})
  set_tests_properties(install.consumer PROPERTIES LABELS unit)
  unset(_cavity_consumer_args)
endif()
