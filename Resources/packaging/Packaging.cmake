# The Debian package (Resources/docs/building.md, "Install": `cpack --config build/CPackConfig.cmake`): everything `cmake --install`
# puts in place, under /usr. Its Depends come from the libraries the binaries actually link (dpkg-shlibdeps),
# plus what is loaded at run time and so invisible to it: the X11 libraries JUCE opens with dlopen for the
# editor and the Standalone (juce_linux_X11_Symbols.h), and Python with matplotlib and NumPy for the figures.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rosin)
set(CPACK_PACKAGE_VENDOR "Rosin")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Rosin developers <rosin-synth@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "physically modelled bowed-string synthesizer (VST3, LV2, standalone)")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "A cello and a violin computed at audio rate: a stiff string with transverse\n\
 and torsional waves, a resonant body and the rosin between bow and string,\n\
 whose friction follows its temperature. VST3 and LV2 instrument plugins, a\n\
 standalone application, and the `rosin` command line: offline rendering,\n\
 Schelleng and Guettler playability scans with figures, and comparison of the\n\
 model with bowing-machine measurements.")
set(CPACK_DEBIAN_PACKAGE_SECTION sound)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/rosin-synth/rosin")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # rosin_VERSION_ARCH.deb
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libx11-6, libxext6, libxcursor1, libxinerama1, libxrandr2, libxrender1, python3, python3-matplotlib, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libjack-jackd2-0 | libjack0") # the Standalone's JACK output, opened at run time
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)
include(CPack)
