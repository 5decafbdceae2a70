# Installation (POSTFX_INSTALL, on when postfx is the top-level project): the library, its public headers
# (with the generated postfx/version.h), a CMake package (find_package(postfx 0.1 CONFIG REQUIRED),
# target postfx::postfx) with its version file, and a pkg-config file. Every path in the package is
# relative to where it lies, so `cmake --install build --prefix <anywhere>` works.
include(CMakePackageConfigHelpers)

set(POSTFX_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/postfx)
install(TARGETS postfx EXPORT postfxTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/postfx/include/postfx ${PROJECT_BINARY_DIR}/postfx/include/postfx
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h" PATTERN "*.glsl")
install(EXPORT postfxTargets NAMESPACE postfx:: DESTINATION ${POSTFX_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/postfxConfig.cmake.in
    ${PROJECT_BINARY_DIR}/postfxConfig.cmake INSTALL_DESTINATION ${POSTFX_CMAKE_DIR})
# 0.x: a minor release may change the API, so a request for 0.1 takes 0.1.y only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/postfxConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/postfxConfig.cmake ${PROJECT_BINARY_DIR}/postfxConfigVersion.cmake
    DESTINATION ${POSTFX_CMAKE_DIR})

# pkg-config: prefix found from the .pc file's own place (pcfiledir), so the package can be moved.
set(POSTFX_PC_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(IS_ABSOLUTE "${POSTFX_PC_DIR}")
    set(POSTFX_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
    file(RELATIVE_PATH pc_to_prefix "/root/${POSTFX_PC_DIR}" "/root")
    string(REGEX REPLACE "/$" "" pc_to_prefix "${pc_to_prefix}")
    set(POSTFX_PC_PREFIX "\${pcfiledir}/${pc_to_prefix}")
endif()
if(BUILD_SHARED_LIBS)
    set(POSTFX_PC_LIBS_PRIVATE "")
else()
    set(POSTFX_PC_LIBS_PRIVATE "-pthread")  # a static libpostfx.a needs what postfx links privately
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/postfx.pc.in ${PROJECT_BINARY_DIR}/postfx.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/postfx.pc DESTINATION ${POSTFX_PC_DIR})
