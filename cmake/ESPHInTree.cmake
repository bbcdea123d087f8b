# Included by the LAMMPS CMake build right after its project() call
# (CMAKE_PROJECT_lammps_INCLUDE): registers the ESPH sources in ESPH_SRC_DIR
# as if ESPH were a LAMMPS package, so that lmp has its styles compiled in.
# The LAMMPS source tree itself is not modified.
if(NOT ESPH_SRC_DIR)
  message(FATAL_ERROR "ESPH_SRC_DIR must point to the ESPH sources")
endif()
include(${CMAKE_CURRENT_SOURCE_DIR}/Modules/StyleHeaderUtils.cmake)
RegisterStyles(${ESPH_SRC_DIR})
file(GLOB ESPH_INTREE_SOURCES CONFIGURE_DEPENDS ${ESPH_SRC_DIR}/[^.]*.cpp)
cmake_language(DEFER CALL target_sources lammps PRIVATE ${ESPH_INTREE_SOURCES})
cmake_language(DEFER CALL target_include_directories lammps PRIVATE ${ESPH_SRC_DIR})
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
cmake_language(DEFER CALL target_link_libraries lammps PRIVATE Eigen3::Eigen)
message(STATUS "ESPH package compiled in from ${ESPH_SRC_DIR}")
