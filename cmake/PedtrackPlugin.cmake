# pedtrack_add_plugin(NAME SOURCES... [LIBS ...])
# Builds one plugin shared library `pedtrack_<NAME>.so` linked to pedtrack::core (the plugin
# contract; LIBS adds what else it uses), places it
# where the host looks (the build tree's plugin dir, or the install prefix's) and installs it.
function(pedtrack_add_plugin NAME)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  set(target pedtrack_${NAME})
  add_library(${target} MODULE ${ARG_SOURCES})
  if(TARGET pedtrack_core)
    target_link_libraries(${target} PRIVATE pedtrack_core ${ARG_LIBS})
  else()
    target_link_libraries(${target} PRIVATE pedtrack::core ${ARG_LIBS})
  endif()
  set_target_properties(${target} PROPERTIES PREFIX "" CXX_VISIBILITY_PRESET hidden
    INSTALL_RPATH "$ORIGIN/../..")
  if(DEFINED PEDTRACK_BUILD_PLUGIN_DIR)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PEDTRACK_BUILD_PLUGIN_DIR})
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION ${PEDTRACK_PLUGIN_SUBDIR})
endfunction()
