# The man page bezsurf(1), written from the tool's own help texts (`bezsurf --help` and
# `bezsurf COMMAND --help`), so that the page and --help cannot drift apart.
#   cmake -DTOOL=path/to/bezsurf -DOUT=bezsurf.1 -DVERSION=1.0.0 -P man_page.cmake

# Help text as roff: shown as written (no filling), backslashes and hyphens escaped, no line
# read as a request.
function(bs_roff_block text out_var)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out_var} ".nf\n${text}.fi\n" PARENT_SCOPE)
endfunction()

function(bs_help out_var)
  execute_process(COMMAND ${TOOL} ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR text STREQUAL "")
    message(FATAL_ERROR "${TOOL} ${ARGN} --help failed (${rc})")
  endif()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

bs_help(main_help)
# The commands are the lines "  NAME   summary" after "commands:" in the main help.
string(REGEX MATCH "commands:\n(( +[a-z]+ +[^\n]*\n)+)" _ "${main_help}")
string(REGEX MATCHALL "[^\n]+" lines "${CMAKE_MATCH_1}")
set(commands "")
foreach(line IN LISTS lines)
  string(REGEX MATCH "^ +([a-z]+) " _ "${line}")
  list(APPEND commands ${CMAKE_MATCH_1})
endforeach()
if(NOT commands)
  message(FATAL_ERROR "no command list in the output of ${TOOL} --help")
endif()

bs_roff_block("${main_help}" main_roff)
set(page ".TH BEZSURF 1 \"\" \"libbezsurf ${VERSION}\" \"User Commands\"
.SH NAME
bezsurf \\- inspect, evaluate, tessellate and render Bezier surfaces
.SH SYNOPSIS
.B bezsurf
.I COMMAND
.RI [ OPTIONS ]
.RI [ FILE ]
.SH DESCRIPTION
${main_roff}.SH COMMANDS
")
foreach(cmd IN LISTS commands)
  bs_help(cmd_help ${cmd})
  bs_roff_block("${cmd_help}" cmd_roff)
  string(APPEND page ".SS ${cmd}\n${cmd_roff}")
endforeach()
string(APPEND page ".SH SEE ALSO
The libbezsurf documentation, docs/cli.md in the source tree.
")
file(WRITE ${OUT} "${page}")
