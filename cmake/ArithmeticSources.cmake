# sdlqr_arithmetic_sources(<out-var> TARGET <library> SOURCES <file>...)
#
# Sources of fixed-size arithmetic: every matrix size a template constant, no message, text,
# length or index from outside the process (their callers, which validate those, stay
# instrumented). The sanitizer build does not compile them again but links the main build's
# uninstrumented objects (SDLQR_SOLVERS_FROM, as it does the solvers, common/CMakeLists.txt):
# instrumented, the two of them named here cost the sanitizer build 68 of its 716 CPU-s, for
# checks that find nothing in code without a pointer or index from outside.
#
# <out-var> receives what to list in add_library(<library> ...): the sources themselves in the
# main build (each its own object, outside the library's unity file, so that the sanitizer build
# finds it), the main build's objects in the sanitizer build. Call it in the directory that
# defines <library>, with paths relative to that directory.
function(sdlqr_arithmetic_sources out_var)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(result "")
  if(SDLQR_SANITIZE AND SDLQR_SOLVERS_FROM)
    file(RELATIVE_PATH binary_dir ${PROJECT_BINARY_DIR} ${CMAKE_CURRENT_BINARY_DIR})
    foreach(source ${ARG_SOURCES})
      set(object ${SDLQR_SOLVERS_FROM}/${binary_dir}/CMakeFiles/${ARG_TARGET}.dir/${source}.o)
      if(NOT EXISTS ${object})
        message(FATAL_ERROR "SDLQR_SOLVERS_FROM=${SDLQR_SOLVERS_FROM} has no ${binary_dir}/CMakeFiles/"
                            "${ARG_TARGET}.dir/${source}.o: build that folder first")
      endif()
      set_source_files_properties(${object} PROPERTIES EXTERNAL_OBJECT ON GENERATED ON)
      list(APPEND result ${object})
    endforeach()
  else()
    foreach(source ${ARG_SOURCES})
      set_source_files_properties(${source} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      list(APPEND result ${source})
    endforeach()
  endif()
  set(${out_var} ${result} PARENT_SCOPE)
endfunction()
