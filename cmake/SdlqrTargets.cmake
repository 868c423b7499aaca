# The ways the repository declares its targets, each written once.

# sdlqr_process(<name> SOURCES <src>... [LINKS <item>...] [LOOP])
#   sdlqr_<name>  the process's library (its include/ public) over sdlqr_common and LINKS (a
#                 target_link_libraries list: PRIVATE and PUBLIC may appear in it); LOOP: it holds
#                 the fixed-rate loops, compiled with SDLQR_LOOP_OPTIONS
#   sdlqr-<name>  its main, <name>_main.cpp, which binds the library's core to the bus
function(sdlqr_process name)
  cmake_parse_arguments(ARG "LOOP" "" "SOURCES;LINKS" ${ARGN})
  add_library(sdlqr_${name} ${ARG_SOURCES})
  target_include_directories(sdlqr_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(sdlqr_${name} PUBLIC sdlqr_common ${ARG_LINKS})
  if(ARG_LOOP)
    target_compile_options(sdlqr_${name} PRIVATE ${SDLQR_LOOP_OPTIONS})
  endif()
  add_executable(sdlqr-${name} ${name}_main.cpp)
  target_link_libraries(sdlqr-${name} PRIVATE sdlqr_${name} sdlqr_bus)
endfunction()

# sdlqr_stamped_generator(<target> GENERATOR <executable target> ARGS <arg>... INPUTS <file>... COMMENT <text>)
#   runs GENERATOR with ARGS at build time when it or an input changes; <target>_generate is what
#   the users of its output depend on. The generators rewrite a header only when its text changes
#   (no needless recompiles), so a stamp records that the generator ran.
function(sdlqr_stamped_generator target)
  cmake_parse_arguments(ARG "" "GENERATOR;COMMENT" "ARGS;INPUTS" ${ARGN})
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}.stamp)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${ARG_GENERATOR} ${ARG_ARGS}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${ARG_GENERATOR} ${ARG_INPUTS}
    COMMENT "${ARG_COMMENT}"
    VERBATIM)
  add_custom_target(${target}_generate DEPENDS ${stamp})
endfunction()
