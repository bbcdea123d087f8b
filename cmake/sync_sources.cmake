cmake_minimum_required(VERSION 3.20)
# cmake -D FROM=dir -D TO=dir -P sync_sources.cmake
# Mirror the package sources (*.cpp, *.h) into TO, touching only files whose content
# changed and removing files that no longer exist, so that the cached in-tree
# LAMMPS build recompiles only what changed.
file(GLOB src_files RELATIVE ${FROM} ${FROM}/*.cpp ${FROM}/*.h)
file(MAKE_DIRECTORY ${TO})
file(GLOB old_files RELATIVE ${TO} ${TO}/*.cpp ${TO}/*.h)
foreach(f ${old_files})
  if(NOT f IN_LIST src_files)
    file(REMOVE ${TO}/${f})
  endif()
endforeach()
foreach(f ${src_files})
  execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${FROM}/${f} ${TO}/${f})
endforeach()
