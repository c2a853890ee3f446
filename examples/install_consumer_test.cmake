# cmake -P: the install test (see examples/CMakeLists.txt). Fails with a message naming the step.
set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(launcher "")
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()

function(step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: ${name} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

step("cmake --install" ${CMAKE_COMMAND} --install ${PROJSURF_BUILD_DIR} --prefix ${prefix})
foreach(f bin/projsurf include/projsurf/detector/detector.hpp include/projsurf/io/yaml/yaml_files.hpp
          lib/cmake/projsurf/projsurf-config.cmake lib/pkgconfig/projsurf.pc lib/pkgconfig/projsurf-core.pc)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install test: ${prefix}/${f} was not installed")
  endif()
endforeach()
# Each folder's public header is installed with what it includes; internals are not (the
# function-multiversioning macro, the paper method's hull and outline raster, the wall relief,
# the PCD reader, the simulator's noise tables): docs/library.md.
foreach(f include/projsurf/types.hpp include/projsurf/detection.hpp include/projsurf/detector.hpp
          include/projsurf/io/formats.hpp include/projsurf/frontend/answer.hpp include/projsurf/sim/scenes.hpp)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install test: the public header ${prefix}/${f} was not installed")
  endif()
endforeach()
foreach(f types/target_clones.hpp detection/paper/hull.hpp detection/paper/outline_raster.hpp
          detection/default/wall_relief.hpp io/formats/pcd_file.hpp sim/gaussian_table.hpp)
  if(EXISTS ${prefix}/include/projsurf/${f})
    message(FATAL_ERROR "install test: the internal header include/projsurf/${f} was installed")
  endif()
endforeach()
# The installed CLI runs from the prefix (it finds its libraries by its RPATH).
step("installed projsurf --help" ${prefix}/bin/projsurf --help)

# 1. examples/cpp with find_package(projsurf COMPONENTS io).
set(calib ${PROJSURF_SOURCE_DIR}/examples/calib/example_calib.yaml)
step("configure examples/cpp" ${CMAKE_COMMAND} -S ${PROJSURF_SOURCE_DIR}/examples/cpp -B ${WORK_DIR}/cpp
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} ${launcher}
  -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON)
step("build examples/cpp" ${CMAKE_COMMAND} --build ${WORK_DIR}/cpp)
step("run examples/cpp" ${WORK_DIR}/cpp/projsurf_example ${calib} ${WORK_DIR}/framebuffer.png)
message(STATUS "examples/cpp: ${step_output}")
if(NOT step_output MATCHES "rectangle [0-9.]+ x [0-9.]+ m" OR NOT step_output MATCHES "framebuffer 1280x800, [1-9]")
  message(FATAL_ERROR "install test: examples/cpp found no rectangle or lit no pixel:\n${step_output}")
endif()
if(NOT EXISTS ${WORK_DIR}/framebuffer.png)
  message(FATAL_ERROR "install test: examples/cpp wrote no framebuffer")
endif()
# Bad input: the library's InputError reaches the program as one line naming the file.
execute_process(COMMAND ${WORK_DIR}/cpp/projsurf_example ${WORK_DIR}/missing.yaml ${WORK_DIR}/x.png
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "^projsurf_example: error: [^\n]*missing.yaml: [^\n]+\n$")
  message(FATAL_ERROR "install test: a missing calibration gave exit ${rc} and '${err}'")
endif()

# 2. The same main.cpp through pkg-config.
find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
  step("pkg-config projsurf" ${PKG_CONFIG} --cflags --libs projsurf)
  string(STRIP "${step_output}" flags)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  step("c++ with pkg-config" c++ -std=c++17 -O1 ${PROJSURF_SOURCE_DIR}/examples/cpp/main.cpp ${flags}
    -Wl,-rpath,${prefix}/lib -o ${WORK_DIR}/example_pc)
  step("run the pkg-config build" ${WORK_DIR}/example_pc ${calib} ${WORK_DIR}/framebuffer_pc.png)
else()
  message(STATUS "install test: no pkg-config, its part is skipped")
endif()

# 3. A core-only program: configured without PCL, CLI11, nlohmann-json, yaml-cpp; linked
#    without PCL.
step("configure core_consumer" ${CMAKE_COMMAND} -S ${PROJSURF_SOURCE_DIR}/tests/core_consumer -B ${WORK_DIR}/core
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} ${launcher}
  -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON)
step("build core_consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/core)
step("run core_consumer" ${WORK_DIR}/core/core_consumer)
step("ldd core_consumer" ldd ${WORK_DIR}/core/core_consumer)
if(step_output MATCHES "libpcl|yaml-cpp|libprojsurf_io|libprojsurf_sim|libprojsurf_eval")
  message(FATAL_ERROR "install test: the core-only program loads more than the core:\n${step_output}")
endif()
# 4. The installed Python module imports from the prefix and reads the example calibration.
if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/lib/python3/dist-packages)
  step("import the installed Python module" ${PYTHON} -c
    "import projsurf, sys\np = projsurf.read_calibration(sys.argv[1])\nprint(projsurf.__file__, p.width, p.height)"
    ${calib})
  if(NOT step_output MATCHES "^${prefix}/lib/python3/dist-packages/projsurf[^ ]*\\.so 1280 800")
    message(FATAL_ERROR "install test: the installed module did not come from the prefix: ${step_output}")
  endif()
endif()
message(STATUS "install test: all steps passed")
