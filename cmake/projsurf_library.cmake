# projsurf_library(<folder>): the library of one folder under src/projsurf/, named
# projsurf_<folder>, with the ALIAS projsurf::<folder> (the name an installed package gives it,
# so a project builds the same way against a subdirectory or an installed tree).
function(projsurf_library folder)
  set(name projsurf_${folder})
  if(PROJSURF_SHARED_LIBS)
    add_library(${name} SHARED ${ARGN})
  else()
    add_library(${name} STATIC ${ARGN})
  endif()
  add_library(projsurf::${folder} ALIAS ${name})
  set_target_properties(${name} PROPERTIES
    EXPORT_NAME ${folder}
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
    POSITION_INDEPENDENT_CODE ON)  # static ones too: the Python module links them
  # Headers are included as "projsurf/<folder>/x.hpp".
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # In a shared library GCC lets every exported function be replaced at load time, and so
  # neither inlines nor calls directly one exported function from another; projsurf's
  # functions are not meant to be interposed, so calls stay as in a static build.
  if(PROJSURF_SHARED_LIBS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${name} PRIVATE -fno-semantic-interposition)
  endif()
  # Each library links everything it uses and nothing else: an undefined symbol (core calling
  # into sim, say) fails this library's link instead of a consumer's.
  if(PROJSURF_SHARED_LIBS AND CMAKE_SYSTEM_NAME STREQUAL "Linux")
    target_link_options(${name} PRIVATE -Wl,--no-undefined)
  endif()
endfunction()

# projsurf_folder(<folder> <target_link_libraries arguments>): the library of
# src/projsurf/<folder>/*.cpp, projsurf_<folder with _ for />, linking what its files include
# (scripts/folder_graph.py, ctest -R folder_graph, reads these calls in every CMakeLists.txt
# under src/projsurf and checks them). Appends the target to PROJSURF_FOLDER_TARGETS.
macro(projsurf_folder folder)
  string(REPLACE "/" "_" _projsurf_name ${folder})
  file(GLOB _projsurf_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/projsurf/${folder}/*.cpp)
  projsurf_library(${_projsurf_name} ${_projsurf_sources})
  target_link_libraries(projsurf_${_projsurf_name} ${ARGN})
  list(APPEND PROJSURF_FOLDER_TARGETS projsurf_${_projsurf_name})
  set_property(GLOBAL APPEND PROPERTY PROJSURF_FOLDERS ${folder})
endmacro()

# projsurf_aggregate(<name> <folder targets>...): projsurf::<name>, an interface library that
# links a family of folder libraries (projsurf::io links io/files, io/yaml, ...).
function(projsurf_aggregate name)
  add_library(projsurf_${name} INTERFACE)
  add_library(projsurf::${name} ALIAS projsurf_${name})
  set_target_properties(projsurf_${name} PROPERTIES EXPORT_NAME ${name})
  target_link_libraries(projsurf_${name} INTERFACE ${ARGN})
endfunction()

# projsurf_install_public_headers(): each folder's public header (src/projsurf/<folder>.hpp, beside
# the folder, as OpenCV's core.hpp is beside core/) and the headers it includes, transitively;
# nothing else (docs/library.md). A consumer includes the public headers only, so that files
# inside a folder can move without breaking it. Configure runs again when one of them changes.
function(projsurf_install_public_headers)
  if(NOT PROJSURF_INSTALL)
    return()
  endif()
  set(root ${PROJECT_SOURCE_DIR}/src/projsurf)
  get_property(folders GLOBAL PROPERTY PROJSURF_FOLDERS)
  set(todo "")
  foreach(folder ${folders})
    if(EXISTS ${root}/${folder}.hpp)
      list(APPEND todo ${folder}.hpp)
    endif()
  endforeach()
  set(done "")
  while(todo)
    list(POP_FRONT todo header)
    if(header IN_LIST done)
      continue()
    endif()
    list(APPEND done ${header})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${root}/${header})
    file(STRINGS ${root}/${header} lines REGEX "^#include \"projsurf/[^\"]+\"")
    foreach(line ${lines})
      string(REGEX REPLACE "^#include \"projsurf/([^\"]+)\".*" "\\1" included "${line}")
      list(APPEND todo ${included})
    endforeach()
  endwhile()
  foreach(header ${done})
    get_filename_component(dir ${header} DIRECTORY)
    install(FILES ${root}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/projsurf/${dir} COMPONENT devel)
  endforeach()
endfunction()
