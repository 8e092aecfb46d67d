# Installs this build to a temporary prefix, builds tests/external_plugin against it with
# find_package(pedtrack), runs the plugin through the installed `pedtrack run --plugin-path`, and
# checks that a plugin of another API version is refused naming both versions.
# Inputs: BUILD_DIR, SOURCE_DIR, WORK_DIR, DATASET, API_VERSION.
function(run_checked)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run_checked(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run_checked(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_BUILD_TYPE=Release)
run_checked(${CMAKE_COMMAND} --build ${WORK_DIR}/build)

set(pedtrack ${prefix}/bin/pedtrack)
file(WRITE ${WORK_DIR}/gate.ini "[pipeline]\nstages = source gate\n[source]\nplugin = rawlog\nfile = ${DATASET}\n[gate]\nplugin = range_gate\nmax_range = 4.0\n")
execute_process(COMMAND ${pedtrack} run ${WORK_DIR}/gate.ini --plugin-path ${WORK_DIR}/build --out ${WORK_DIR}/out -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err MATCHES "range_gate: kept [1-9][0-9]* of [0-9]+ points in 225 frames")
  message(FATAL_ERROR "external plugin run failed (${rc}):\n${out}\n${err}")
endif()
file(READ ${WORK_DIR}/out/run.json json)
if(NOT json MATCHES "\"name\": \"gate\", \"plugin\": \"range_gate\", \"calls\": 225")
  message(FATAL_ERROR "run.json lacks the external stage:\n${json}")
endif()

execute_process(COMMAND ${pedtrack} plugins --plugin-path ${WORK_DIR}/build
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT out MATCHES "range_gate +segmenter" OR NOT out MATCHES "other_api +- +REFUSED")
  message(FATAL_ERROR "plugin listing misses the external plugins:\n${out}\n${err}")
endif()

file(WRITE ${WORK_DIR}/other.ini "[pipeline]\nstages = source other\n[source]\nplugin = rawlog\nfile = ${DATASET}\n[other]\nplugin = other_api\n")
execute_process(COMMAND ${pedtrack} run ${WORK_DIR}/other.ini --plugin-path ${WORK_DIR}/build --out ${WORK_DIR}/out2
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "API version 0, but this pedtrack has API version ${API_VERSION}" OR EXISTS ${WORK_DIR}/out2)
  message(FATAL_ERROR "a plugin of another API version was not refused properly (${rc}):\n${err}")
endif()
message(STATUS "external plugin: ${err}")

# The plugin contract is pedtrack_core alone: the example links no other pedtrack library.
execute_process(COMMAND readelf -d ${WORK_DIR}/build/pedtrack_range_gate.so
  RESULT_VARIABLE rc OUTPUT_VARIABLE dyn ERROR_VARIABLE err)
string(REGEX MATCHALL "libpedtrack_[a-z_]+" needed "${dyn}")
if(NOT rc EQUAL 0 OR NOT needed STREQUAL "libpedtrack_core")
  message(FATAL_ERROR "the external plugin links ${needed}, not libpedtrack_core alone:\n${dyn}${err}")
endif()
