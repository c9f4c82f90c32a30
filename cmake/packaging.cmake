# `cpack -G DEB` in a build directory makes orthoray_VERSION_ARCH.deb: the
# program, the static library and headers, the CMake package and pkg-config
# files, the man pages and bash completion (docs/install.md).
set(CPACK_PACKAGE_NAME orthoray)
set(CPACK_PACKAGE_VENDOR "The orthoray developers")
set(CPACK_PACKAGE_CONTACT "The orthoray developers <orthoray@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "orthoray decides exactly where light goes among axis-aligned and diagonal mirrors, "
    "beam splitters and absorbers in 2D and 3D, and proves each answer with a certificate "
    "that 'orthoray verify' checks.")
set(CPACK_STRIP_FILES ON)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.invalid/orthoray")
# The program links GMP dynamically (libgmp10, libgmpxx4ldbl) and the C++
# runtime; a program built against the library also needs GMP's headers.
# Written out rather than found by dpkg-shlibdeps, which lives in dpkg-dev, a
# package a fresh machine need not have.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libc6 (>= 2.34), libstdc++6 (>= 12), libgmp10, libgmpxx4ldbl")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libgmp-dev, librsvg2-bin, python3")
include(CPack)
