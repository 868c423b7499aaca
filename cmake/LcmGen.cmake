# Drives lcm-gen from CMake: Debian's LCM ships no CMake package.
#
# sdlqr_lcm_generate(<target> PACKAGE <pkg> FILES <a.lcm> ...)
#   <target>        INTERFACE library whose include directory holds <pkg>/<type>.hpp
#   <target>_jar    custom target building ${CMAKE_BINARY_DIR}/lcmtypes_<pkg>.jar (if javac is found)
# Everything is generated into the build folder, never the source tree.

find_program(LCM_GEN_EXECUTABLE lcm-gen REQUIRED)
find_program(JAVAC_EXECUTABLE javac)
find_program(JAR_EXECUTABLE jar)
find_file(LCM_JAR lcm.jar PATHS /usr/share/java /usr/local/share/java)

function(sdlqr_lcm_generate target)
  cmake_parse_arguments(ARG "" "PACKAGE" "FILES" ${ARGN})
  set(cpp_dir ${CMAKE_BINARY_DIR}/lcmtypes/cpp)
  set(java_dir ${CMAKE_BINARY_DIR}/lcmtypes/java)
  set(headers)
  set(java_sources)
  foreach(lcm_file ${ARG_FILES})
    get_filename_component(type_name ${lcm_file} NAME_WE)
    get_filename_component(lcm_abs ${lcm_file} ABSOLUTE)
    set(header ${cpp_dir}/${ARG_PACKAGE}/${type_name}.hpp)
    set(java ${java_dir}/${ARG_PACKAGE}/${type_name}.java)
    add_custom_command(
      OUTPUT ${header} ${java}
      COMMAND ${LCM_GEN_EXECUTABLE} --cpp --cpp-std c++11 --cpp-hpath ${cpp_dir}
              --java --jpath ${java_dir} ${lcm_abs}
      DEPENDS ${lcm_abs}
      COMMENT "lcm-gen ${type_name}"
      VERBATIM)
    list(APPEND headers ${header})
    list(APPEND java_sources ${java})
  endforeach()

  add_custom_target(${target}_generate DEPENDS ${headers})
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_generate)
  target_include_directories(${target} SYSTEM INTERFACE ${cpp_dir})

  if(JAVAC_EXECUTABLE AND JAR_EXECUTABLE AND LCM_JAR)
    set(jar_file ${CMAKE_BINARY_DIR}/lcmtypes_${ARG_PACKAGE}.jar)
    set(class_dir ${CMAKE_BINARY_DIR}/lcmtypes/classes)
    add_custom_command(
      OUTPUT ${jar_file}
      COMMAND ${CMAKE_COMMAND} -E rm -rf ${class_dir}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${class_dir}
      COMMAND ${JAVAC_EXECUTABLE} -nowarn -source 8 -target 8 -cp ${LCM_JAR} -d ${class_dir} ${java_sources}
      COMMAND ${JAR_EXECUTABLE} cf ${jar_file} -C ${class_dir} .
      DEPENDS ${java_sources}
      COMMENT "javac + jar lcmtypes_${ARG_PACKAGE}.jar"
      VERBATIM)
    add_custom_target(${target}_jar ALL DEPENDS ${jar_file})
  else()
    message(WARNING "javac, jar or lcm.jar not found: lcmtypes_${ARG_PACKAGE}.jar (for lcm-spy) is not built")
  endif()
endfunction()
