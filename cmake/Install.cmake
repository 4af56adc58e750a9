# `cmake --install BUILD --prefix P`: the gaitopt tool, the libraries, their headers under
# include/gaitopt/, and a CMake package (lib/cmake/gaitopt) so another project can
#   find_package(gaitopt 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE gaitopt::sim gaitopt::ocp)
# (examples/controller/ is such a project; tests/package/ builds it against an installed tree).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GAITOPT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/gaitopt)
set(gaitopt_libraries config io dynamics gaits ocp sim library study report parallel)

foreach(name IN LISTS gaitopt_libraries)
  set_target_properties(gaitopt_${name} PROPERTIES EXPORT_NAME ${name})
  install(DIRECTORY ${name}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gaitopt/${name}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
# The warning flags target is linked privately by every library: the static libraries' exported
# link interface names it, so it is exported too (it carries no compile flags to consumers).
set_target_properties(gaitopt_options PROPERTIES EXPORT_NAME options)
list(TRANSFORM gaitopt_libraries PREPEND gaitopt_ OUTPUT_VARIABLE gaitopt_targets)
install(TARGETS ${gaitopt_targets} gaitopt_options EXPORT gaitoptTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gaitopt)
# The KKT solver is a shared library named libpardiso.so (ocp/CMakeLists.txt): in a directory
# of its own, so it never stands in for a real Pardiso of the system, and found through the
# run path of the tool and of the programs that link gaitopt::ocp.
set_target_properties(gaitopt_kkt PROPERTIES EXPORT_NAME kkt)
install(TARGETS gaitopt_kkt EXPORT gaitoptTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/gaitopt)
# The DART plant's module (sim/CMakeLists.txt) beside it, where walkDart's dlopen looks.
if(TARGET gaitopt_dart)
  install(TARGETS gaitopt_dart LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/gaitopt)
endif()
set_target_properties(gaitopt_cli PROPERTIES
  INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}/gaitopt")
install(TARGETS gaitopt_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT gaitoptTargets NAMESPACE gaitopt:: DESTINATION ${GAITOPT_INSTALL_CMAKEDIR})
# The Python module, for PYTHONPATH=PREFIX/lib/python3/dist-packages; it finds the KKT solver
# beside the libraries as the tool does.
if(TARGET gaitopt_python)
  set_target_properties(gaitopt_python PROPERTIES
    INSTALL_RPATH "$ORIGIN/../../gaitopt")
  install(TARGETS gaitopt_python LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/python3/dist-packages)
endif()
# The files the tool reads at run time (io/data_dir.hpp): the shipped configs and the plot
# scripts, so an installed tree works with the source tree gone.
install(DIRECTORY configs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gaitopt/configs)
install(DIRECTORY plots/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gaitopt/plots
        FILES_MATCHING PATTERN "*.py")

set(GAITOPT_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/gaitopt)
configure_package_config_file(cmake/gaitoptConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/gaitoptConfig.cmake
  INSTALL_DESTINATION ${GAITOPT_INSTALL_CMAKEDIR}
  PATH_VARS GAITOPT_DATA_INSTALL_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/gaitoptConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gaitoptConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/gaitoptConfigVersion.cmake
              cmake/installed_data_dir.cpp
        DESTINATION ${GAITOPT_INSTALL_CMAKEDIR})
