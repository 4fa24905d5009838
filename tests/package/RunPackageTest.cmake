# Installs a FIGMENT build to a fresh prefix, then configures, builds and runs examples/
# against it, as a project that extends FIGMENT would: its SphereVolume node drapes a
# square of cloth (drape_over_sphere checks the cloth lies on the ball), and the
# installed figment-view, which knows nothing of SphereVolume, renders the scene with
# the example's library found through LD_LIBRARY_PATH (Coin's dynamic loading); the
# picture's cloth and ball pixels are counted. Last, a plain Coin program reads a
# FIGMENT scene through the installed lib<Class>.so links.
#   cmake -DFIGMENT_BINARY_DIR=... -DEXAMPLES_SOURCE_DIR=... -DWORK_DIR=... -DCOUNT_COLOURS=... -DINSTALL_LIBDIR=lib
#         [-DPLAIN_COIN_READER=... -DPLAIN_COIN_SCENE=...] [-DEXPECT_VIEWER=ON] [-DGENERATOR=...] -P RunPackageTest.cmake
foreach(var FIGMENT_BINARY_DIR EXAMPLES_SOURCE_DIR WORK_DIR COUNT_COLOURS INSTALL_LIBDIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "RunPackageTest.cmake needs -D${var}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}")
  endif()
  string(STRIP "${out}" out)
  string(REGEX REPLACE ".*\n" "" last_line "${out}")
  message(STATUS "${what}: ok ${last_line}")
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
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
run("configure examples/" ${CMAKE_COMMAND} -S ${EXAMPLES_SOURCE_DIR} -B ${build} ${generator_args}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run("build examples/" ${CMAKE_COMMAND} --build ${build})

# The example's application: FIGMENT's kit and SphereVolume linked in.
run("drape_over_sphere" ${build}/drape_over_sphere ${EXAMPLES_SOURCE_DIR}/sphere-drape.iv)

# A second front end on the installed scene session: two sessions with one drape context,
# the second reading the first's drape from the context's cache.
run("session_drape" ${build}/session_drape ${EXAMPLES_SOURCE_DIR}/sphere-drape.iv ${WORK_DIR}/session-cache)

# A plain Coin program (Coin and figment::guard only) reads through the guard: the example's
# scene, with FIGMENT's nodes and SphereVolume loaded by name, and the scene of issue 28, an
# included volumes file declaring a field its CapsuleVolume does not have, refused in one line.
set(guard_path "${build}:${prefix}/${INSTALL_LIBDIR}")
run("guarded_read reads sphere-drape.iv" ${CMAKE_COMMAND} -E env "LD_LIBRARY_PATH=${guard_path}"
    ${build}/guarded_read ${EXAMPLES_SOURCE_DIR}/sphere-drape.iv)
file(WRITE ${WORK_DIR}/volumes.iv "#Inventor V2.1 ascii\nGroup {\n  CapsuleVolume {\n"
     "    fields [ SFString part, SFFloat r1e308 ]\n    part \"head\"\n  }\n  CapsuleVolume { part \"neck\" }\n}\n")
file(WRITE ${WORK_DIR}/bad.iv "#Inventor V2.1 ascii\nSeparator {\n  File { name \"volumes.iv\" }\n}\n")
execute_process(COMMAND ${CMAKE_COMMAND} -E env "LD_LIBRARY_PATH=${guard_path}" ${build}/guarded_read ${WORK_DIR}/bad.iv
  RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT status EQUAL 1 OR NOT err MATCHES "^guarded_read: [^\n]*bad.iv: line 4: CapsuleVolume: fields \\[ SFFloat r1e308 \\] declares a field CapsuleVolume does not have[^\n]*\n$")
  message(FATAL_ERROR "guarded_read on the scene of issue 28: status ${status}, stderr:\n${err}")
endif()
message(STATUS "guarded_read refuses the scene of issue 28: ok ${err}")

# The installed figment-view (a build with the viewer), with only the library path to
# find the new node. The drape cache is left out: it keys a body by its fields, not by
# its code.
set(figment_view ${prefix}/bin/figment-view)
if(EXISTS ${figment_view})
  set(picture ${WORK_DIR}/sphere.png)
  set(library_path "${build}:${prefix}/${INSTALL_LIBDIR}")
  if(DEFINED ENV{LD_LIBRARY_PATH})
    string(APPEND library_path ":$ENV{LD_LIBRARY_PATH}")
  endif()
  run("figment-view renders sphere-drape.iv" ${CMAKE_COMMAND} -E env "LD_LIBRARY_PATH=${library_path}"
      ${figment_view} ${EXAMPLES_SOURCE_DIR}/sphere-drape.iv -o ${picture} --size 240x200 --view 30,25 --no-cache)
  # 240 x 200 pixels: the cloth covers about a tenth of them (5,500) and the ball shows
  # below it (600); a cloth that falls through the ball is framed small, 2 m below it
  # (2,400 red pixels).
  run("the picture's cloth and ball" ${COUNT_COLOURS} ${picture} 3000 200)
elseif(EXPECT_VIEWER)
  message(FATAL_ERROR "${figment_view} is not installed, though this build has the viewer")
else()
  message(STATUS "no figment-view installed (a build without the viewer): no picture")
endif()

# The installed lib<Class>.so links: a plain Coin program (no FIGMENT in it) reads and
# renders a FIGMENT scene with only the installed library directory on its path.
if(PLAIN_COIN_READER AND PLAIN_COIN_SCENE)
  run("a plain Coin program reads ${PLAIN_COIN_SCENE} from the install" ${CMAKE_COMMAND} -E env
      "LD_LIBRARY_PATH=${prefix}/${INSTALL_LIBDIR}" ${PLAIN_COIN_READER} ${PLAIN_COIN_SCENE} 2000)
endif()
