# OpenCASCADE for the programs that write fixtures with it or compare with it (tests/io,
# bench/); never a dependency of the library or of the tests. Include it from the folder of those
# programs: it enables C++ there when OpenCASCADE and a C++ compiler are found, and sets
# BS_OCCT_FOUND. bs_occt_executable(NAME SOURCE LIBRARY...) then builds NAME from SOURCE against
# those OpenCASCADE libraries (and any target given), excluded from the default build.
find_path(BS_OCCT_INCLUDE IGESControl_Writer.hxx PATH_SUFFIXES opencascade)
find_library(BS_OCCT_KERNEL TKernel)
include(CheckLanguage)
check_language(CXX)
set(BS_OCCT_FOUND OFF)
if(BS_OCCT_INCLUDE AND BS_OCCT_KERNEL AND CMAKE_CXX_COMPILER)
  enable_language(CXX)
  set(BS_OCCT_FOUND ON)
endif()

function(bs_occt_executable name source)
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
