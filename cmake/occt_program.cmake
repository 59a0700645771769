# OpenCASCADE, for the programs that write test fixtures with it or measure against it; never a
# dependency of the library or of the tests. bs_occt_program(NAME SOURCE LIB...) adds the C++
# program NAME, excluded from the default build (build it by name), when OpenCASCADE and a C++
# compiler are found. Include this file at the top of a folder's CMakeLists.txt.
find_path(BS_OCCT_INCLUDE Standard.hxx PATH_SUFFIXES opencascade)
find_library(BS_OCCT_KERNEL TKernel)
include(CheckLanguage)
check_language(CXX)
if(BS_OCCT_INCLUDE AND BS_OCCT_KERNEL AND CMAKE_CXX_COMPILER)
  enable_language(CXX)
  set(BS_OCCT_FOUND ON)
endif()

function(bs_occt_program name source)
  if(NOT BS_OCCT_FOUND)
    return()
  endif()
  get_filename_component(_occt_dir ${BS_OCCT_KERNEL} DIRECTORY)
  add_executable(${name} ${source})
  target_include_directories(${name} PRIVATE ${BS_OCCT_INCLUDE})
  target_link_directories(${name} PRIVATE ${_occt_dir})
  target_link_libraries(${name} PRIVATE ${ARGN})
  # The project's C warning options, less the one C++ does not know; OpenCASCADE's headers use
  # std::iterator, deprecated in C++17.
  get_target_property(_occt_opts ${name} COMPILE_OPTIONS)
  if(NOT _occt_opts)
    set(_occt_opts "")
  endif()
  list(REMOVE_ITEM _occt_opts -Wmissing-prototypes)
  set_target_properties(${name} PROPERTIES CXX_STANDARD 17 EXCLUDE_FROM_ALL ON
                        COMPILE_OPTIONS "${_occt_opts};-Wno-deprecated-declarations")
endfunction()
