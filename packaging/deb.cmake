# `cpack -G DEB` in a build configured with -DCMAKE_INSTALL_PREFIX=/usr makes
# pineda_<version>_amd64.deb (scripts/package-test.sh builds and checks it). The package adds
# files beside Mesa's and replaces none:
#   /usr/lib/x86_64-linux-gnu/libGLX_pineda.so.0, libEGL_pineda.so.0   libglvnd's vendor libraries
#   /usr/lib/x86_64-linux-gnu/pineda/   libpineda.so.0, its libGL/libEGL/libOSMesa names, pkgconfig
#   /usr/share/pineda/egl_vendor.d/50_pineda.json   selected only by __EGL_VENDOR_LIBRARY_FILENAMES
#   /usr/bin/pineda-run, pineda-bench, ...
set(CPACK_PACKAGE_NAME pineda)
set(CPACK_PACKAGE_VENDOR Pineda)
set(CPACK_PACKAGE_CONTACT "Pineda developers <pineda@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Pineda, a software OpenGL 1.5 driver (GLX, EGL, OSMesa)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# install(CODE) writes the links and the vendor file under $DESTDIR: CPack must stage with it.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libGLX and libEGL (libglvnd0) load the vendor libraries; the tools link libEGL and libGL.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libglvnd0")
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_CURRENT_LIST_DIR}/deb_check_prefix.cmake)
set(CPACK_PINEDA_LIBDIR ${CMAKE_INSTALL_LIBDIR})
include(CPack)
