cmake_minimum_required(VERSION 3.16)
# The libraries each in-tree plugin needs (readelf -d): pedtrack_core always; never the simulator
# or the evaluator, which only the host and the tests link (the `sim` source is the simulator's
# own plugin). Inputs: PLUGIN_DIR.
file(GLOB plugins ${PLUGIN_DIR}/pedtrack_*.so)
list(LENGTH plugins n)
if(n LESS 15)
  message(FATAL_ERROR "only ${n} plugins in ${PLUGIN_DIR}")
endif()
foreach(plugin ${plugins})
  get_filename_component(name ${plugin} NAME)
  execute_process(COMMAND readelf -d ${plugin} RESULT_VARIABLE rc OUTPUT_VARIABLE dyn)
  string(REGEX MATCHALL "libpedtrack_[a-z_]+" needed "${dyn}")
  message(STATUS "${name}: ${needed}")
  if(NOT rc EQUAL 0 OR NOT "libpedtrack_core" IN_LIST needed)
    message(FATAL_ERROR "${name} does not link libpedtrack_core (${needed})")
  endif()
  if(NOT name STREQUAL "pedtrack_sim.so" AND
     ("libpedtrack_simulator" IN_LIST needed OR "libpedtrack_eval" IN_LIST needed))
    message(FATAL_ERROR "${name} links the simulator or the evaluator: ${needed}")
  endif()
endforeach()
