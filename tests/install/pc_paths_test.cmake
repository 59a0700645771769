# bezsurf.pc under /usr has plain paths (-I/usr/include, not
# /usr/lib/x86_64-linux-gnu/pkgconfig/../../../include); elsewhere it is relocatable.
# usage: cmake -DSOURCE=<source dir> -DWORK=<scratch dir> -P pc_paths_test.cmake
cmake_minimum_required(VERSION 3.16)
include(${SOURCE}/cmake/pc_paths.cmake)
set(PROJECT_DESCRIPTION "test")
set(PROJECT_HOMEPAGE_URL "https://example.invalid")
set(PROJECT_VERSION "1.2.0")
set(failures 0)
function(expect_line file line)
  file(STRINGS ${file} lines)
  if(NOT "${line}" IN_LIST lines)
    message(SEND_ERROR "${file}: no line '${line}' in:\n${lines}")
  endif()
endfunction()

bs_pc_paths("/usr" "lib/x86_64-linux-gnu" "include")
configure_file(${SOURCE}/pkgconfig/bezsurf.pc.in ${WORK}/usr/bezsurf.pc @ONLY)
expect_line(${WORK}/usr/bezsurf.pc "prefix=/usr")
expect_line(${WORK}/usr/bezsurf.pc "includedir=\${prefix}/include")
expect_line(${WORK}/usr/bezsurf.pc "libdir=\${exec_prefix}/lib/x86_64-linux-gnu")

bs_pc_paths("/home/u/.local" "lib" "include")
configure_file(${SOURCE}/pkgconfig/bezsurf.pc.in ${WORK}/local/bezsurf.pc @ONLY)
expect_line(${WORK}/local/bezsurf.pc "prefix=\${pcfiledir}/../..")

find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG) # what a user sees: the include directory pkg-config resolves
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${WORK}/usr
                  ${PKG_CONFIG} --variable=includedir bezsurf OUTPUT_VARIABLE inc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT inc STREQUAL "/usr/include")
    message(SEND_ERROR "pkg-config under /usr gives includedir '${inc}', not /usr/include")
  endif()
endif()
