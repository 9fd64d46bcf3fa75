# Read by cpack: a Debian package must put the vendor libraries in the multiarch folder, which
# GNUInstallDirs chooses only when the build was configured with the prefix /usr.
if(CPACK_GENERATOR STREQUAL "DEB" AND NOT CPACK_PINEDA_LIBDIR MATCHES "^lib/.+-linux-gnu")
  message(FATAL_ERROR "the library folder is '${CPACK_PINEDA_LIBDIR}': configure the build for "
    "the package with -DCMAKE_INSTALL_PREFIX=/usr (scripts/package-test.sh does)")
endif()
