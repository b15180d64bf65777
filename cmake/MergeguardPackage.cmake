# The installed CMake package (docs/package.md): `cmake --install build --prefix P`
# puts the headers under P/include/mergeguard/, the module libraries and the mergeguard binary
# under P/lib and P/bin, and P/lib/cmake/mergeguard/ with the package config, its version file
# and the exported targets mergeguard::mergeguard (everything) and mergeguard::core, ::planner,
# ::sim, ::rules, ::check, ::report, ::audit, ::recording, ::paper, ::fuzz, ::league, ::cli (the
# modules, made by mg_module). Nothing of the top-level
# add_compile_options (warnings, -Werror, sanitizers) is a usage requirement: the exported
# targets carry include directories, link libraries and cxx_std_20 only.
include(CMakePackageConfigHelpers)

# mergeguard::mergeguard: every module, and the umbrella header <mergeguard/mergeguard.h>.
# (The target is mg_all in this tree: `mergeguard` is the binary.)
add_library(mg_all INTERFACE)
target_link_libraries(mg_all INTERFACE mg_cli mg_league mg_paper mg_audit mg_recording mg_fuzz mg_check mg_report mg_rules mg_sim mg_planner mg_core)
target_include_directories(mg_all INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
set_target_properties(mg_all PROPERTIES EXPORT_NAME mergeguard)
add_library(mergeguard::mergeguard ALIAS mg_all)
install(TARGETS mg_all EXPORT mergeguardTargets)
install(FILES ${PROJECT_SOURCE_DIR}/include/mergeguard/mergeguard.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mergeguard)

set(mg_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/mergeguard)
install(EXPORT mergeguardTargets NAMESPACE mergeguard:: DESTINATION ${mg_package_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/mergeguardConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/mergeguardConfig.cmake
                              INSTALL_DESTINATION ${mg_package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/mergeguardConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/mergeguardConfig.cmake
              ${PROJECT_BINARY_DIR}/package/mergeguardConfigVersion.cmake
        DESTINATION ${mg_package_dir})
