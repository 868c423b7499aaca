# What the sanitizer build (SDLQR_SANITIZE) leaves uninstrumented: fixed-size arithmetic, every
# matrix size a template constant, no message, text, length or index from outside the process
# (their callers, which validate those, stay instrumented). Uninstrumented, it is what a main build
# has already compiled: with SDLQR_MAIN_BUILD=<main build folder> (`./sdlqr test` sets it) the
# sanitizer build links the main build's objects instead of compiling them again. Without it, a
# sanitizer build compiles them itself without the sanitizers.
set(SDLQR_MAIN_BUILD "" CACHE PATH "sanitizer build: the main build folder whose uninstrumented objects it links")
set(_SDLQR_UNINSTRUMENTED_OPTIONS "-fno-sanitize=all;-g0;-O2")

# The folder of the main build's objects of <target>, defined in the current directory.
function(_sdlqr_main_build_object_dir out_var target)
  file(RELATIVE_PATH binary_dir ${PROJECT_BINARY_DIR} ${CMAKE_CURRENT_BINARY_DIR})
  set(${out_var} ${SDLQR_MAIN_BUILD}/${binary_dir}/CMakeFiles/${target}.dir PARENT_SCOPE)
endfunction()

# <objects>, which exist, as sources to link: none missing, or configuring stops.
function(_sdlqr_link_main_build_objects objects)
  if(NOT objects)
    message(FATAL_ERROR "SDLQR_MAIN_BUILD=${SDLQR_MAIN_BUILD} lacks objects this sanitizer build links: "
                        "build that folder first")
  endif()
  foreach(object ${objects})
    if(NOT EXISTS ${object})
      message(FATAL_ERROR "SDLQR_MAIN_BUILD=${SDLQR_MAIN_BUILD} has no ${object}: build that folder first")
    endif()
  endforeach()
  set_source_files_properties(${objects} PROPERTIES EXTERNAL_OBJECT ON GENERATED ON)
endfunction()

# sdlqr_uninstrumented_library(<library> [INSTRUMENTED <file>...])
#
# <library> is arithmetic (common/math's solvers; the simulator's physics and the bodyrate loop,
# which the replay and batch tests run thousands of times a simulated second), but for the files
# listed INSTRUMENTED: those that read parameters, command lines or messages. In the main build
# these files compile apart from the library's unity file; in a sanitizer build they are compiled
# with the sanitizers and the rest is the main build's objects (or, without a main build, compiled
# without the sanitizers). Call it in the directory that defines <library>, after add_library,
# with paths relative to that directory.
function(sdlqr_uninstrumented_library target)
  cmake_parse_arguments(ARG "" "" "INSTRUMENTED" ${ARGN})
  if(NOT SDLQR_SANITIZE)
    set_source_files_properties(${ARG_INSTRUMENTED} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    return()
  endif()
  if(SDLQR_MAIN_BUILD)
    _sdlqr_main_build_object_dir(object_dir ${target})
    file(GLOB_RECURSE objects ${object_dir}/*.o)
    foreach(source ${ARG_INSTRUMENTED})
      list(REMOVE_ITEM objects ${object_dir}/${source}.o)
    endforeach()
    _sdlqr_link_main_build_objects("${objects}")
    set_property(TARGET ${target} PROPERTY SOURCES ${objects} ${ARG_INSTRUMENTED})
  else()
    get_target_property(sources ${target} SOURCES)
    list(REMOVE_ITEM sources ${ARG_INSTRUMENTED})
    set_source_files_properties(${sources} PROPERTIES COMPILE_OPTIONS "${_SDLQR_UNINSTRUMENTED_OPTIONS}")
  endif()
endfunction()

# sdlqr_arithmetic_sources(<out-var> TARGET <library> SOURCES <file>...)
#
# Single files of arithmetic in a library that is otherwise instrumented (the EKF, the closed-loop
# check of a K). <out-var> receives what to list in add_library(<library> ...): the sources
# themselves in the main build (each its own object, outside the library's unity file, so that the
# sanitizer build finds it), the main build's objects in the sanitizer build. Call it in the
# directory that defines <library>, with paths relative to that directory.
function(sdlqr_arithmetic_sources out_var)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  if(SDLQR_SANITIZE AND SDLQR_MAIN_BUILD)
    _sdlqr_main_build_object_dir(object_dir ${ARG_TARGET})
    list(TRANSFORM ARG_SOURCES PREPEND ${object_dir}/ OUTPUT_VARIABLE objects)
    list(TRANSFORM objects APPEND .o)
    _sdlqr_link_main_build_objects("${objects}")
    set(${out_var} ${objects} PARENT_SCOPE)
    return()
  endif()
  set_source_files_properties(${ARG_SOURCES} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
  if(SDLQR_SANITIZE)
    set_source_files_properties(${ARG_SOURCES} PROPERTIES COMPILE_OPTIONS "${_SDLQR_UNINSTRUMENTED_OPTIONS}")
  endif()
  set(${out_var} ${ARG_SOURCES} PARENT_SCOPE)
endfunction()
