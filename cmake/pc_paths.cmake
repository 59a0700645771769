# The paths of bezsurf.pc from PREFIX, LIBDIR and INCLUDEDIR (the CMAKE_INSTALL_ values):
# BS_PC_PREFIX, BS_PC_LIBDIR, BS_PC_INCLUDEDIR. Under /usr (a Debian package, a distribution)
# plain absolute paths: prefix=/usr, includedir=${prefix}/include, which pkg-config knows as a
# system directory and leaves out. Elsewhere the file is relocatable: its prefix is found from
# its own directory, so `cmake --install --prefix` anywhere works. Absolute install dirs are kept.
# Included by CMakeLists.txt and run alone by tests/install/pc_paths_test.cmake.
function(bs_pc_paths prefix libdir includedir)
  if(prefix STREQUAL "/usr")
    set(pc_prefix "/usr")
  else()
    file(RELATIVE_PATH to_prefix "/prefix/${libdir}/pkgconfig" "/prefix")
    string(REGEX REPLACE "/$" "" to_prefix "${to_prefix}")
    set(pc_prefix "\${pcfiledir}/${to_prefix}")
  endif()
  if(IS_ABSOLUTE "${includedir}")
    set(pc_include "${includedir}")
  else()
    set(pc_include "\${prefix}/${includedir}")
  endif()
  if(IS_ABSOLUTE "${libdir}")
    set(pc_lib "${libdir}")
  else()
    set(pc_lib "\${exec_prefix}/${libdir}")
  endif()
  set(BS_PC_PREFIX "${pc_prefix}" PARENT_SCOPE)
  set(BS_PC_LIBDIR "${pc_lib}" PARENT_SCOPE)
  set(BS_PC_INCLUDEDIR "${pc_include}" PARENT_SCOPE)
endfunction()
