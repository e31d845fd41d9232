# Debian's libfftw3-dev ships pkg-config files but no CMake package: find it through pkg-config.
find_package(PkgConfig REQUIRED)
pkg_check_modules(PC_FFTW3 QUIET IMPORTED_TARGET fftw3)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FFTW3 REQUIRED_VARS PC_FFTW3_FOUND VERSION_VAR PC_FFTW3_VERSION)
if(FFTW3_FOUND AND NOT TARGET FFTW3::fftw3)
  add_library(FFTW3::fftw3 INTERFACE IMPORTED)
  target_link_libraries(FFTW3::fftw3 INTERFACE PkgConfig::PC_FFTW3)
endif()
