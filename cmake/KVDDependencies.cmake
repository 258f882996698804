# GMP and MPFR ship no CMake package: imported targets found by library
# name, made by the build and by an installed KVDConfig.cmake alike.
if(NOT TARGET KVD::gmp)
  find_library(KVD_GMP_LIBRARY gmp REQUIRED)
  find_library(KVD_GMPXX_LIBRARY gmpxx REQUIRED)
  find_library(KVD_MPFR_LIBRARY mpfr REQUIRED)
  find_path(KVD_GMPXX_INCLUDE_DIR gmpxx.h REQUIRED)
  find_path(KVD_MPFR_INCLUDE_DIR mpfr.h REQUIRED)
  add_library(KVD::gmp UNKNOWN IMPORTED)
  set_target_properties(KVD::gmp PROPERTIES IMPORTED_LOCATION "${KVD_GMP_LIBRARY}"
                                            INTERFACE_INCLUDE_DIRECTORIES "${KVD_GMPXX_INCLUDE_DIR}")
  add_library(KVD::gmpxx UNKNOWN IMPORTED)
  set_target_properties(KVD::gmpxx PROPERTIES IMPORTED_LOCATION "${KVD_GMPXX_LIBRARY}" INTERFACE_LINK_LIBRARIES KVD::gmp)
  add_library(KVD::mpfr UNKNOWN IMPORTED)
  set_target_properties(KVD::mpfr PROPERTIES IMPORTED_LOCATION "${KVD_MPFR_LIBRARY}"
                                             INTERFACE_INCLUDE_DIRECTORIES "${KVD_MPFR_INCLUDE_DIR}"
                                             INTERFACE_LINK_LIBRARIES KVD::gmp)
endif()
