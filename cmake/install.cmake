# cmake --install: the three programs, the libraries and their headers, and a CMake package
# (find_package(lmgc), targets lmgc::grammar, lmgc::case_folder, lmgc::validate, lmgc::solver, ...).
#
# Layout under the prefix:
#   bin/                      lmgc-check, lmgc-solve, lmgc-fc3d (when HDF5 was found)
#   lib/                      the static libraries
#   include/lmgc/             grammar/, case_folder/, run/, validate/, solver/, spatial/ headers, as the sources
#                             include them
#   lib/cmake/lmgc/           lmgcConfig.cmake, lmgcConfigVersion.cmake, lmgcTargets.cmake
#   share/doc/lmgc/           README.md, LICENSE, CHANGELOG.md, docs/
#   lib/python3/dist-packages/lmgc/  the Python module lmgc.chipy (python/CMakeLists.txt), bin/lmgc-run,
#   lib/lmgc/forward/pylmgc90/        the forwarding package lmgc-run alone puts on its path
include(CMakePackageConfigHelpers)

set(lmgc_libraries lmgc_options lmgc_spatial lmgc_grammar_common lmgc_grammar lmgc_case_folder lmgc_run lmgc_validate
                   lmgc_solver lmgc_chipy)
foreach(kind IN LISTS LMGC_GRAMMAR_KINDS)
  list(APPEND lmgc_libraries lmgc_grammar_${kind})
endforeach()
if(TARGET lmgc_fclib)
  list(APPEND lmgc_libraries lmgc_fclib)
endif()
foreach(target IN LISTS lmgc_libraries)
  string(REGEX REPLACE "^lmgc_" "" exported ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${exported})
endforeach()

set(lmgc_programs lmgc-check lmgc-solve)
if(TARGET lmgc-fc3d)
  list(APPEND lmgc_programs lmgc-fc3d)
endif()
install(TARGETS ${lmgc_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${lmgc_libraries} EXPORT lmgcTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lmgc)
foreach(folder grammar case_folder run validate solver spatial chipy)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lmgc/${folder}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(EXPORT lmgcTargets NAMESPACE lmgc:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lmgc)

set(LMGC_PACKAGE_NEEDS_HDF5 ${HDF5_FOUND})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lmgcConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/lmgcConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lmgc)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lmgcConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lmgcConfig.cmake ${PROJECT_BINARY_DIR}/lmgcConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lmgc)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
