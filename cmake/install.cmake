# Install rules, the CMake package and the Debian package (docs/api.md, "Install and package").
#
#   cmake --install build --prefix P       P/bin/pseudoshadow
#                                          P/share/pseudoshadow/{glsl,scenes,textures}
#                                          P/<libdir>/libpseudoshadow.so (+ the OpenImageIO module
#                                            in P/<libdir>/pseudoshadow/)
#                                          P/include/pseudoshadow/pseudoshadow.h
#                                          P/<libdir>/cmake/pseudoshadow/ (find_package)
#                                          P/lib/python3/dist-packages/pseudoshadow/
#   cd build && cpack                      pseudoshadow_<version>_<arch>.deb
include(CMakePackageConfigHelpers)

set(PS_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/pseudoshadow)

install(TARGETS pseudoshadow RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Loaded with dlopen for EXR and other non-PNG files (src/image/image_io.cpp looks here).
install(TARGETS ps_image_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/pseudoshadow)
install(DIRECTORY glsl/ DESTINATION ${PS_DATA_INSTALL_DIR}/glsl
        FILES_MATCHING PATTERN "*.vert" PATTERN "*.frag" PATTERN "*.comp" PATTERN "*.glsl")
install(DIRECTORY scenes/ DESTINATION ${PS_DATA_INSTALL_DIR}/scenes FILES_MATCHING PATTERN "*.toml")
install(DIRECTORY textures/ DESTINATION ${PS_DATA_INSTALL_DIR}/textures FILES_MATCHING PATTERN "*.png" PATTERN "*.lut")

# The C++ API and its CMake package: find_package(pseudoshadow CONFIG) gives pseudoshadow::pseudoshadow.
install(TARGETS pseudoshadow_shared EXPORT pseudoshadowTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/pseudoshadow DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set(PS_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/pseudoshadow)
install(EXPORT pseudoshadowTargets NAMESPACE pseudoshadow:: DESTINATION ${PS_CMAKE_INSTALL_DIR})
configure_package_config_file(cmake/pseudoshadowConfig.cmake.in
  ${CMAKE_BINARY_DIR}/cmake/pseudoshadowConfig.cmake INSTALL_DESTINATION ${PS_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/pseudoshadowConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/pseudoshadowConfig.cmake
              ${CMAKE_BINARY_DIR}/cmake/pseudoshadowConfigVersion.cmake
        DESTINATION ${PS_CMAKE_INSTALL_DIR})

# The Python package (not in sanitizer builds, see the top-level CMakeLists.txt).
if(TARGET ps_python_core)
  install(TARGETS ps_python_core LIBRARY DESTINATION ${PS_PYTHON_INSTALL_DIR}/pseudoshadow)
  install(FILES python/pseudoshadow/__init__.py DESTINATION ${PS_PYTHON_INSTALL_DIR}/pseudoshadow)
endif()

# ---- Debian package (CPack) ----
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pseudoshadow)
set(CPACK_PACKAGE_VENDOR "pseudoshadow")
set(CPACK_PACKAGE_CONTACT "pseudoshadow maintainers <pseudoshadow@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Pseudo-shadows of a haptic probe on virtual surfaces (OpenGL 4.5, headless)")
set(CPACK_PACKAGE_INSTALL_DIRECTORY pseudoshadow)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)          # pseudoshadow_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Stripped: the debug info of a RelWithDebInfo build is ~10x the code; the package stays small
# and builds in seconds.
set(CPACK_STRIP_FILES ON)
# The shared libraries the binaries link (libEGL, libOSMesa, glslang, assimp, libpng, ...) are
# found by dpkg-shlibdeps (dpkg-dev) from the binaries themselves. What they only dlopen is named
# here: Mesa's EGL vendor library and its llvmpipe driver (the GL itself), and numpy for the
# Python module. The monkey-head scene reads Suzanne from assimp-testmodels.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "assimp-testmodels, python3-matplotlib")
include(CPack)
