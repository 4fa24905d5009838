# Installs a FIGMENT build to a fresh prefix, then configures, builds and runs
# tests/package against it, as a project that uses FIGMENT would.
#   cmake -DFIGMENT_BINARY_DIR=... -DPACKAGE_SOURCE_DIR=... -DWORK_DIR=... [-DGENERATOR=...] -P RunPackageTest.cmake
foreach(var FIGMENT_BINARY_DIR PACKAGE_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "RunPackageTest.cmake needs -D${var}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run("install" ${CMAKE_COMMAND} --install ${FIGMENT_BINARY_DIR} --prefix ${prefix})

# The node kit's installed headers must stand alone: no sim/ or io/ types in them.
file(GLOB_RECURSE node_headers ${prefix}/include/figment/nodes/*.h)
if(NOT node_headers)
  message(FATAL_ERROR "no headers installed under ${prefix}/include/figment/nodes")
endif()
foreach(header IN LISTS node_headers)
  file(STRINGS ${header} includes REGEX "#include [<\"](sim|io)/")
  if(includes)
    message(FATAL_ERROR "${header} includes ${includes}")
  endif()
endforeach()

set(generator_args)
if(GENERATOR)
  set(generator_args -G ${GENERATOR})
endif()
run("configure" ${CMAKE_COMMAND} -S ${PACKAGE_SOURCE_DIR} -B ${WORK_DIR}/build ${generator_args}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run("build" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run("run" ${WORK_DIR}/build/figment_package_test)
